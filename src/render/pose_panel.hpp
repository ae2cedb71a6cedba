// One panel of a pose scene as its layers see it, in the plane (Pose =
// Affine2) and in space (Pose = Affine3): the panel's poses and motion from
// the stage, the times a layer samples, the body the poses carry (the
// panel's shapes; the scene's solids) and how a point of it reaches the
// figure (the identity in the plane, the camera in space). The drawer of each
// layer kind (render/layers/pose_layers.hpp) draws through it.
#pragma once

#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include <Eigen/Core>

#include "core/affine2.hpp"
#include "core/affine3.hpp"
#include "core/pose_traits.hpp"
#include "render/drawing.hpp"
#include "render/panel_drawing.hpp"
#include "render/projection.hpp"
#include "scene/scene.hpp"

namespace pita::motion {
class SceneMotion;  // motion/scene_motion.hpp
}

namespace pita::render {

// A point of the body a pose moves: a point of the plane, or of space.
template <class Pose>
using BodyPoint = typename PoseTraits<Pose>::BodyPoint;

// How the figure sees a body point: nothing in the plane, the camera in space.
template <class Pose>
using PoseView = std::conditional_t<in_space_v<Pose>, Projection, std::monostate>;

template <class Pose>
class PosePanel {
 public:
  using Keys = scene::PoseKeys<Pose>;

  // Throws RenderError when the panel holds no poses of this dimension, or
  // (in space) when the camera cannot see the scene. With a cache (frames of
  // one animation), the view in space is chosen once and kept there.
  PosePanel(const motion::Stage& stage, std::size_t index, const FrameSelection* selection,
            StaticLayers* cache = nullptr);

  const motion::Stage& stage() const { return stage_; }
  std::size_t index() const { return index_; }
  const scene::Scene& scene() const { return scene_; }
  const scene::Panel& panel() const { return panel_; }
  const Keys& keys() const { return keys_; }
  // The scene's figure data (reference simplex, shapes, layers, camera in
  // space), and the shapes this panel draws: the scene's, or in the plane the
  // panel's own.
  const scene::PoseFigure<Pose>& figure() const { return scene::figure_of<Keys>(scene_); }
  const std::vector<scene::ShapeOf<Pose>>& shapes() const { return scene::figure_of<Keys>(panel_).shapes; }
  // An animation frame's time and trail, or nullptr for the static figure.
  // Every layer asks here, so that a layer that never asks is known to be
  // the same at every frame (render/static_layers.hpp).
  const FrameSelection* selection() const {
    read_frame_ = true;
    return selection_;
  }
  // Whether the layer being drawn asked for the frame.
  bool took_frame() const { return read_frame_; }

  // The layer being drawn: its JSON Pointer names every error.
  void begin_layer(std::string pointer) {
    layer_ = std::move(pointer);
    read_frame_ = false;
  }
  const std::string& layer() const { return layer_; }
  [[noreturn]] void fail(const std::string& reason) const;
  [[noreturn]] void fail_at(const std::string& pointer, const std::string& reason) const;

  // The panel's motion, built once by the stage; fails when the panel has no
  // poses or its method has no motion through them.
  const motion::SceneMotion& motion() const;
  // A(t) and dA/du at scene time t, u the time normalised to the motion's
  // duration (1 from the first pose to the last).
  Pose pose_at(double t) const;
  Pose velocity_at(double t) const;
  // `samples` (else the panel's) times evenly over `range` (else the motion's knots).
  std::vector<double> times(const std::optional<int>& samples, const std::optional<scene::TimeRange>& range) const;

  // The points of the body, in the order the layers draw them: every point of
  // every shape (plane), every vertex of every solid (space); scene::body_points,
  // the rule pita measure's ARA follows too.
  std::vector<BodyPoint<Pose>> body_points() const;
  // Where a point of the world is drawn; in space, fails when it is behind a
  // perspective camera.
  Point image(const BodyPoint<Pose>& x) const;
  const PoseView<Pose>& view() const { return view_; }

  void push(int index, Shape shape, bool moving = false);
  void append(std::vector<Item> items);
  // In space with "camera": {"shadow": ...}: the shadow of one solid at a
  // pose (its faces, points of space), cast straight down on the ground: the
  // plane z = the lowest point of the solids at the panel's poses and its
  // motion's samples, or of any shadow lower still. take() paints every
  // shadow first, under all the layers, at "/camera/shadow".
  void cast_shadow(int index, std::vector<std::vector<Eigen::Vector3d>> faces, double opacity, bool moving);
  std::size_t shadow_count() const { return shadows_.size(); }
  // The drawing so far (before take()'s shadows).
  Drawing& drawing() { return drawing_; }
  Drawing take();

 private:
  const motion::Stage& stage_;
  std::size_t index_;
  const scene::Scene& scene_;
  const scene::Panel& panel_;
  const FrameSelection* selection_;  // through selection() only
  mutable bool read_frame_ = false;
  const Keys& keys_;
  double ground_ = 0.0;  // z of the ground (space, with a shadow): set with view_, so declared first
  PoseView<Pose> view_;
  std::string layer_;
  Drawing drawing_;
  struct Shadow {
    int index;
    std::vector<std::vector<Eigen::Vector3d>> faces;
    double opacity;
    bool moving;
  };
  std::vector<Shadow> shadows_;
};

extern template class PosePanel<Affine2>;
extern template class PosePanel<Affine3>;

// The camera panel `index` of a 3D pose scene is drawn with: the scene's,
// turned as "auto" turns it (camera_choice.hpp) when it says so; `pita serve`
// starts turning a panel in the page from it. Throws RenderError when the
// panel has no poses of space.
scene::Camera drawn_camera(const motion::Stage& stage, std::size_t index);

}  // namespace pita::render
