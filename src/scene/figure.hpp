// The figure part of a scene (docs/reference/render.md "Figures"): the canvas, the animation,
// each kind's figure data (the layers and shapes of arrow scenes; the
// reference simplex, shapes, layers and, in space, the camera of pose
// scenes), and the panels of a grid. Everything
// here is resolved: defaults applied, colours parsed, names looked up, so that
// render/ never sees JSON. The layers are in layers.hpp.
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <Eigen/Core>

#include "core/pose_traits.hpp"
#include "scene/layers.hpp"
#include "scene/motion_keys.hpp"
#include "scene/timing.hpp"

namespace pita::scene {

struct Canvas {
  int width = 800;  // pixels, [kMinCanvasSide, kMaxCanvasSide]
  int height = 600;
  std::optional<Color> background = Color{1.0, 1.0, 1.0, 1.0};  // nullopt: transparent ("none")
  // World box shown in every panel; nullopt: each panel fits its own drawing
  // ("auto"), shared_fit: one box that fits every panel's drawing ("shared").
  std::optional<Box> view;
  bool shared_fit = false;
  double margin = 0.06;       // fraction of the panel's smaller side, [0, 0.45]
  bool y_up = true;           // mathematical axes (y up) unless "y_axis": "down"
  int columns = 0;            // panels per row; 0 = automatic (ceil(sqrt(n)))
  std::string font = "Sans";  // pango family for titles, labels and legends
};

// "animation" (docs/reference/animate.md "Animation"): how `pita animate` and `pita render --at`
// play the scene. Command-line flags override these fields.
struct Animation {
  enum class What { motion, pattern };
  double duration = 4.0;      // seconds, > 0
  double fps = 30.0;          // (0, kMaxFps]
  std::optional<int> frames;  // [kMinAnimationFrames, kMaxAnimationFrames]; default round(duration * fps)
  bool loop = true;
  // "motion": one frame D(t) (and the shapes it carries) runs over the knots;
  // "pattern": the whole figure changes with tau in [0, 1] as its moving
  // keyframes move (PITA Sec. 7.4). Default: "pattern" when a keyframe
  // moves, else "motion".
  What what = What::motion;
  int trail = 0;  // "motion": how many earlier frames fade behind, [0, kMaxTrail]
  // The values of tau that a static figure of moving keyframes overlays
  // (Fig. 27), each in [0, 1]; default [0].
  std::vector<double> overlay{0.0};
};

// A solid of a 3D pose scene ("shapes" of docs/reference/pose-scenes.md "3D pose scenes"): a
// polyhedron given by its vertices and faces (indices into them, at least
// three each, in order around the face), or a builtin one.
struct Solid {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::vector<int>> faces;
  std::optional<Color> color;  // faces: the layer's fill otherwise
};

// How a 3D scene is seen ("camera"): from the direction (azimuth about the z
// axis from +x, elevation above the xy plane, degrees) at `distance` from
// the target, looking at it with z up; orthographic (parallel) or
// perspective projection onto the image plane, whose coordinates are the
// figure's world coordinates. With `automatic` ("auto"), pita turns the
// camera to the direction nearest the given one from which no pose is seen
// edge-on (render/camera_choice.hpp). With a `shadow` colour, every solid
// drawn casts its shadow, straight down, on the ground below the lowest one:
// the depth cue of the figure.
struct Camera {
  double azimuth = 35.0;
  double elevation = 25.0;
  double distance = 10.0;  // > 0 for perspective
  bool perspective = false;
  std::optional<Eigen::Vector3d> target;  // default: the centre of the solids at the poses
  bool automatic = false;
  std::optional<Color> shadow;
};

// ---------------------------------------------------------------- each kind's figure data

// A pose scene of the plane is drawn in the plane's own coordinates: it has
// no camera.
struct NoCamera {};

// What the figure of a pose scene is made of, by the dimension of its poses:
// poses of the plane move outlines (and images) of the plane; poses of space
// move solids, seen through a camera. The reference simplex defaults to the
// unit one (docs/reference/pose-scenes.md "Pose scenes" and "3D pose scenes").
template <class Pose>
struct FigureTraits;
template <>
struct FigureTraits<Affine2> {
  using Shape = ShapeOutline;
  using Camera = NoCamera;
  static PoseTraits<Affine2>::Simplex unit_simplex() { return {Point{0.0, 0.0}, Point{1.0, 0.0}, Point{0.0, 1.0}}; }
};
template <>
struct FigureTraits<Affine3> {
  using Shape = Solid;
  using Camera = scene::Camera;
  static PoseTraits<Affine3>::Simplex unit_simplex() {
    return {Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d(0.0, 1.0, 0.0),
            Eigen::Vector3d(0.0, 0.0, 1.0)};
  }
};
template <class Pose>
using ShapeOf = typename FigureTraits<Pose>::Shape;

// The points of a shape that a pose moves: an outline's, a solid's vertices.
inline const std::vector<Point>& points_of(const ShapeOutline& shape) { return shape.points; }
inline const std::vector<Eigen::Vector3d>& points_of(const Solid& solid) { return solid.vertices; }

// The figure of an arrow scene (keyframes or points): its layers, and the
// shapes its keyframes carry (PITA Sec. 7.1).
struct ArrowFigure {
  std::vector<Layer> layers;         // in drawing order; default: pattern, then keyframes (points: their curve)
  std::vector<ShapeOutline> shapes;  // carried by the handle; default none
};

// The figure of a pose scene: the reference simplex ("reference_triangle",
// "reference_tetrahedron") that poses given as simplices map, the shapes the
// poses move, the layers, and in space the camera.
template <class Pose>
struct PoseFigure {
  typename PoseTraits<Pose>::Simplex reference = FigureTraits<Pose>::unit_simplex();
  std::vector<ShapeOf<Pose>> shapes;  // default: the reference simplex (a triangle, a tetrahedron)
  std::vector<PoseLayer> layers;      // default: shapes, then poses
  [[no_unique_address]] typename FigureTraits<Pose>::Camera camera;
};

// A panel's part of the figure, of the scene's family: its own layers, drawn
// instead of the scene's (Fig. 1 draws different trajectories per panel;
// nullopt: the scene's), and the shapes it draws (the scene's, or in the
// plane the panel's own "shapes").
template <class LayerType, class Shape>
struct PanelFigureData {
  std::optional<std::vector<LayerType>> layers;
  std::vector<Shape> shapes;
};
using ArrowPanelFigure = PanelFigureData<Layer, ShapeOutline>;
template <class Pose>
using PosePanelFigure = PanelFigureData<PoseLayer, ShapeOf<Pose>>;

// The figure data of each family of kinds: arrows (keyframes and points, as a
// panel may draw points in a scene of keyframes), poses of the plane, poses of
// space. Which alternative a scene holds follows from its keys: figure_of
// below is the one way to reach it.
using SceneFigure = std::variant<ArrowFigure, PoseFigure<Affine2>, PoseFigure<Affine3>>;
using PanelFigure = std::variant<ArrowPanelFigure, PosePanelFigure<Affine2>, PosePanelFigure<Affine3>>;

// The figure types of the family of `Keys` (an alternative of MotionKeys):
// FigureOf<KeyframeKeys> is ArrowFigure, FigureOf<PoseKeys<Pose>> is PoseFigure<Pose>.
template <class Keys>
struct FamilyOf {  // KeyframeKeys, PointKeys
  using OfScene = ArrowFigure;
  using OfPanel = ArrowPanelFigure;
};
template <class Pose>
struct FamilyOf<PoseKeys<Pose>> {
  using OfScene = PoseFigure<Pose>;
  using OfPanel = PosePanelFigure<Pose>;
};
template <class Keys>
using FigureOf = typename FamilyOf<Keys>::OfScene;
template <class Keys>
using PanelFigureOf = typename FamilyOf<Keys>::OfPanel;

// One cell of the grid: the scene's keyframes, method and options unless the
// panel overrides them. A scene without "panels" has one panel.
struct Panel {
  std::string title;  // "" = no title; default for a panel given by
                      // its method: "P6 La-LP"
  // What the panel's motion is made of (the scene's unless the panel gives
  // its own method, keyframes, points or poses); its alternative is the kind
  // of the panel's motion.
  MotionKeys keys;
  int samples = 9;
  // Where `samples` came from: "/panels/2/samples", the scene's "/samples",
  // or "" for the default (what the render budget's messages name).
  std::string samples_pointer;
  std::string pointer;  // JSON Pointer of the panel ("" = the scene itself)
  // JSON Pointer that errors of the panel's motion name: its own keyframes or
  // poses, else the panel (its method with the scene's keyframes), else the
  // scene's "/keyframes", "/points" or "/poses".
  std::string motion_pointer = "/keyframes";
  // The panel's part of the figure, of the family of `keys`: its own layers
  // and the shapes it draws (figure_of, scene.hpp).
  PanelFigure figure;

  // "timing": the scene's unless the panel gives its own.
  Timing timing;
};

}  // namespace pita::scene
