#include "render/pose_panel.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "core/affine3.hpp"
#include "motion/no_motion.hpp"
#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"
#include "motion/stage.hpp"
#include "render/camera_choice.hpp"
#include "render/static_layers.hpp"
#include "scene/body_points.hpp"

namespace pita::render {

namespace {

// The panel's poses of this dimension (a panel of another kind is not drawn here).
template <class Pose>
const scene::PoseKeys<Pose>& pose_keys_of(const scene::Scene& scene, const scene::Panel& panel) {
  if (const auto* keys = std::get_if<scene::PoseKeys<Pose>>(&panel.keys)) return *keys;
  throw RenderError(scene.path, panel.pointer, "these layers draw poses; this panel has none of this kind");
}

// The poses "camera": {"auto": true} keeps open: the panel's, and its
// motion's frames at the panel's samples when it has a motion.
std::vector<Affine3> seen_poses(const motion::Stage& stage, std::size_t index, const scene::SpacePoseKeys& keys) {
  std::vector<Affine3> poses;
  for (const TimedPoseOf<Affine3>& pose : keys.poses) poses.push_back(pose.pose);
  if (keys.poses.empty()) return poses;
  try {
    const motion::SceneMotion& motion = stage.motion(index);
    for (const double t : motion::uniform_times(motion.first(), motion.last(), stage.panel(index).samples)) {
      poses.push_back(motion.pose_at<Affine3>(t));
    }
  } catch (const motion::NoMotion&) {
    // The poses alone: the layers that draw the motion report its error.
  }
  return poses;
}

// The least z of the solids' vertices at the poses (0 without any).
double lowest_point(const std::vector<scene::Solid>& solids, const std::vector<Affine3>& poses) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const Affine3& pose : poses) {
    for (const scene::Solid& solid : solids) {
      for (const Eigen::Vector3d& v : solid.vertices) lowest = std::min(lowest, apply(pose, v).z());
    }
  }
  return std::isfinite(lowest) ? lowest : 0.0;
}

// In space, the camera looks at its target: given, else the centre of the
// solids' vertices at the poses; "auto" turns it (render/camera_choice.hpp).
Projection camera_view(const scene::Scene& scene, const scene::SpacePoseKeys& keys, const std::vector<Affine3>& seen) {
  const scene::PoseFigure<Affine3>& figure = scene::figure_of(scene, keys);
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  if (figure.camera.target) {
    target = *figure.camera.target;
  } else {
    double count = 0.0;
    for (const TimedPoseOf<Affine3>& pose : keys.poses) {
      for (const scene::Solid& solid : figure.shapes) {
        for (const Eigen::Vector3d& v : solid.vertices) {
          target += apply(pose.pose, v);
          count += 1.0;
        }
      }
    }
    if (count > 0.0) target /= count;
  }
  const scene::Camera camera =
      figure.camera.automatic ? chosen_camera(figure.camera, figure.shapes, seen) : figure.camera;
  try {
    return Projection(camera, target);
  } catch (const std::invalid_argument& error) {
    throw RenderError(scene.path, "/camera", error.what());
  }
}

// The view, and in space with a shadow the ground's height.
template <class Pose>
PoseView<Pose> make_view(const motion::Stage& stage, std::size_t index, const scene::PoseKeys<Pose>& keys,
                         double& ground) {
  if constexpr (!in_space_v<Pose>) {
    (void)stage;
    (void)index;
    (void)keys;
    (void)ground;
    return {};
  } else {
    // The poses "auto" and "shadow" look at, found once.
    const scene::PoseFigure<Affine3>& figure = scene::figure_of(stage.scene(), keys);
    const bool looks = figure.camera.automatic || figure.camera.shadow;
    const std::vector<Affine3> seen = looks ? seen_poses(stage, index, keys) : std::vector<Affine3>{};
    if (figure.camera.shadow) ground = lowest_point(figure.shapes, seen);
    return camera_view(stage.scene(), keys, seen);
  }
}

}  // namespace

scene::Camera drawn_camera(const motion::Stage& stage, std::size_t index) {
  const scene::SpacePoseKeys& keys = pose_keys_of<Affine3>(stage.scene(), stage.panel(index));
  const scene::PoseFigure<Affine3>& figure = scene::figure_of(stage.scene(), keys);
  if (!figure.camera.automatic) return figure.camera;
  return chosen_camera(figure.camera, figure.shapes, seen_poses(stage, index, keys));
}

namespace {

// make_view, once per panel of an animation's frames when given a cache.
template <class Pose>
PoseView<Pose> kept_view(const motion::Stage& stage, std::size_t index, const scene::PoseKeys<Pose>& keys,
                         double& ground, StaticLayers* cache) {
  if constexpr (in_space_v<Pose>) {
    if (cache != nullptr) {
      if (const SpaceView* kept = cache->view(index)) {
        ground = kept->ground;
        return kept->projection;
      }
      const Projection view = make_view<Pose>(stage, index, keys, ground);
      cache->record_view(index, SpaceView{view, ground});
      return view;
    }
  } else {
    (void)cache;
  }
  return make_view<Pose>(stage, index, keys, ground);
}

}  // namespace

template <class Pose>
PosePanel<Pose>::PosePanel(const motion::Stage& stage, std::size_t index, const FrameSelection* selection,
                           StaticLayers* cache)
    : stage_(stage),
      index_(index),
      scene_(stage.scene()),
      panel_(stage.panel(index)),
      selection_(selection),
      keys_(pose_keys_of<Pose>(stage.scene(), stage.panel(index))),
      view_(kept_view<Pose>(stage, index, keys_, ground_, selection != nullptr ? cache : nullptr)) {}

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
    return motion().template pose_at<Pose>(t);
  } catch (const motion::NoMotion& error) {
    fail(error.reason());
  }
}

template <class Pose>
Pose PosePanel<Pose>::velocity_at(double t) const {
  const double duration = motion().last() - motion().first();
  Pose rate;
  try {
    rate = motion().template pose_velocity<Pose>(t);
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
  return scene::body_points<Pose>(scene_, panel_);
}

template <class Pose>
Point PosePanel<Pose>::image(const BodyPoint<Pose>& x) const {
  if constexpr (!in_space_v<Pose>) {
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

template <class Pose>
void PosePanel<Pose>::cast_shadow(int index, std::vector<std::vector<Eigen::Vector3d>> faces, double opacity,
                                  bool moving) {
  shadows_.push_back({index, std::move(faces), opacity, moving});
}

template <class Pose>
Drawing PosePanel<Pose>::take() {
  if constexpr (in_space_v<Pose>) {
    if (!shadows_.empty() && figure().camera.shadow) {
      double ground = ground_;
      for (const Shadow& shadow : shadows_) {
        for (const auto& face : shadow.faces) {
          for (const Eigen::Vector3d& x : face) ground = std::min(ground, x.z());
        }
      }
      std::vector<Item> under;
      for (const Shadow& shadow : shadows_) {
        // The union of the faces' shadows: each contour turned counter-clockwise,
        // so that the winding rule fills every point any face covers once.
        std::vector<std::vector<Point>> contours;
        for (const auto& face : shadow.faces) {
          std::vector<Point> contour;
          for (const Eigen::Vector3d& x : face) contour.push_back(image(Eigen::Vector3d(x.x(), x.y(), ground)));
          if (contour.size() >= 3 && turn_counter_clockwise(contour) != 0.0) contours.push_back(std::move(contour));
        }
        if (contours.empty()) continue;
        Item& item = under.emplace_back();
        item.layer = "/camera/shadow";
        item.index = shadow.index;
        item.shape = FilledPath{std::move(contours), *figure().camera.shadow, shadow.opacity, std::nullopt};
        item.moving = shadow.moving;
      }
      drawing_.items.insert(drawing_.items.begin(), std::make_move_iterator(under.begin()),
                            std::make_move_iterator(under.end()));
      shadows_.clear();
    }
  }
  return std::move(drawing_);
}

template class PosePanel<Affine2>;
template class PosePanel<Affine3>;

}  // namespace pita::render
