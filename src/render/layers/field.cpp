// "field" (SAM Fig. 8, SAM Eq. 7, docs/paper-notes.md N47): the stationary
// velocity field of the panel's SAM at the nodes of a grid, its integral
// curves through every `curves`-th node, the fixed point, and the measured
// agreement of the curves with the field.
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "analysis/velocity_field.hpp"
#include "core/affine_power.hpp"
#include "core/sam_velocity_field.hpp"
#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"
#include "render/layer_cost.hpp"
#include "render/layers/pose_layers.hpp"

namespace pita::render {

namespace {

// Points per integral curve.
constexpr int kFieldCurveSamples = 257;

Point field_point(const Eigen::Vector2d& x) { return Point{x.x(), x.y()}; }

// The label that says how closely the curves follow the field: every curve at
// 33 times of its range, its velocity by finite differences against the field
// at the same point (analysis/velocity_field.hpp).
std::string field_check_text(const SamVelocityField& field, const std::vector<Eigen::Vector2d>& starts,
                             const std::vector<double>& us) {
  std::vector<double> checked;
  for (std::size_t k = 0; k < us.size(); k += us.size() / 32) checked.push_back(us[k]);
  const analysis::FieldCheck check = analysis::check_integral_curves(field, starts, checked);
  // Below 1e-10 the digits are rounding noise that varies between compilers,
  // so the figure prints the bound (golden-stable).
  const std::string deviation =
      check.deviation < 1e-10 ? std::string("< 1e-10") : fmt::format("= {:.1e}", check.deviation);
  return fmt::format("stationary field: |x'(u) - v(x(u))| / max|v| {} on {} curve points", deviation, check.samples);
}

}  // namespace

void draw_pose_layer(PosePanel<Affine2>& panel, const scene::FieldLayer& layer) {
  const auto& keys = panel.keys();
  if (keys.method != PoseMethod::sam) {
    panel.fail(fmt::format("a field layer draws the stationary velocity field of a SAM; the panel's method is {}",
                           scene::method_id(panel.panel().keys)));
  }
  const double first = panel.motion().first(), last = panel.motion().last();
  std::optional<SamVelocityField> field;
  try {
    field.emplace(SamVelocityField::between(keys.poses.front().pose, keys.poses.back().pose));
  } catch (const NoRealLogarithm& error) {
    panel.fail(error.what());
  }
  // u = (t - first) / (last - first): the field per unit of u, as "velocities".
  const auto node = [&](int i, int j) {
    const Point low = layer.box.min, high = layer.box.max;
    return Eigen::Vector2d(low.real() + (high.real() - low.real()) * i / (layer.columns - 1),
                           low.imag() + (high.imag() - low.imag()) * j / (layer.rows - 1));
  };
  for (int j = 0; j < layer.rows; ++j) {
    for (int i = 0; i < layer.columns; ++i) {
      const Eigen::Vector2d x = node(i, j);
      panel.push(-1, ArrowShape{field_point(x), field_point(x + layer.scale * field->at(x)), layer.line});
    }
  }
  std::vector<Eigen::Vector2d> starts;
  if (layer.curves > 0) {
    for (int j = 0; j < layer.rows; j += layer.curves) {
      for (int i = 0; i < layer.columns; i += layer.curves) starts.push_back(node(i, j));
    }
  }
  const double from = layer.range ? layer.range->from : first, to = layer.range ? layer.range->to : last;
  std::vector<double> us;
  for (const double t : motion::uniform_times(from, to, kFieldCurveSamples)) us.push_back((t - first) / (last - first));
  // Each integral curve, drawn where it runs inside the field's box (the
  // figure shows the field there; outside, the curves would run off the panel).
  const auto in_box = [&layer](Point p) {
    return p.real() >= layer.box.min.real() && p.real() <= layer.box.max.real() && p.imag() >= layer.box.min.imag() &&
           p.imag() <= layer.box.max.imag();
  };
  for (const Eigen::Vector2d& x0 : starts) {
    std::vector<Point> run;
    const auto flush = [&] {
      if (run.size() >= 2) panel.push(-1, Polyline{run, false, layer.curve});
      run.clear();
    };
    for (const double u : us) {
      const Point p = field_point(field->trajectory(x0, u));
      if (in_box(p)) {
        run.push_back(p);
      } else {
        flush();
      }
    }
    flush();
  }
  const double side =
      std::min(layer.box.max.real() - layer.box.min.real(), layer.box.max.imag() - layer.box.min.imag());
  if (layer.fixed_point && field->fixed_point()) {
    const Point q = field_point(*field->fixed_point());
    panel.push(-1, Circle{q, 0.012 * side, LineStyle{Color{0, 0, 0, 1}, 1.0, 1.0, {}}, Color{0, 0, 0, 1}});
    // Beside the fixed point, off the integral curves through it.
    panel.push(-1, Label{"q", q + Point{0.02 * side, 0.02 * side}, 12.0, Color{0, 0, 0, 1}, true});
  }
  if (panel.selection() == nullptr && !starts.empty()) {
    panel.push(
        -1, Label{field_check_text(*field, starts, us), Point{layer.box.min.real(), layer.box.min.imag() - 0.17 * side},
                  13.0, Color{0.1, 0.1, 0.1, 1.0}});
  }
}

// Its cost (render/layer_cost.hpp).
namespace detail {

void LayerCost::operator()(const scene::FieldLayer& l) {
  // An arrow per node; per curve 257 powers, and 33 x 5 more for the check.
  const double nodes = static_cast<double>(l.columns) * l.rows;
  const double curves = l.curves > 0 ? std::ceil(l.columns / static_cast<double>(l.curves)) *
                                           std::ceil(l.rows / static_cast<double>(l.curves))
                                     : 0.0;
  add(layer_ + "/columns", fmt::format("{} x {} arrows of a field", l.columns, l.rows),
      nodes * (kShapeUnits + 2) + curves * (kShapeUnits + 257 + 33 * 5));
}

}  // namespace detail

}  // namespace pita::render
