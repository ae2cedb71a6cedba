#include "render/space_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <fmt/format.h>

#include "core/sam_splines.hpp"
#include "motion/no_motion.hpp"
#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"
#include "motion/stage.hpp"

namespace pita::render {

namespace {

using Eigen::Vector3d;

constexpr double kDegree = std::numbers::pi / 180.0;
const Color kDefaultFaceColor{0.55, 0.65, 0.85, 1.0};

// Newell's normal of a polygon of space (any winding, not necessarily planar), unit or zero.
Vector3d newell_normal(const std::vector<Vector3d>& points) {
  Vector3d n = Vector3d::Zero();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vector3d& a = points[i];
    const Vector3d& b = points[(i + 1) % points.size()];
    n += Vector3d((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
                  (a.x() - b.x()) * (a.y() + b.y()));
  }
  const double length = n.norm();
  return length > 0.0 ? Vector3d(n / length) : Vector3d::Zero();
}

Color shaded(Color c, double shade) { return Color{c.r * shade, c.g * shade, c.b * shade, c.a}; }

// A face to paint, how far its solid is (the mean depth of the solid's
// vertices) and how far the face itself is.
struct Face {
  double solid_depth;
  double depth;
  int index;
  Shape shape;
};

class SpaceBuilder {
 public:
  SpaceBuilder(const motion::Stage& stage, std::size_t index, const FrameSelection* selection)
      : stage_(stage), index_(index), scene_(stage.scene()), panel_(stage.panel(index)), selection_(selection),
        keys_(keys_of(stage.scene(), stage.panel(index))) {}

  Drawing build() {
    projection_.emplace(make_projection());
    // The panel's own layers, else the scene's.
    const bool own = panel_.pose_layers.has_value();
    const std::vector<scene::PoseLayer>& layers = own ? *panel_.pose_layers : scene_.pose_layers;
    for (std::size_t i = 0; i < layers.size(); ++i) {
      layer_ = (own ? panel_.pointer : std::string()) + "/layers/" + std::to_string(i);
      std::visit([this](const auto& layer) { add(layer); }, layers[i]);
    }
    return std::move(drawing_);
  }

 private:
  // The panel's poses (a panel of another kind is not drawn here).
  static const scene::SpacePoseKeys& keys_of(const scene::Scene& scene, const scene::Panel& panel) {
    if (const auto* keys = std::get_if<scene::SpacePoseKeys>(&panel.keys)) return *keys;
    throw RenderError(scene.path, panel.pointer, "these layers draw poses; this panel has none of this kind");
  }

  [[noreturn]] void fail(const std::string& pointer, const std::string& reason) const {
    throw RenderError(scene_.path, pointer, reason);
  }

  // The panel's motion, from the stage, when a layer needs it.
  const motion::SceneMotion& motion() const {
    try {
      return stage_.motion(index_);
    } catch (const motion::NoMotion& error) {
      throw RenderError(error.file(), error.pointer(), error.reason());
    }
  }

  Affine3 pose_at(double t) {
    try {
      return motion().pose3_at(t);
    } catch (const motion::NoMotion& error) {
      fail(layer_, error.reason());
    }
  }

  std::vector<double> times(const std::optional<int>& samples, const std::optional<scene::TimeRange>& range) {
    const double from = range ? range->from : motion().first();
    const double to = range ? range->to : motion().last();
    return motion::uniform_times(from, to, samples.value_or(panel_.samples));
  }

  // The camera's target: given, else the centre of the solids' vertices at the poses.
  Projection make_projection() {
    Vector3d target = Vector3d::Zero();
    if (scene_.camera.target) {
      target = *scene_.camera.target;
    } else {
      double count = 0.0;
      for (const TimedPose3& pose : keys_.poses) {
        for (const scene::Solid& solid : scene_.solids) {
          for (const Vector3d& v : solid.vertices) {
            target += apply(pose.pose, v);
            count += 1.0;
          }
        }
      }
      if (count > 0.0) target /= count;
    }
    try {
      return Projection(scene_.camera, target);
    } catch (const std::invalid_argument& error) {
      fail("/camera", error.what());
    }
  }

  Point projected(const Vector3d& x) {
    const std::optional<Point> p = projection_->project(x);
    if (!p) {
      fail("/camera/distance",
           fmt::format("a point of the figure ({:g}, {:g}, {:g}) is behind the perspective camera: move the "
                       "camera farther (\"distance\") or use \"projection\": \"orthographic\"",
                       x.x(), x.y(), x.z()));
    }
    return *p;
  }

  // The faces of `solid` under `pose`: filled and shaded (fill given) or as
  // closed outlines (a wireframe), each with its depth.
  void solid_faces(const scene::Solid& solid, const Affine3& pose, const std::optional<Color>& fill,
                   const LineStyle& line, double opacity, int index, std::vector<Face>& out) {
    const bool mirrored = pose.L.determinant() < 0.0;
    double solid_depth = 0.0;
    for (const Vector3d& v : solid.vertices) solid_depth += projection_->depth(apply(pose, v));
    solid_depth /= static_cast<double>(solid.vertices.size());
    for (const std::vector<int>& face : solid.faces) {
      std::vector<Vector3d> points;
      std::vector<Point> image;
      double depth = 0.0;
      for (const int k : face) {
        const Vector3d x = apply(pose, solid.vertices[static_cast<std::size_t>(k)]);
        points.push_back(x);
        image.push_back(projected(x));
        depth += projection_->depth(x);
      }
      depth /= static_cast<double>(face.size());
      LineStyle edge = line;
      edge.opacity *= opacity;
      if (fill) {
        Vector3d normal = newell_normal(points);
        if (mirrored) normal = -normal;
        const Color color = shaded(*fill, face_shade(normal, *projection_));
        out.push_back({solid_depth, depth, index, FilledPath{{std::move(image)}, color, opacity, edge}});
      } else {
        out.push_back({solid_depth, depth, index, Polyline{std::move(image), true, edge}});
      }
    }
  }

  // Back to front: solid by solid (by the mean depth of their vertices: no
  // face of a nearer solid under a farther one unless the solids overlap),
  // and within a solid face by face.
  void paint(std::vector<Face> faces, bool moving) {
    std::stable_sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) {
      return a.solid_depth != b.solid_depth ? a.solid_depth > b.solid_depth : a.depth > b.depth;
    });
    for (Face& face : faces) {
      drawing_.items.push_back({layer_, face.index, std::move(face.shape)});
      drawing_.items.back().moving = moving;
    }
  }

  void add(const scene::ShapesLayer& layer) {
    const std::vector<double> ts =
        selected_times(selection_, selection_ != nullptr ? std::vector<double>{} : times(layer.samples, layer.range));
    // "lightness": "area": in space, by volume (|det L|), as in 2D by area.
    std::vector<double> volumes;
    if (layer.lightness_by_area) {
      for (const double t : ts) volumes.push_back(std::abs(pose_at(t).L.determinant()));
    }
    const std::vector<double> whites = lightness_whites(volumes);
    std::vector<Face> faces;
    for (std::size_t i = 0; i < ts.size(); ++i) {
      const Affine3 pose = pose_at(ts[i]);
      const double fade = selection_ != nullptr ? trail_fade(i, ts.size()) : 1.0;
      const double white = whites.empty() ? 0.0 : whites[i];
      for (const scene::Solid& solid : scene_.solids) {
        LineStyle line = layer.line;
        if (solid.color && !layer.fill) line.color = *solid.color;
        line.color = lightened(line.color, white);
        std::optional<Color> fill;
        if (layer.fill) fill = lightened(solid.color.value_or(*layer.fill), white);
        solid_faces(solid, pose, fill, line, fade, static_cast<int>(i), faces);
      }
    }
    paint(std::move(faces), selection_ != nullptr);
  }

  void add(const scene::PosesLayer& layer) {
    std::vector<Face> faces;
    for (std::size_t i = 0; i < keys_.poses.size(); ++i) {
      const Color color = layer.colors[i % layer.colors.size()];
      const LineStyle line{color, layer.width, 1.0, {}};
      for (const scene::Solid& solid : scene_.solids) {
        solid_faces(solid, keys_.poses[i].pose, lightened(color, 0.55), line, 1.0, static_cast<int>(i), faces);
      }
    }
    paint(std::move(faces), false);
  }

  void add(const scene::PathsLayer& layer) {
    const std::vector<double> ts = times(layer.samples, layer.range);
    std::vector<Affine3> poses;
    for (const double t : ts) poses.push_back(pose_at(t));
    for (const scene::Solid& solid : scene_.solids) {
      for (const Vector3d& v : solid.vertices) {
        std::vector<Point> path;
        for (const Affine3& pose : poses) path.push_back(projected(apply(pose, v)));
        drawing_.items.push_back({layer_, -1, Polyline{std::move(path), false, layer.line}});
      }
    }
  }

  void add(const scene::VelocitiesLayer& layer) {
    for (const double t : times(layer.samples, layer.range)) {
      const Affine3 pose = pose_at(t);
      Affine3 rate;
      try {
        rate = motion().pose3_velocity(t);
      } catch (const motion::NoMotion& error) {
        fail(layer_, error.reason());
      }
      for (const scene::Solid& solid : scene_.solids) {
        for (const Vector3d& v : solid.vertices) {
          const Vector3d from = apply(pose, v);
          const Vector3d to = from + layer.scale * apply(rate, v);
          drawing_.items.push_back({layer_, -1, ArrowShape{projected(from), projected(to), layer.line}});
        }
      }
    }
  }

  // SAM paper Fig. 11 in space: the solids at sam_patch(A, B, C, D, u, v).
  void add(const scene::PatchLayer& layer) {
    const std::vector<TimedPose3>& poses = keys_.poses;
    const std::size_t needed = layer.regular ? 3 : 4;
    if (poses.size() < needed) {
      fail(layer_, fmt::format("a patch takes the scene's first {} poses as corners; the scene has {}", needed,
                               poses.size()));
    }
    const Affine3 &A = poses[0].pose, &B = poses[1].pose, &C = poses[2].pose;
    std::vector<Face> faces;
    try {
      const Affine3 D = layer.regular ? regular_patch_corner(A, B, C) : poses[3].pose;
      int index = 0;
      for (int j = 0; j < layer.rows; ++j) {
        const double v = static_cast<double>(j) / (layer.rows - 1);
        for (int i = 0; i < layer.columns; ++i, ++index) {
          const double u = static_cast<double>(i) / (layer.columns - 1);
          const Affine3 pose = sam_patch(A, B, C, D, u, v);
          if (!pose.L.allFinite() || !pose.b.allFinite()) fail(layer_, "the patch overflows");
          const bool corner = i == layer.columns - 1 && j == layer.rows - 1;
          for (const scene::Solid& solid : scene_.solids) {
            LineStyle line = corner && layer.corner ? *layer.corner : layer.line;
            std::optional<Color> fill;
            if (layer.fill) fill = solid.color.value_or(*layer.fill);
            solid_faces(solid, pose, fill, line, 1.0, index, faces);
          }
        }
      }
    } catch (const NoRealLogarithm& error) {
      fail(layer_, std::string("the patch needs SAMs between its corners and rows: ") + error.what());
    }
    paint(std::move(faces), false);
  }

  // Every other pose layer kind is refused by the reader (scene's
  // read_space_pose_layers: the table's in_space column).
  template <class Layer>
  void add(const Layer&) {
    fail(layer_, "this layer type draws pose scenes of the plane only");
  }

  const motion::Stage& stage_;
  std::size_t index_;
  const scene::Scene& scene_;
  const scene::Panel& panel_;
  const FrameSelection* selection_;
  const scene::SpacePoseKeys& keys_;
  std::optional<Projection> projection_;
  Drawing drawing_;
  std::string layer_;
};

}  // namespace

Projection::Projection(const scene::Camera& camera, const Vector3d& target)
    : target_(target), distance_(camera.distance), perspective_(camera.perspective) {
  if (perspective_ && !(distance_ > 0.0)) {
    throw std::invalid_argument(fmt::format("a perspective camera needs a distance > 0 (got {:g})", distance_));
  }
  const double a = camera.azimuth * kDegree, e = camera.elevation * kDegree;
  const Vector3d towards_eye(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
  eye_ = target_ + distance_ * towards_eye;
  forward_ = -towards_eye;
  const Vector3d world_up = std::abs(forward_.z()) > 0.999 ? Vector3d::UnitY() : Vector3d::UnitZ();
  right_ = forward_.cross(world_up).normalized();
  up_ = right_.cross(forward_);
}

std::optional<Point> Projection::project(const Vector3d& x) const {
  const Vector3d d = x - target_;
  double scale = 1.0;
  if (perspective_) {
    const double depth = (x - eye_).dot(forward_);
    if (!(depth > 1e-9 * distance_)) return std::nullopt;
    scale = distance_ / depth;
  }
  return Point{scale * d.dot(right_), scale * d.dot(up_)};
}

double Projection::depth(const Vector3d& x) const { return (x - eye_).dot(forward_); }

double face_shade(const Vector3d& normal, const Projection& projection) {
  const Vector3d light = (-projection.forward() + 0.8 * projection.up() - 0.5 * projection.right()).normalized();
  return 0.35 + 0.65 * std::abs(normal.dot(light));
}

Drawing space_panel_drawing(const motion::Stage& stage, std::size_t index, const FrameSelection* selection) {
  return SpaceBuilder(stage, index, selection).build();
}

Drawing space_panel_drawing(const scene::Scene& scene, const scene::Panel& panel, const FrameSelection* selection) {
  return space_panel_drawing(motion::Stage(scene, panel), 0, selection);
}

}  // namespace pita::render
