#include "render/pose_panel.hpp"

#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "core/affine3.hpp"
#include "motion/no_motion.hpp"
#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"
#include "motion/stage.hpp"

namespace pita::render {

namespace {

// The panel's poses of this dimension (a panel of another kind is not drawn here).
template <class Pose>
const scene::PoseKeys<Pose>& pose_keys_of(const scene::Scene& scene, const scene::Panel& panel) {
  if (const auto* keys = std::get_if<scene::PoseKeys<Pose>>(&panel.keys)) return *keys;
  throw RenderError(scene.path, panel.pointer, "these layers draw poses; this panel has none of this kind");
}

// In space, the camera looks at its target: given, else the centre of the
// solids' vertices at the poses.
Projection camera_view(const scene::Scene& scene, const scene::SpacePoseKeys& keys) {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  if (scene.camera.target) {
    target = *scene.camera.target;
  } else {
    double count = 0.0;
    for (const TimedPose3& pose : keys.poses) {
      for (const scene::Solid& solid : scene.solids) {
        for (const Eigen::Vector3d& v : solid.vertices) {
          target += apply(pose.pose, v);
          count += 1.0;
        }
      }
    }
    if (count > 0.0) target /= count;
  }
  try {
    return Projection(scene.camera, target);
  } catch (const std::invalid_argument& error) {
    throw RenderError(scene.path, "/camera", error.what());
  }
}

template <class Pose>
PoseView<Pose> make_view(const scene::Scene& scene, const scene::PoseKeys<Pose>& keys) {
  if constexpr (std::is_same_v<Pose, Affine2>) {
    (void)scene;
    (void)keys;
    return {};
  } else {
    return camera_view(scene, keys);
  }
}

}  // namespace

template <class Pose>
PosePanel<Pose>::PosePanel(const motion::Stage& stage, std::size_t index, const FrameSelection* selection)
    : stage_(stage),
      index_(index),
      scene_(stage.scene()),
      panel_(stage.panel(index)),
      selection_(selection),
      keys_(pose_keys_of<Pose>(stage.scene(), stage.panel(index))),
      view_(make_view<Pose>(scene_, keys_)) {}

template <class Pose>
void PosePanel<Pose>::fail(const std::string& reason) const {
  // A layer of the scene drawn in one of its panels names that panel too.
  const bool elsewhere = !panel_.pointer.empty() && !layer_.starts_with(panel_.pointer);
  throw RenderError(scene_.path, layer_, elsewhere ? reason + " (in the panel at " + panel_.pointer + ")" : reason);
}

template <class Pose>
void PosePanel<Pose>::fail_at(const std::string& pointer, const std::string& reason) const {
  throw RenderError(scene_.path, pointer, reason);
}

template <class Pose>
const motion::SceneMotion& PosePanel<Pose>::motion() const {
  if (keys_.poses.empty()) fail("this layer draws a motion, and the panel has no poses");
  try {
    return stage_.motion(index_);
  } catch (const motion::NoMotion& error) {  // at the poses (or panel) it blames
    throw RenderError(error.file(), error.pointer(), error.reason());
  }
}

template <class Pose>
Pose PosePanel<Pose>::pose_at(double t) const {
  try {
    if constexpr (std::is_same_v<Pose, Affine2>) {
      return motion().pose_at(t);
    } else {
      return motion().pose3_at(t);
    }
  } catch (const motion::NoMotion& error) {
    fail(error.reason());
  }
}

template <class Pose>
Pose PosePanel<Pose>::velocity_at(double t) const {
  const double duration = motion().last() - motion().first();
  Pose rate;
  try {
    if constexpr (std::is_same_v<Pose, Affine2>) {
      rate = motion().pose_velocity(t);
    } else {
      rate = motion().pose3_velocity(t);
    }
  } catch (const motion::NoMotion& error) {
    fail(error.reason());
  }
  rate.L *= duration;
  rate.b *= duration;
  return rate;
}

template <class Pose>
std::vector<double> PosePanel<Pose>::times(const std::optional<int>& samples,
                                           const std::optional<scene::TimeRange>& range) const {
  const double from = range ? range->from : motion().first();
  const double to = range ? range->to : motion().last();
  return motion::uniform_times(from, to, samples.value_or(panel_.samples));
}

template <class Pose>
std::vector<BodyPoint<Pose>> PosePanel<Pose>::body_points() const {
  std::vector<BodyPoint<Pose>> points;
  if constexpr (std::is_same_v<Pose, Affine2>) {
    for (const scene::ShapeOutline& shape : panel_.shapes) points.insert(points.end(), shape.points.begin(), shape.points.end());
  } else {
    for (const scene::Solid& solid : scene_.solids) points.insert(points.end(), solid.vertices.begin(), solid.vertices.end());
  }
  return points;
}

template <class Pose>
Point PosePanel<Pose>::image(const BodyPoint<Pose>& x) const {
  if constexpr (std::is_same_v<Pose, Affine2>) {
    return x;
  } else {
    const std::optional<Point> p = view_.project(x);
    if (!p) {
      fail_at("/camera/distance",
              fmt::format("a point of the figure ({:g}, {:g}, {:g}) is behind the perspective camera: move the "
                          "camera farther (\"distance\") or use \"projection\": \"orthographic\"",
                          x.x(), x.y(), x.z()));
    }
    return *p;
  }
}

template <class Pose>
void PosePanel<Pose>::push(int index, Shape shape, bool moving) {
  drawing_.items.push_back({layer_, index, std::move(shape)});
  drawing_.items.back().moving = moving;
}

template <class Pose>
void PosePanel<Pose>::append(std::vector<Item> items) {
  for (Item& item : items) drawing_.items.push_back(std::move(item));
}

template class PosePanel<Affine2>;
template class PosePanel<Affine3>;

}  // namespace pita::render
