// The "existence" layer (SAM Fig. 6): where a SAM between two poses exists.
#include "render/layers/existence.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "analysis/existence.hpp"
#include "render/layer_cost.hpp"
#include "render/layers/pose_layers.hpp"

namespace pita::render {

Drawing existence_drawing(const scene::ExistenceLayer& layer, const std::string& pointer) {
  Drawing drawing;
  const double h = kExistenceHeight;
  const auto push = [&](int index, Shape shape) { drawing.items.push_back({pointer, index, std::move(shape)}); };
  const auto rectangle = [h](double a0, double a1, double s0, double s1) {
    return std::vector<Point>{{a0, h * s0}, {a1, h * s0}, {a1, h * s1}, {a0, h * s1}};
  };
  if (layer.exists_fill) {
    push(-1, FilledPath{{rectangle(-kPi, kPi, 0.0, 1.0)}, *layer.exists_fill, 1.0, std::nullopt});
  }
  // The cells without a SAM (analysis/existence.hpp), row by row, runs of
  // neighbours merged.
  FilledPath bad{{}, layer.fill, 1.0, std::nullopt};
  const analysis::ExistenceGrid grid = analysis::classify_existence(layer.columns, layer.rows);
  const double da = 2.0 * kPi / layer.columns, ds = 1.0 / layer.rows;
  for (int j = 0; j < layer.rows; ++j) {
    int run_start = -1;
    for (int i = 0; i <= layer.columns; ++i) {
      const bool no_sam = i < layer.columns && grid.no_sam[static_cast<std::size_t>(j) * layer.columns + i];
      if (no_sam && run_start < 0) run_start = i;
      if (!no_sam && run_start >= 0) {
        bad.contours.push_back(rectangle(-kPi + run_start * da, -kPi + i * da, j * ds, (j + 1) * ds));
        run_start = -1;
      }
    }
  }
  push(-1, std::move(bad));
  // SAM Eq. 4: |a| = acos(-2 s / (s^2 + 1)), s in (0, 1].
  for (const double side : {-1.0, 1.0}) {
    std::vector<Point> curve;
    for (int k = 0; k <= 400; ++k) {
      const double s = k / 400.0;
      curve.push_back({side * analysis::existence_boundary(s), h * s});
    }
    push(-1, Polyline{std::move(curve), false, layer.boundary});
  }
  // The trapezoid |a| < (1 + s) pi / 2.
  push(-1, Polyline{{{-kPi / 2.0, 0.0}, {kPi / 2.0, 0.0}, {kPi, h}, {-kPi, h}}, true, layer.trapezoid});
  // The frame of the plot and its ticks.
  const LineStyle frame{Color{0.3, 0.3, 0.3, 1.0}, 0.8, 1.0, {}};
  push(-1, Polyline{rectangle(-kPi, kPi, 0.0, 1.0), true, frame});
  const Color text{0.1, 0.1, 0.1, 1.0};
  push(-1, Label{"a = -\u03c0", {-kPi, -0.12 * h}, 12.0, text});
  push(-1, Label{"0", {0.0, -0.12 * h}, 12.0, text});
  push(-1, Label{"\u03c0", {kPi, -0.12 * h}, 12.0, text});
  push(-1, Label{"s = 0", {-kPi - 0.45, 0.0}, 12.0, text});
  push(-1, Label{"s = 1", {-kPi - 0.45, h}, 12.0, text});
  return drawing;
}

void draw_pose_layer(PosePanel<Affine2>& panel, const scene::ExistenceLayer& layer) {
  panel.append(existence_drawing(layer, panel.layer()).items);
}

// Its cost (render/layer_cost.hpp).
namespace detail {

void LayerCost::operator()(const scene::ExistenceLayer& l) {
  // Each cell is one classification by EAR (about 0.1 us), drawn in runs.
  add(layer_ + "/columns", fmt::format("{} x {} cells of an existence map", l.columns, l.rows),
      static_cast<double>(l.columns) * l.rows / 8.0 + 64 * kShapeUnits);
}

}  // namespace detail

}  // namespace pita::render
