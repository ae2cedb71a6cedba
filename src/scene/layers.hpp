// The layers of a figure (docs/reference/render.md "Figures", docs/reference/pose-scenes.md "Pose scenes"): one struct
// per layer kind with its fields resolved (defaults applied, colours parsed, names looked up), the styles they share,
// and the variants of the layers of arrow scenes (Layer) and of pose scenes (PoseLayer). Read by arrow_layer_reader.cpp
// and pose_layer_reader.cpp; drawn by render/.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/arrow.hpp"
#include "core/keyframe.hpp"
#include "core/pitas/method_options.hpp"
#include "core/pitas/registry.hpp"
#include "core/point_curves.hpp"
#include "core/pose_motion.hpp"
#include "core/sam_family_motion.hpp"
#include "scene/limits.hpp"
#include "scene/measure_name.hpp"
#include "scene/motion_keys.hpp"
#include "scene/timing.hpp"

namespace pita::scene {

// sRGB colour with alpha, each channel in [0, 1].
struct Color {
  double r = 0.0, g = 0.0, b = 0.0, a = 1.0;
  friend bool operator==(const Color&, const Color&) = default;
};

// How a line is drawn. Widths and dashes are in pixels of the output at
// scale 1 (they do not grow with the view).
struct LineStyle {
  Color color;
  double width = 1.0;        // > 0
  double opacity = 1.0;      // in [0, 1], multiplies color.a
  std::vector<double> dash;  // on, off, ... lengths (> 0); empty = solid
  friend bool operator==(const LineStyle&, const LineStyle&) = default;
};

// An axis-aligned box of the plane (world units), min < max on both axes.
struct Box {
  Point min;
  Point max;
};

// Where a keyframe's winding spiral is centred (Fig. 1: midpoint; others: start).
enum class SpiralCenter { start, middle };  // "start", "midpoint"

// The prediction a discrepancy circle compares each frame with (Sec. 6.1).
enum class Predictor {
  previous,  // the previous frame D(t_{i-1})
  average,   // the steady average M(D(t_{i-1}), D(t_{i+1})) (PITA Eq. 23)
  pita,      // the chosen PITA through D(t_{i-3}), D(t_{i-2}), D(t_{i-1}), at t_i (Sec. 7.5)
};

// A time range [from, to] (from < to); nullopt in a layer means [a, c], the
// first and last knots.
struct TimeRange {
  double from = 0.0;
  double to = 1.0;
};

// A layer's "options": the panel's method options it changes, each left
// unset keeps the panel's (docs/paper-notes.md N57).
struct MethodOptionsPatch {
  MethodOptions values;  // the options given (the others are not read)
  unsigned given = 0;    // their MethodOption bits (core/pitas/method_options.hpp)

  bool empty() const { return given == 0; }
  MethodOptions over(const MethodOptions& base) const { return with_options(base, values, given); }
};

struct PatternLayer {  // "pattern": the frames D(t_i) as segments
  LineStyle line{Color{0.2, 0.2, 0.2, 1.0}, 0.8, 1.0, {}};
  // Overlays (Figs. 4, 5): the frames of another method, or of the panel's
  // with other options, through the panel's keyframes; "label" names it in legends.
  std::optional<Method> method;
  MethodOptionsPatch options;
  std::string label;
  bool extended = false;           // draw from p - (q - p) to q (Sec. 2.1)
  bool coils = false;              // each frame's winding as a spiral at p (Fig. 3)
  bool heads = false;              // each frame as an arrow, head at q (Figs. 7, 28)
  std::optional<int> samples;      // default: the panel's samples
  std::optional<TimeRange> range;  // default: [a, c]
  std::vector<double> times;       // set: exactly these times (Fig. 5's D(1/4)), not samples/range
  bool dots = false;               // a dot at each frame's p instead of its segment (Fig. 6)
};

struct KeyframesLayer {       // "keyframes": A, B, C as arrows with heads and winding spirals
  std::vector<Color> colors;  // one per keyframe, cycled; none: the default series (scene::series_color)
  double width = 2.0;
  double opacity = 1.0;
  bool winding = true;  // draw the spiral whose turns show w
  SpiralCenter spiral_center = SpiralCenter::start;
  bool extended = false;
};

struct TrajectoryLayer {  // "trajectory": the smooth path of p, q or the midpoint
  TrackedPoint point = TrackedPoint::start;
  int samples = 512;  // [2, kMaxTrajectorySamples], independent of the pattern
  std::optional<TimeRange> range;
  LineStyle line{Color{0.45, 0.45, 0.45, 1.0}, 1.0, 1.0, {}};
  // The path of another method, or of the panel's with other options, as
  // a "pattern" layer's (Fig. D.35: each overlaid pattern with its path).
  std::optional<Method> method;
  MethodOptionsPatch options;
};

struct StrokeLayer {  // "stroke": the filled quads between consecutive frames (Sec. 7.2)
  Color fill{0.25, 0.4, 0.65, 1.0};
  double opacity = 1.0;
  std::optional<LineStyle> outline;  // the strip's boundary
  std::optional<int> samples;
  std::optional<TimeRange> range;
};

struct BannerLayer {               // "banner": a text mapped through the pattern's quad strip (Sec. 7.3)
  std::string text;                // required, 1..kMaxTextLength characters
  std::string font = "Sans Bold";  // pango font description (the size is irrelevant)
  Color fill{0.1, 0.1, 0.1, 1.0};
  double opacity = 1.0;
  std::optional<LineStyle> outline;
  double padding = 0.1;  // fraction of the strip's width left free on each side, [0, 0.45]
  std::optional<int> samples;
  std::optional<TimeRange> range;
};

struct DiscrepancyLayer {  // "discrepancy": circles of radius scale * E (Sec. 6.2, Fig. 17)
  Predictor predictor = Predictor::previous;
  std::optional<Method> method;  // predictor "pita": default the panel's method
  double scale = 30.0;           // world units per unit of E, > 0
  LineStyle line{Color{0.8, 0.3, 0.0, 1.0}, 1.0, 1.0, {}};
  std::optional<Color> fill;
  std::optional<int> samples;
};

struct LabelLayer {  // "label": a text at a point of the plane
  std::string text;
  Point at;
  double size = 12.0;  // pixels
  Color color{0.0, 0.0, 0.0, 1.0};
  // "place": "at" (the text starts at `at`) or "auto": the figure moves it
  // around `at` to where it covers no data (render/label_placement.hpp).
  bool avoid_data = false;
};

struct LegendLayer {  // "legend": the keyframes' colours and knots, and the method
  enum class Corner { top_left, top_right, bottom_left, bottom_right };
  Corner corner = Corner::top_left;
  double size = 11.0;  // pixels
};

// "plot": the distance-time function of the panel's timing (the chapter's
// Sec. 3.2.2): the fraction of the tracked point's path covered against the
// fraction of time, drawn in a box of the plane with its frame, the diagonal
// of constant speed, and a dot at each of the panel's frame times.
// With "of": "area" (pose scenes; SAM paper Fig. 9, docs/paper-notes.md N48)
// it draws instead the area of the moving shapes, |det L(t)| times their
// reference area, over time, for each of `methods` (default the panel's) on
// the panel's poses, scaled so that the smallest and the largest area met by
// any curve span the box's height (a constant area sits at mid-height), with
// each curve's summary printed under the box: monotone and end/start, or its
// interior extremum (render/time_chart.cpp).
enum class PlotOf { distance, area, time };
struct PlotLayer {
  Box box{Point{0.0, 0.0}, Point{1.0, 1.0}};  // required: where the unit square is drawn
  PlotOf of = PlotOf::distance;
  std::vector<PoseMethod> methods;  // "area": empty = the panel's method
  std::vector<Color> colors{Color{0.0, 0.45, 0.0, 1.0}, Color{0.75, 0.1, 0.1, 1.0},
                            Color{0.1, 0.3, 0.7, 1.0}};  // "area": one per method, cycled
  TrackedPoint point = TrackedPoint::start;
  int samples = 200;  // [2, kMaxTrajectorySamples]
  LineStyle line{Color{0.1, 0.3, 0.7, 1.0}, 1.5, 1.0, {}};
  bool marks = true;
  double size = 10.0;  // text size of the axes' names; their end values one pixel smaller
};
inline constexpr std::size_t kMaxPlotMethods = 8;

// "point-trajectory": a curve through the panel's timed "points" (PITA Sec. 7.6,
// Fig. 29): the PITA-based curve of PITA Eq. 48-50 with the panel's method and
// chain, or one of the curves it is compared with (core/point_curves.hpp).
struct PointTrajectoryLayer {
  PointCurve curve = PointCurve::pita;
  int samples = 512;               // [2, kMaxTrajectorySamples]
  std::optional<TimeRange> range;  // default: first to last point's knot
  LineStyle line{Color{0.1, 0.1, 0.1, 1.0}, 1.5, 1.0, {}};
  bool dots = true;  // a dot at each timed point
};

// "vectors" (PITA Figs. 9, 14, 15; docs/paper-notes.md N40): at each frame
// the velocity or the acceleration of D(t).p and D(t).q as arrows, drawn
// `scale` x the derivative by the normalised time u = (t - a)/(c - a) (as
// the pose scenes' "velocities"). Not to be confused with those: this one
// draws the arrow's two points, of arrow scenes.
enum class VectorKind { velocity, acceleration };  // "of"
struct VectorsLayer {
  VectorKind of = VectorKind::acceleration;
  bool at_p = true, at_q = true;      // "at": "both", "p" or "q"
  bool tail_at_point = true;          // "at_point": "tail" (from the point) or "head" (onto it)
  double scale = 0.1;                 // > 0; default by `of` (reader)
  Color color_p{0.0, 0.0, 0.0, 1.0};  // "colors": [at p, at q]; default by `of` (reader)
  Color color_q{139.0 / 255.0, 69.0 / 255.0, 19.0 / 255.0, 1.0};  // brown, #8b4513
  LineStyle line{Color{}, 1.2, 1.0, {}};                          // width, opacity, dash (colour from color_p/q)
  bool heads = true;                                              // arrowheads
  std::optional<int> samples;
  std::optional<TimeRange> range;
};

// "fixed-points" (PITA Fig. 9; docs/paper-notes.md N40): at each frame a
// segment from D(t).p (or q, mid) to a center of the motion: P7's global
// fixed point f (PITA Eq. 35-36), or the instantaneous center where the
// acceleration (default) or the velocity of the plane's moving points is zero.
enum class CenterKind { global, acceleration, velocity };  // "center"
struct FixedPointsLayer {
  CenterKind center = CenterKind::acceleration;
  TrackedPoint point = TrackedPoint::start;
  LineStyle line{Color{1.0, 140.0 / 255.0, 0.0, 1.0}, 1.0, 1.0, {}};  // orange, #ff8c00
  bool dots = true;                                                   // a dot at each center
  std::optional<int> samples;
  std::optional<TimeRange> range;
};

// A closed outline (polygon) or open polyline in reference coordinates.
// A raster image placed in the shapes' frame (PITA Sec. 7.1): a PNG file read
// by cairo when drawn. The scene reader has checked that the file exists, is a
// PNG of at most kMaxImageSide pixels a side, and lies in the scene's folder
// tree (docs/reference/render.md "Figure fields of a scene").
struct ImageRef {
  std::string path;   // the file to open (the scene's folder joined with `given`)
  std::string given;  // as the scene spells it (what messages and goldens show)
  int width = 0;      // pixels, from the PNG header
  int height = 0;
  std::string pointer;  // JSON Pointer of "image" in the scene (what decoding errors name)
};

// A closed outline (polygon), an open polyline, or an image, in the frame of
// the shapes (reference coordinates of a pose scene; the handle's frame of an
// arrow scene). An image's points are the corners of its box, counter-
// clockwise from (x0, y0); it is drawn upright in that box.
struct ShapeOutline {
  std::vector<Point> points;  // at least 2
  bool closed = true;
  std::optional<Color> color;     // nullopt: the layer's colour
  std::optional<ImageRef> image;  // set: an image in the box of `points`
};

// "shapes": the shapes at each frame (a pattern of shapes). In pose scenes
// each frame maps them by the pose A(t); in arrow scenes by the carrier
// similarity that takes the handle onto D(t) (PITA Sec. 7.1).
struct ShapesLayer {
  LineStyle line{Color{0.15, 0.3, 0.6, 1.0}, 1.0, 1.0, {}};
  std::optional<Color> fill;  // filled with fill_opacity when given
  double fill_opacity = 0.25;
  std::optional<int> samples;      // default: the panel's samples
  std::optional<TimeRange> range;  // default: first to last knot
  std::vector<double> times;       // set: exactly these times (Fig. 24's square at B)
  // "lightness": "area" (pose scenes; SAM paper Fig. 9, docs/paper-notes.md
  // N48): each frame's line and fill mixed with white in proportion to its
  // area among the layer's frames (the smallest as given, the largest lightest).
  bool lightness_by_area = false;
};

// "handle" (PITA Sec. 7.1, Fig. 23): the picture X where it was drawn, in
// its own frame, and the handle arrow E over it.
struct HandleLayer {
  Color color{0.85, 0.0, 0.0, 1.0};
  double width = 2.0;
  bool shapes = true;  // draw the shapes (images, outlines) under the handle
};

// "property-table" (PITA Fig. 10): the properties of Sec. 4 measured as
// `pita audit` does (analysis/audit.hpp) for `methods`, drawn as a table whose
// top-left corner is `at`, one world unit per pixel at scale 1 (docs/reference/audit.md
// "pita audit": give the canvas a view that shows it so). It ignores the
// panel's keyframes.
// "trees" of a property-table layer: Fig. 10's decision trees, drawn below
// the table from the same measurements (analysis/decision_tree.hpp).
struct DecisionTreeSpec {
  std::string title;
  std::vector<std::string> order;  // property names, in the order asked (checked when drawn: render/)
  std::vector<Method> methods;     // empty: P1-P8
  std::string pointer;             // "/layers/0/trees/1", for errors
};
inline constexpr std::size_t kMaxDecisionTrees = 4;

struct PropertyTableLayer {
  std::vector<Method> methods;  // empty: every arrow method through three keyframes
  int configs = 200;            // random configurations, [1, kMaxTableConfigs]
  int seed = 1;                 // [0, 2^31 - 1]
  Point at{0.0, 0.0};
  std::vector<DecisionTreeSpec> trees;
};
inline constexpr int kMaxTableConfigs = 2000;

// The most names a "measures" layer shows (the schema's maxItems).
inline constexpr std::size_t kMaxMeasures = 17;

// "measures": the numbers of `pita measure` (analysis/measure.hpp) for the
// panel's motion, one line per name of `show`, at a point of the plane or in
// a corner of the panel.
struct MeasuresLayer {
  // The names (scene/measure_name.hpp, the one table; docs/reference/render.md "Figure fields of a scene"), parsed
  // and checked against the scene's kind by the reader. Default:
  // default_measures() of the scene's kind.
  std::vector<MeasureName> show;
  std::optional<Point> at;  // world point; nullopt: `corner`
  LegendLayer::Corner corner = LegendLayer::Corner::bottom_left;
  double size = 11.0;  // pixels
  Color color{0.1, 0.1, 0.1, 1.0};
};

// One arrow a user drew for a time t (PITA Sec. 6.1, 6.3): the in-betweener's
// guesses L and R of Fig. 16, the editing target E of Fig. 18.
struct Guess {
  double t = 0.0;
  Arrow arrow;       // as drawn: {"p", "q"} or {"p", "m", "w"}
  std::string name;  // what the printed lines call it ("L"); default "G1", "G2", ...
  Color color;       // default brown, magenta, orange, cycled
};

// What a "guesses" layer prints for each guess G at t: the discrepancy
// E(G, D(t)) (PITA Eq. 47, docs/paper-notes.md N5) or the distance
// max(|G.p - D(t).p|, |G.q - D(t).q|) (docs/paper-notes.md N53).
enum class GuessMeasure { discrepancy, distance };

// "guesses" (PITA Figs. 16, 18; docs/paper-notes.md N53): each guess as an
// arrow in its colour, the panel's frame D(t) at its time as an arrow in
// `frame_color`, and one printed line per guess and measure.
struct GuessesLayer {
  std::vector<Guess> guesses;  // required, 1..kMaxGuesses
  std::vector<GuessMeasure> show{GuessMeasure::discrepancy};
  double width = 2.0;  // of the guesses and the frames
  Color frame_color{0.1, 0.1, 0.1, 1.0};
  std::optional<Point> at;  // world point of the text; nullopt: `corner`
  LegendLayer::Corner corner = LegendLayer::Corner::bottom_left;
  double size = 11.0;               // pixels
  Color color{0.1, 0.1, 0.1, 1.0};  // of the text
};
inline constexpr int kMaxGuesses = 16;

// "compare" (PITA appendix B, Fig. B.30; docs/paper-notes.md N54): the
// pattern of another method through the panel's keyframes, drawn over the
// panel's, and the printed largest distance between their frames at the same
// times, max_i max(|dp|, |dq|).
struct CompareLayer {
  Method method = Method::P10;  // required
  std::string method_name = "P10";
  LineStyle line{Color{0.9, 0.45, 0.0, 1.0}, 1.2, 1.0, {4.0, 3.0}};
  std::optional<int> samples;  // default: the panel's samples
  std::optional<Point> at;     // world point of the text; nullopt: `corner`
  LegendLayer::Corner corner = LegendLayer::Corner::bottom_left;
  double size = 11.0;  // pixels
};

using Layer =
    std::variant<PatternLayer, KeyframesLayer, TrajectoryLayer, StrokeLayer, BannerLayer, DiscrepancyLayer, LabelLayer,
                 LegendLayer, PlotLayer, PointTrajectoryLayer, ShapesLayer, HandleLayer, PropertyTableLayer,
                 MeasuresLayer, VectorsLayer, FixedPointsLayer, GuessesLayer, CompareLayer>;

// ------------------------------------------------------------ pose scenes
// Scenes of timed affine poses (SAM paper; docs/reference/pose-scenes.md "Pose scenes"). Their
// shapes are outlines in the frame of the reference pose, drawn through the
// pose of each frame.

struct PosesLayer {           // "poses": the shapes at the control poses
  std::vector<Color> colors;  // one per pose, cycled; none: the default series (scene::series_color)
  double width = 2.0;
  double fill_opacity = 0.15;
  // Four-point SAM (SAM Fig. 13): the control poses inserted by the panel's
  // last subdivision step, drawn in this colour (docs/paper-notes.md N43).
  std::optional<Color> inserted;
};

struct VelocitiesLayer {  // "velocities": the velocity of each vertex at each frame
  double scale = 0.25;    // drawn length = scale * velocity (per unit of time)
  LineStyle line{Color{0.8, 0.2, 0.1, 1.0}, 1.0, 1.0, {}};
  std::optional<int> samples;
  std::optional<TimeRange> range;
};

// "field" (SAM paper Fig. 8, SAM Eq. 7; docs/paper-notes.md N47): the stationary
// velocity field of the panel's SAM (two poses) as arrows at the nodes of a
// grid over `box`, drawn `scale` x the velocity per unit of the normalised
// time u (as "velocities"), and the trajectories through every `curves`-th
// node, its integral curves, over `range` (scene times; default the knots).
// The measured agreement of the curves with the field is printed under the box.
struct FieldLayer {
  Box box{Point{0.0, 0.0}, Point{1.0, 1.0}};  // required
  int columns = 15;                           // nodes per row, [2, kMaxFieldSide]
  int rows = 11;                              // nodes per column, [2, kMaxFieldSide]
  double scale = 0.15;                        // > 0
  LineStyle line{Color{0.25, 0.25, 0.25, 1.0}, 0.8, 1.0, {}};
  int curves = 0;  // every curves-th node in both directions; 0: none
  LineStyle curve{Color{0.2, 0.45, 0.8, 1.0}, 0.8, 1.0, {}};
  std::optional<TimeRange> range;
  bool fixed_point = true;  // a dot at the field's zero (A's fixed point)
};
inline constexpr int kMaxFieldSide = 100;

struct PathsLayer {  // "paths": the trajectory of each vertex of each shape
  int samples = 256;
  std::optional<TimeRange> range;
  LineStyle line{Color{0.55, 0.55, 0.55, 1.0}, 0.8, 1.0, {}};
};

struct PatchLayer {      // "patch": SAM paper Fig. 11, the panel's first four poses as corners
  int columns = 5;       // shapes per row, [2, 100]
  int rows = 4;          // shapes per column, [2, 100]
  bool regular = false;  // replace the 4th pose by SAM(C, A, 1, B)
  LineStyle line{Color{0.15, 0.3, 0.6, 1.0}, 1.0, 1.0, {}};
  std::optional<Color> fill;
  double fill_opacity = 0.25;
  std::optional<LineStyle> corner;  // the bottom-right shape's line (Fig. 11's F_D), if given
  std::optional<LineStyle> grid;    // lines through the bodies' centres along rows and columns, if given
};

// "existence": Fig. 6 of the SAM paper in the plane (a, s): L = R(a) diag(1/s, s)
// classified by EAR's case selection on a grid of cells over a in [-pi, pi],
// s in (0, 1]; cells without a SAM (G3) are filled; the boundary of PITA Eq. 4,
// |a| = acos(-2s/(s^2+1)), and the trapezoid |a| < (1+s) pi/2 are drawn over it.
struct ExistenceLayer {
  int columns = 360;
  int rows = 200;
  Color fill{0.85, 0.2, 0.2, 1.0};  // no SAM
  std::optional<Color> exists_fill = Color{0.93, 0.96, 0.93, 1.0};
  LineStyle boundary{Color{0.0, 0.0, 0.0, 1.0}, 1.5, 1.0, {6.0, 4.0}};  // SAM Eq. 4
  LineStyle trapezoid{Color{0.0, 0.0, 0.0, 1.0}, 2.0, 1.0, {}};
};

// "sam3d-existence": the 3D existence experiment of the SAM paper's Sec. 5.2
// as a plot (docs/reference/audit.md "Where a SAM exists in 3D", docs/paper-notes.md N61): the
// largest safe perturbation p against the rotation angle theta in [0, pi],
// computed at theta = k pi / steps (analysis/sam3d_existence.hpp), drawn as a
// staircase over x = theta, y = kSafeCurveScale p, with the paper's three
// stated bounds beside it.
struct Sam3dExistenceLayer {
  int steps = 48;        // angles k pi / steps, k = 0..steps: [1, kMaxSam3dExistenceSteps]
  int subdivisions = 2;  // of the icosahedron: [0, kMaxSam3dExistenceSubdivisions]
  double step = 0.01;    // the grid of p
  LineStyle line{Color{0.1, 0.3, 0.7, 1.0}, 2.0, 1.0, {}};
  std::optional<Color> fill = Color{0.1, 0.3, 0.7, 1.0};  // under the curve, at fill_opacity; or "none"
  double fill_opacity = 0.12;
  bool paper = true;  // the paper's bounds
  LineStyle paper_line{Color{0.85, 0.35, 0.0, 1.0}, 1.5, 1.0, {6.0, 4.0}};
};
inline constexpr double kSafeCurveScale = 5.0;  // drawn height of p = 1

// "ara": the panel's measured unsteadiness printed as a text, "ARA = 0.042"
// (SAM paper Sec. 2.4, Fig. 2): core/steadiness.hpp's average relative
// acceleration of the panel's motion (its method, without the timing), over a
// grid x grid regular sampling of the bounding box of the panel's shapes in
// reference coordinates (the paper's "dense regular sampling of a vicinity of
// the moving shape").
struct AraLayer {
  Point at;            // required: where the text goes
  double size = 12.0;  // pixels
  Color color{0.0, 0.0, 0.0, 1.0};
  int digits = 3;  // decimals, [0, kMaxAraDigits]
  int grid = 11;   // points per side, [2, kMaxAraGrid]; core's kDefaultAraGrid (pita measure's)
};
inline constexpr int kMaxAraDigits = 9;
inline constexpr int kMaxAraGrid = 100;

// "swept": SAM paper Fig. 10 (Sec. 7.2, SAM Eq. 8): an edge given in reference
// coordinates, carried by the panel's motion; its copies at the layer's
// frames, the paths of its ends, the envelope (the grazing points A(t) x(s(t))
// with s(t) in [0, 1], core/grazing_point.hpp), and the paths of the points
// of the edge grazing at `instants` evenly spread times, each with a dot
// where it grazes (Fig. 10's green trajectories). nullopt hides a part.
// With `claim_at`, it prints how far the grazing parameter moves along the
// edge over the layer's range (constant under a SAM).
struct SweptLayer {
  std::array<Point, 2> edge{};  // required, reference coordinates
  std::optional<int> samples;   // copies of the edge (the panel's samples)
  std::optional<TimeRange> range;
  int trace_samples = 512;  // times of the envelope and the paths, [2, kMaxTrajectorySamples]
  int instants = 3;         // grazing paths, [0, kMaxSweptInstants]
  std::optional<LineStyle> segments = LineStyle{Color{0.35, 0.35, 0.35, 1.0}, 0.8, 1.0, {}};
  std::optional<LineStyle> ends = LineStyle{Color{0.55, 0.55, 0.55, 1.0}, 0.8, 1.0, {4.0, 3.0}};
  std::optional<LineStyle> envelope = LineStyle{Color{0.8, 0.1, 0.1, 1.0}, 2.5, 1.0, {}};
  std::optional<LineStyle> grazing = LineStyle{Color{0.0, 0.62, 0.0, 1.0}, 1.5, 1.0, {}};
  std::optional<Point> claim_at;    // where the measured claim goes; nullopt: not printed
  double size = 12.0;               // pixels
  Color color{0.0, 0.0, 0.0, 1.0};  // of the claim
};
inline constexpr int kMaxSweptInstants = 64;

// "versus": the shapes carried by the panel's poses interpolated by another
// pose method, over the panel's own motion (SAM paper Fig. 4: the mid-way
// poses of SAM and of Alexa's blend, and their squares; Fig. 5: the two
// motions overlaid). With `power` k each drawn pose D(t) becomes
// (D(t) o D(t0)^-1)^k o D(t0), t0 the first knot: the displacement from the
// first pose applied k times (k = 2 at t = 1/2 is Fig. 4's "squared" pose,
// which is the last pose exactly when the motion is steady).
struct VersusLayer {
  PoseMethod method = PoseMethod::sam;  // required
  std::vector<double> at;               // the times drawn; empty: `samples` over `range`
  int power = 1;                        // [1, kMaxComparePower]
  LineStyle line{Color{0.0, 0.0, 0.85, 1.0}, 1.0, 1.0, {}};
  std::optional<Color> fill;  // filled with fill_opacity when given
  double fill_opacity = 0.25;
  std::optional<int> samples;      // default: the panel's samples
  std::optional<TimeRange> range;  // default: first to last knot
};
inline constexpr int kMaxComparePower = 16;
inline constexpr std::size_t kMaxCompareTimes = 64;

using PoseLayer =
    std::variant<ShapesLayer, PosesLayer, VelocitiesLayer, PathsLayer, ExistenceLayer, LabelLayer, PatchLayer,
                 PlotLayer, AraLayer, MeasuresLayer, SweptLayer, VersusLayer, FieldLayer, Sam3dExistenceLayer>;

// A layer's "type" ("pattern", "poses", ...), from the one table of layer
// kinds of its scene's kind (scene/layer_kinds.hpp).
std::string_view layer_type(const Layer& layer);
std::string_view layer_type(const PoseLayer& layer);

}  // namespace pita::scene
