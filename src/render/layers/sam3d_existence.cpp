// The "sam3d-existence" layer (SAM Sec. 5.2): the largest safe perturbation
// against the angle, beside the paper's bounds.
#include "render/layers/sam3d_existence.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "render/layer_cost.hpp"
#include "render/layers/pose_layers.hpp"

namespace pita::render {

Drawing sam3d_existence_drawing(const scene::Sam3dExistenceLayer& layer, const std::string& pointer) {
  analysis::Sam3dExistenceOptions options;
  options.subdivisions = layer.subdivisions;
  options.p_step = layer.step;
  const analysis::SafeCurve curve = analysis::largest_safe_perturbation_curve(layer.steps, options);
  return sam3d_existence_drawing(layer, curve, pointer);
}

namespace {

// Shapes of the layer at `pointer`, added in drawing order.
struct Sam3dPlot {
  Drawing& drawing;
  const std::string& pointer;
  void add(Shape shape) { drawing.items.push_back({pointer, -1, std::move(shape)}); }
};

const Color kSam3dText{0.1, 0.1, 0.1, 1.0};

// The curve as a staircase: over [theta_k, theta_k+1) the bound is that of
// the angles up to theta_k.
std::vector<Point> safe_staircase(const analysis::SafeCurve& curve, double h) {
  std::vector<Point> stairs;
  for (std::size_t k = 0; k < curve.thetas.size(); ++k) {
    const double y = h * curve.largest_p[k];
    stairs.emplace_back(curve.thetas[k], y);
    const double next = k + 1 < curve.thetas.size() ? curve.thetas[k + 1] : kPi;
    if (next > curve.thetas[k]) stairs.emplace_back(next, y);
  }
  return stairs;
}

// "2 pi/3" as "2π/3" (built forwards: GCC 12 warns, falsely, of an overflow
// in std::string::replace here at -O3).
std::string angle_with_pi(const std::string& given) {
  std::string angle;
  for (std::size_t i = 0; i < given.size();) {
    const std::size_t pi = given.compare(i, 3, " pi") == 0 ? 3 : given.compare(i, 2, "pi") == 0 ? 2 : 0;
    if (pi > 0) {
      angle += "\u03c0";
      i += pi;
    } else {
      angle += given[i++];
    }
  }
  return angle;
}

// The paper's claims, "theta < T: p < P", as the corner of the box they
// claim safe, beside the curve's value at T (the angles up to T).
void add_paper_claims(Sam3dPlot& plot, const scene::Sam3dExistenceLayer& layer, const analysis::SafeCurve& curve,
                      std::span<const analysis::PaperExistenceBound> bounds, double h) {
  for (const auto& bound : bounds) {
    double ours = curve.largest_p.empty() ? 0.0 : curve.largest_p.front();
    for (std::size_t k = 0; k < curve.thetas.size() && curve.thetas[k] <= bound.theta + 1e-9; ++k) {
      ours = curve.largest_p[k];
    }
    plot.add(Polyline{{{0.0, h * bound.p}, {bound.theta, h * bound.p}, {bound.theta, 0.0}}, false, layer.paper_line});
    plot.add(Circle{{bound.theta, h * ours}, 0.035, layer.line, layer.line.color});
    const bool agrees = std::abs(ours - bound.p) < 0.5 * layer.step;
    plot.add(Label{fmt::format("\u03b8 < {}: paper p < {:.2f}, ours {:.2f}{}", angle_with_pi(bound.theta_text), bound.p,
                               ours, agrees ? "" : " (differs)"),
                   {bound.theta + 0.06, h * bound.p + 0.12},
                   12.0,
                   agrees ? kSam3dText : layer.paper_line.color});
  }
}

// The frame, its ticks and names, and what is what (right of the middle,
// between the claims).
void add_frame(Sam3dPlot& plot, const scene::Sam3dExistenceLayer& layer, int tenths, double h) {
  const double top = 0.1 * tenths * h;
  const LineStyle frame{Color{0.3, 0.3, 0.3, 1.0}, 0.8, 1.0, {}};
  plot.add(Polyline{{{0.0, 0.0}, {kPi, 0.0}, {kPi, top}, {0.0, top}}, true, frame});
  const std::array<std::pair<double, const char*>, 5> ticks = {
      {{0.0, "0"}, {kPi / 4.0, "\u03c0/4"}, {kPi / 2.0, "\u03c0/2"}, {3.0 * kPi / 4.0, "3\u03c0/4"}, {kPi, "\u03c0"}}};
  for (const auto& [x, name] : ticks) plot.add(Label{name, {x - 0.05, -0.18}, 12.0, kSam3dText});
  plot.add(Label{"\u03b8 (largest rotation angle)", {kPi / 2.0 - 0.7, -0.42}, 12.0, kSam3dText});
  for (int i = 0; i < tenths; i += 1) {
    plot.add(Label{fmt::format("{:.1f}", 0.1 * i), {-0.32, 0.1 * i * h}, 12.0, kSam3dText});
  }
  plot.add(Label{"p", {-0.32, top + 0.15}, 12.0, kSam3dText});
  plot.add(Label{"\u2014 ours: every rotation up to \u03b8 keeps a SAM below it",
                 {0.45 * kPi, top - 0.7},
                 11.0,
                 layer.line.color});
  if (layer.paper) {
    plot.add(Label{"- - the paper's claims, \u03b8 < T: p < P", {0.45 * kPi, top - 0.9}, 11.0, layer.paper_line.color});
  }
}

}  // namespace

Drawing sam3d_existence_drawing(const scene::Sam3dExistenceLayer& layer, const analysis::SafeCurve& curve,
                                const std::string& pointer) {
  Drawing drawing;
  Sam3dPlot plot{drawing, pointer};
  const double h = scene::kSafeCurveScale;
  const std::span<const analysis::PaperExistenceBound> bounds = analysis::paper_existence_bounds();
  // The plot's height: the highest p shown, rounded up to a tenth, plus one.
  double highest = 0.0;
  for (const double p : curve.largest_p) highest = std::max(highest, p);
  if (layer.paper) {
    for (const auto& bound : bounds) highest = std::max(highest, bound.p);
  }
  const int tenths = static_cast<int>(std::ceil(highest * 10.0 - 1e-9)) + 1;
  const double top = 0.1 * tenths * h;

  // The grid, the region under the staircase, the staircase.
  const Color grid_color{0.85, 0.85, 0.85, 1.0};
  const LineStyle grid{grid_color, 0.6, 1.0, {}};
  for (int i = 1; i < tenths; ++i) plot.add(Polyline{{{0.0, 0.1 * i * h}, {kPi, 0.1 * i * h}}, false, grid});
  for (const double x : {kPi / 4.0, kPi / 2.0, 3.0 * kPi / 4.0}) plot.add(Polyline{{{x, 0.0}, {x, top}}, false, grid});
  const std::vector<Point> stairs = safe_staircase(curve, h);
  if (layer.fill && !stairs.empty()) {
    std::vector<Point> region = stairs;
    region.emplace_back(stairs.back().real(), 0.0);
    region.emplace_back(0.0, 0.0);
    plot.add(FilledPath{{std::move(region)}, *layer.fill, layer.fill_opacity, std::nullopt});
  }
  plot.add(Polyline{stairs, false, layer.line});
  if (layer.paper) add_paper_claims(plot, layer, curve, bounds, h);
  add_frame(plot, layer, tenths, h);
  return drawing;
}

void draw_pose_layer(PosePanel<Affine2>& panel, const scene::Sam3dExistenceLayer& layer) {
  panel.append(sam3d_existence_drawing(layer, panel.layer()).items);
}

// Its cost (render/layer_cost.hpp).
namespace detail {

// Matrices (angle x axis x perturbation) per unit of work, measured: the
// default layer (49 angles x 81 axes x 3^9) takes 0.85 s on two cores, about
// 1.7 core-seconds or 680 000 units (docs/explanation/performance.md "Performance"); the searches of p
// along the curve are included.
constexpr double kSafeCurveMatricesPerUnit = 110.0;

void LayerCost::operator()(const scene::Sam3dExistenceLayer& l) {
  const double axes = 5.0 * std::pow(4.0, l.subdivisions) + 1.0;  // one per antipodal pair of vertices
  add(layer_ + "/steps",
      fmt::format("{} angles x {:.0f} axes x 3^9 perturbations of the 3D existence experiment", l.steps + 1, axes),
      (l.steps + 1.0) * axes * 19683.0 / kSafeCurveMatricesPerUnit + (2.0 * l.steps + 64.0) * kShapeUnits);
}

}  // namespace detail

}  // namespace pita::render
