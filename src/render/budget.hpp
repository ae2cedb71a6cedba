// The work budget of a figure (issue 11): what drawing a scene will cost,
// estimated from the scene alone before anything is evaluated or drawn, and
// refused above a documented budget with the JSON Pointer of the field that
// dominates. Every field has its own limit (scene/limits.hpp), but fields
// multiply: 64 panels x 64 layers x 10 000 frames is within every limit and
// far beyond any machine.
//
// The unit is one drawn point; each separately drawn shape (a frame's segment,
// a circle, a polyline) costs kShapeUnits more, since cairo writes every shape
// with its own style (docs/reference/exit-codes-and-limits.md "Exit codes, errors and limits" has the
// measurements behind the numbers).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "scene/scene.hpp"

namespace pita::render {

inline constexpr double kShapeUnits = 16.0;
// About 5 s and 400 MB for an SVG on one core of the reference machine;
// PNG and PDF cost less (docs/explanation/performance.md "Performance").
inline constexpr double kDefaultBudgetUnits = 2e6;
// PNG pixels (canvas x scale^2): 8192 x 8192, 256 MiB of ARGB, about 4 s.
inline constexpr double kDefaultBudgetPixels = 8192.0 * 8192.0;
// Length of the lines a PNG strokes, in its pixels: rasterizing costs about
// 0.1 s per million pixels of line (a 10 000-point zigzag whose every segment
// crosses the panel costs more than a smooth 100 000-point curve).
inline constexpr double kDefaultBudgetInk = 3e7;
// --budget multiplies all three; at most this much.
inline constexpr double kMaxBudgetFactor = 1000.0;

// One part of the estimate: the units a field drives, and the field.
struct CostPart {
  std::string pointer;  // the field that sets the count ("/panels/3/layers/2/samples", "/samples")
  std::string layer;    // the layer ("/panels/3/layers/2")
  std::string what;     // "10000 frames of a pattern"
  double units = 0.0;
};

struct FigureCost {
  double units = 0.0;
  std::vector<CostPart> parts;  // one per layer and panel
};

// The estimate of every panel's layers. Throws RenderError at "/samples" when
// the scene's top-level "samples" (up to kMaxSamples, meant for `eval`) would
// give a drawn layer more frames than kMaxFigureSamples.
FigureCost estimate_cost(const scene::Scene& scene);

// What building a scene's motions costs, in the same units (about one method
// frame each), beyond the frames drawn: an arc-length timing measures its
// point's path in a table per span ("per": "span") or one for the whole
// motion, about kArcLengthSpanUnits method frames per span a table covers
// (a 1000-keyframe track whose knots run to 1000: 5.5 s on one core), at most
// kArcLengthTableUnits a table (limits::kArcLengthMaxCells). `pita animate`
// builds them once for a "motion" animation and once per frame for a
// "pattern" one (animate/output.hpp). 0 without arc-length timing.
inline constexpr double kArcLengthSpanUnits = 3.3e4;
inline constexpr double kArcLengthTableUnits = 2e6;
struct MotionBuildCost {
  double units = 0.0;
  std::string pointer;  // the "timing" that costs most ("/timing", "/panels/2/timing")
};
MotionBuildCost motion_build_cost(const scene::Scene& scene);

// Throws RenderError when `cost` exceeds factor x kDefaultBudgetUnits, naming
// the pointer whose parts add up to the most units.
void check_budget(const scene::Scene& scene, const FigureCost& cost, double factor = 1.0);

// Throws RenderError at /canvas when a PNG of the canvas at `scale` has more
// than factor x kDefaultBudgetPixels pixels.
void check_pixel_budget(const scene::Scene& scene, double scale, double factor = 1.0);

struct Figure;

// The length of every stroked line of the laid-out figure in canvas pixels
// (each segment counted at most as long as its panel's diagonal, since panels
// clip), by layer pointer.
std::vector<std::pair<std::string, double>> ink_by_layer(const Figure& figure);

// Throws RenderError naming the layer with the most ink when a PNG at `scale`
// would stroke more than factor x kDefaultBudgetInk pixels of lines.
void check_ink_budget(const scene::Scene& scene, const Figure& figure, double scale, double factor = 1.0);

}  // namespace pita::render
