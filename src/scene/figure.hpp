// The figure part of a scene (README "Figures"): the canvas, the layers drawn
// in order, and the panels of a grid. Everything here is resolved: defaults
// applied, colours parsed, names looked up, so that render/ never sees JSON.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/arrow.hpp"
#include "core/keyframe.hpp"
#include "core/pitas/method_options.hpp"
#include "core/pitas/registry.hpp"

namespace pita::scene {

// Limits on what a scene may ask for (errors name the field and the bound).
inline constexpr int kMinCanvasSide = 16;        // pixels
inline constexpr int kMaxCanvasSide = 8192;      // pixels, per side
inline constexpr int kMaxTrajectorySamples = 100'000;
inline constexpr int kMaxFigureSamples = 10'000;  // frames of a drawn pattern
inline constexpr int kMaxPanels = 64;
inline constexpr int kMaxLayers = 64;
inline constexpr std::size_t kMaxTextLength = 1000;  // characters of a banner or label

// sRGB colour with alpha, each channel in [0, 1].
struct Color {
  double r = 0.0, g = 0.0, b = 0.0, a = 1.0;
  friend bool operator==(const Color&, const Color&) = default;
};

// How a line is drawn. Widths and dashes are in pixels of the output at
// scale 1 (they do not grow with the view).
struct LineStyle {
  Color color;
  double width = 1.0;          // > 0
  double opacity = 1.0;        // in [0, 1], multiplies color.a
  std::vector<double> dash;    // on, off, ... lengths (> 0); empty = solid
};

// An axis-aligned box of the plane (world units), min < max on both axes.
struct Box {
  Point min;
  Point max;
};

struct Canvas {
  int width = 800;                          // pixels, [kMinCanvasSide, kMaxCanvasSide]
  int height = 600;
  std::optional<Color> background = Color{1.0, 1.0, 1.0, 1.0};  // nullopt: transparent ("none")
  // World box shown in every panel; nullopt: each panel fits its own drawing
  // ("auto"), shared_fit: one box that fits every panel's drawing ("shared").
  std::optional<Box> view;
  bool shared_fit = false;
  double margin = 0.06;                      // fraction of the panel's smaller side, [0, 0.45]
  bool y_up = true;                          // mathematical axes (y up) unless "y_axis": "down"
  int columns = 0;                           // panels per row; 0 = automatic (ceil(sqrt(n)))
  std::string font = "Sans";                 // pango family for titles, labels and legends
};

// Which point of a frame a trajectory follows.
enum class TrackedPoint { start, end, middle };  // "p", "q", "mid"

// Where a keyframe's winding spiral is centred (Fig. 1: midpoint; others: start).
enum class SpiralCenter { start, middle };  // "start", "midpoint"

// The prediction a discrepancy circle compares each frame with (Sec. 6.1).
enum class Predictor {
  previous,  // the previous frame D(t_{i-1})
  average,   // the steady average M(D(t_{i-1}), D(t_{i+1})) (Eq. 23)
  pita,      // the chosen PITA through D(t_{i-3}), D(t_{i-2}), D(t_{i-1}), at t_i (Sec. 7.5)
};

// A time range [from, to] (from < to); nullopt in a layer means [a, c], the
// first and last knots.
struct TimeRange {
  double from = 0.0;
  double to = 1.0;
};

struct PatternLayer {  // "pattern": the frames D(t_i) as segments
  LineStyle line{Color{0.2, 0.2, 0.2, 1.0}, 0.8, 1.0, {}};
  bool extended = false;               // draw from p - (q - p) to q (Sec. 2.1)
  std::optional<int> samples;          // default: the panel's samples
  std::optional<TimeRange> range;      // default: [a, c]
};

struct KeyframesLayer {  // "keyframes": A, B, C as arrows with heads and winding spirals
  std::vector<Color> colors{Color{0.85, 0.0, 0.0, 1.0}, Color{0.0, 0.6, 0.0, 1.0},
                            Color{0.0, 0.0, 0.85, 1.0}};  // one per keyframe, cycled
  double width = 2.0;
  double opacity = 1.0;
  bool winding = true;                 // draw the spiral whose turns show w
  SpiralCenter spiral_center = SpiralCenter::start;
  bool extended = false;
};

struct TrajectoryLayer {  // "trajectory": the smooth path of p, q or the midpoint
  TrackedPoint point = TrackedPoint::start;
  int samples = 512;                   // [2, kMaxTrajectorySamples], independent of the pattern
  std::optional<TimeRange> range;
  LineStyle line{Color{0.45, 0.45, 0.45, 1.0}, 1.0, 1.0, {}};
};

struct StrokeLayer {  // "stroke": the filled quads between consecutive frames (Sec. 7.2)
  Color fill{0.25, 0.4, 0.65, 1.0};
  double opacity = 1.0;
  std::optional<LineStyle> outline;    // the strip's boundary
  std::optional<int> samples;
  std::optional<TimeRange> range;
};

struct BannerLayer {  // "banner": a text mapped through the pattern's quad strip (Sec. 7.3)
  std::string text;                    // required, 1..kMaxTextLength characters
  std::string font = "Sans Bold";      // pango font description (the size is irrelevant)
  Color fill{0.1, 0.1, 0.1, 1.0};
  double opacity = 1.0;
  std::optional<LineStyle> outline;
  double padding = 0.1;                // fraction of the strip's width left free on each side, [0, 0.45]
  std::optional<int> samples;
  std::optional<TimeRange> range;
};

struct DiscrepancyLayer {  // "discrepancy": circles of radius scale * E (Sec. 6.2, Fig. 17)
  Predictor predictor = Predictor::previous;
  std::optional<Method> method;        // predictor "pita": default the panel's method
  double scale = 30.0;                 // world units per unit of E, > 0
  LineStyle line{Color{0.8, 0.3, 0.0, 1.0}, 1.0, 1.0, {}};
  std::optional<Color> fill;
  std::optional<int> samples;
};

struct LabelLayer {  // "label": a text at a point of the plane
  std::string text;
  Point at;
  double size = 12.0;                  // pixels
  Color color{0.0, 0.0, 0.0, 1.0};
};

struct LegendLayer {  // "legend": the keyframes' colours and knots, and the method
  enum class Corner { top_left, top_right, bottom_left, bottom_right };
  Corner corner = Corner::top_left;
  double size = 11.0;                  // pixels
};

using Layer = std::variant<PatternLayer, KeyframesLayer, TrajectoryLayer, StrokeLayer,
                           BannerLayer, DiscrepancyLayer, LabelLayer, LegendLayer>;

// One cell of the grid: the scene's keyframes, method and options unless the
// panel overrides them. A scene without "panels" has one panel.
struct Panel {
  std::string title;                   // "" = no title; default for a panel given by
                                       // its method: "P6 La-LP"
  Method method = Method::P6;
  std::string method_name;             // canonical id, "P6"
  MethodOptions options;
  std::vector<Keyframe> keyframes;
  int samples = 9;
  std::string pointer;                 // JSON Pointer of the panel ("" = the scene itself)
  // The panel's own "layers", drawn instead of the scene's (Fig. 1 draws
  // different trajectories per panel); nullopt: the scene's layers.
  std::optional<std::vector<Layer>> layers;
};

}  // namespace pita::scene
