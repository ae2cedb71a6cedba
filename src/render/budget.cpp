#include "render/budget.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <variant>

#include <fmt/format.h>

#include "analysis/audit_configs.hpp"
#include "analysis/measure.hpp"
#include "analysis/swept_edge.hpp"
#include "core/overloaded.hpp"
#include "motion/moving_keyframes.hpp"
#include "motion/scene_motion.hpp"
#include "render/figure.hpp"
#include "render/layer_cost.hpp"
#include "render/panel_drawing.hpp"
#include "render/spiral.hpp"

namespace pita::render {

namespace detail {

// ------------------------------------------------- LayerCost's shared parts

void LayerCost::frames(const std::optional<int>& samples, const char* what, double per_frame) {
  const int n = samples.value_or(panel_.samples);
  std::string pointer = samples ? layer_ + "/samples" : panel_.samples_pointer;
  if (!samples && panel_.samples_pointer == "/samples" && n > scene::kMaxFigureSamples) {
    throw RenderError(scene_.path, "/samples",
                      fmt::format("{} frames for the figure's layers exceeds the figure limit of "
                                  "{} (the top-level \"samples\", up to {}, is also what `pita "
                                  "eval` prints: give the panels or layers their own \"samples\")",
                                  n, scene::kMaxFigureSamples, scene::kMaxSamples));
  }
  if (pointer.empty()) pointer = layer_;
  // A frame of a chained track evaluates its method several times
  // (motion::frame_cost); one unit is about one method frame.
  add(pointer, fmt::format("{} frames of {}", n, what), n * (per_frame + motion::frame_cost(panel_) - 1.0));
}

namespace {

// What one shape costs to draw: an outline, its points, once; a solid of a 3D
// scene, a shape per face, each vertex and each face's corners projected.
double drawn_shapes(const scene::ShapeOutline&) { return 1.0; }
double drawn_shapes(const scene::Solid& solid) { return static_cast<double>(solid.faces.size()); }
double drawn_points(const scene::ShapeOutline& shape) { return static_cast<double>(shape.points.size()); }
double drawn_points(const scene::Solid& solid) {
  double points = static_cast<double>(solid.vertices.size());
  for (const std::vector<int>& face : solid.faces) points += static_cast<double>(face.size());
  return points;
}

// The sum of `cost` over the shapes the panel draws.
template <class Cost>
double over_shapes(const scene::Panel& panel, Cost cost) {
  return std::visit(
      [&](const auto& figure) {
        double sum = 0.0;
        for (const auto& shape : figure.shapes) sum += cost(shape);
        return sum;
      },
      panel.figure);
}

}  // namespace

double LayerCost::shape_points() const {
  return over_shapes(panel_, [](const auto& shape) { return drawn_points(shape); });
}

// "camera": {"shadow": ...} in a 3D scene: a shape per solid, every face's corners again.
double LayerCost::shadow_units() const {
  const auto solids = [&](const scene::PosePanelFigure<Affine3>& figure) {
    double shadows = 0.0;
    if (!scene::figure_of<scene::SpacePoseKeys>(scene_).camera.shadow) return shadows;
    for (const scene::Solid& solid : figure.shapes) {
      shadows += kShapeUnits;
      for (const std::vector<int>& face : solid.faces) shadows += static_cast<double>(face.size());
    }
    return shadows;
  };
  return std::visit(overloaded{[](const scene::ArrowPanelFigure&) { return 0.0; },
                               [](const scene::PosePanelFigure<Affine2>&) { return 0.0; }, solids},
                    panel_.figure);
}

double LayerCost::shapes_units() const {
  const double shapes = over_shapes(panel_, [](const auto& shape) { return drawn_shapes(shape); });
  return shapes * kShapeUnits + shape_points() + shadow_units();
}

const std::vector<Keyframe>& LayerCost::keyframes() const {
  static const std::vector<Keyframe> kNone;
  const auto* given = std::get_if<scene::KeyframeKeys>(&panel_.keys);
  return given != nullptr ? given->keyframes : kNone;
}

}  // namespace detail

namespace {

template <typename LayerType>
void add_layers(const scene::Scene& scene, const scene::Panel& panel, FigureCost& cost) {
  const scene::LayersOf<LayerType> drawn = scene::layers_of<LayerType>(scene, panel);
  for (std::size_t i = 0; i < drawn.layers.size(); ++i) {
    std::visit(detail::LayerCost(scene, panel, drawn.pointer(i), cost), drawn.layers[i]);
  }
}

std::string count_text(double units) {
  if (units >= 1e9) return fmt::format("{:.3g} billion", units / 1e9);
  if (units >= 1e6) return fmt::format("{:.3g} million", units / 1e6);
  return fmt::format("{:.0f}", units);
}

}  // namespace

FigureCost estimate_cost(const scene::Scene& scene) {
  FigureCost cost;
  for (const scene::Panel& panel : scene.panels) {
    // The title and frame of each panel.
    cost.units += 8 * kShapeUnits;
    const auto arrows = [&](const auto&) { add_layers<scene::Layer>(scene, panel, cost); };
    const auto poses = [&](const auto&) { add_layers<scene::PoseLayer>(scene, panel, cost); };
    std::visit(overloaded{[&](const scene::KeyframeKeys& given) { arrows(given); },
                          [&](const scene::PointKeys& given) { arrows(given); },
                          [&](const scene::PlanePoseKeys& given) { poses(given); },
                          [&](const scene::SpacePoseKeys& given) { poses(given); }},
               panel.keys);
  }
  // Moving keyframes (Sec. 7.4): the static figure overlays the pattern at
  // each tau of the animation's "overlay".
  if (motion::has_moving_keyframes(scene) && scene.animation.overlay.size() > 1) {
    const double copies = static_cast<double>(scene.animation.overlay.size());
    cost.units *= copies;
    for (CostPart& part : cost.parts) part.units *= copies;
  }
  return cost;
}

MotionBuildCost motion_build_cost(const scene::Scene& scene) {
  MotionBuildCost cost;
  double most = 0.0;
  for (const scene::Panel& panel : scene.panels) {
    if (!panel.timing.arc_length) continue;
    const std::size_t knots =
        std::visit(overloaded{[](const scene::KeyframeKeys& given) { return given.keyframes.size(); },
                              [](const scene::PointKeys& given) { return given.points.size(); },
                              [](const scene::PlanePoseKeys& given) { return given.poses.size(); },
                              [](const scene::SpacePoseKeys& given) { return given.poses.size(); }},
                   panel.keys);
    const double spans = knots > 1 ? static_cast<double>(knots - 1) : 1.0;
    const double tables = panel.timing.per == WarpSpan::span ? spans : 1.0;
    const double units =
        tables * std::min(spans / tables * kArcLengthSpanUnits, kArcLengthTableUnits) * motion::frame_cost(panel);
    cost.units += units;
    if (units > most) {
      most = units;
      cost.pointer = panel.timing.pointer.empty() ? "/timing" : panel.timing.pointer;
    }
  }
  return cost;
}

void check_budget(const scene::Scene& scene, const FigureCost& cost, double factor) {
  const double budget = kDefaultBudgetUnits * factor;
  if (cost.units <= budget) return;
  // The field that dominates: the most specific pointer whose parts add up to
  // at least half the cost. A field first ("/layers/0/samples", or "/samples"
  // feeding every panel), else a list of layers ("/layers": 64 layers drawn in
  // each of 64 panels), else the panels.
  const auto group = [&](auto key_of) {
    std::map<std::string, std::pair<double, std::vector<const CostPart*>>> groups;
    for (const CostPart& part : cost.parts) {
      auto& [units, parts] = groups[key_of(part)];
      units += part.units;
      parts.push_back(&part);
    }
    return *std::max_element(groups.begin(), groups.end(),
                             [](const auto& a, const auto& b) { return a.second.first < b.second.first; });
  };
  const auto largest = [](const std::vector<const CostPart*>& parts) {
    return *std::max_element(parts.begin(), parts.end(),
                             [](const CostPart* a, const CostPart* b) { return a->units < b->units; });
  };
  std::string pointer, what;
  double units = 0.0;
  if (const auto [field, share] = group([](const CostPart& p) { return p.pointer; }); share.first >= 0.5 * cost.units) {
    pointer = field;
    units = share.first;
    what = share.second.size() == 1
               ? share.second.front()->what
               : fmt::format("{} in each of {} places", share.second.front()->what, share.second.size());
  } else if (const auto [list, in_list] =
                 group([](const CostPart& p) { return p.layer.substr(0, p.layer.rfind("/layers/")) + "/layers"; });
             in_list.first >= 0.5 * cost.units) {
    pointer = list;
    units = in_list.first;
    what = fmt::format("{} layer drawings, the largest {}", in_list.second.size(), largest(in_list.second)->what);
  } else {
    pointer = scene.panels.size() > 1 ? "/panels" : "";
    units = cost.units;
    what = fmt::format("{} panels, the largest part {}", scene.panels.size(),
                       largest(group([](const CostPart& p) { return p.pointer; }).second.second)->what);
  }
  throw RenderError(scene.path, pointer,
                    fmt::format("{}: the figure would draw about {} points, beyond the budget of "
                                "{} ({:.0f}% of it from here); lower this, or raise the budget "
                                "with --budget F of pita render or pita animate (F times the default)",
                                what, count_text(cost.units), count_text(budget), 100.0 * units / cost.units));
}

void check_pixel_budget(const scene::Scene& scene, double scale, double factor) {
  const double pixels = std::round(scene.canvas.width * scale) * std::round(scene.canvas.height * scale);
  const double budget = kDefaultBudgetPixels * factor;
  if (pixels <= budget) return;
  throw RenderError(
      scene.path, "/canvas",
      fmt::format("a PNG of {} pixels ({}x{} at scale {}) is beyond the budget of {} "
                  "pixels; lower the scale, or raise the budget with "
                  "--budget F of pita render or pita animate",
                  count_text(pixels), scene.canvas.width, scene.canvas.height, scale, count_text(budget)));
}

namespace {

// Canvas length of a polyline's segments, each at most `clip` long.
double clipped_length(const std::vector<Point>& points, bool closed, const ViewTransform& view, double clip) {
  double length = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    length += std::min(std::abs(points[i] - points[i - 1]) * view.scale, clip);
  }
  if (closed && points.size() > 2) length += std::min(std::abs(points.back() - points.front()) * view.scale, clip);
  return length;
}

struct Ink {
  const ViewTransform& view;
  double clip;
  double operator()(const Polyline& s) const { return clipped_length(s.points, s.closed, view, clip); }
  double operator()(const FilledPath& s) const {
    // A fill costs its area, at most the panel's; an outline its length.
    double length = clip;
    if (s.outline) {
      for (const auto& contour : s.contours) length += clipped_length(contour, true, view, clip);
    }
    return length;
  }
  double operator()(const Circle& s) const {
    return std::min(2.0 * std::numbers::pi * s.radius * view.scale, 4.0 * clip);
  }
  double operator()(const ArrowShape& s) const { return 2.0 * std::min(std::abs(s.to - s.from) * view.scale, clip); }
  double operator()(const Label&) const { return 0.0; }
  // An image costs like a fill: its area, at most the panel's.
  double operator()(const Image&) const { return clip; }
};

}  // namespace

std::vector<std::pair<std::string, double>> ink_by_layer(const Figure& figure) {
  std::map<std::string, double> ink;
  for (std::size_t i = 0; i < figure.drawings.size() && i < figure.placements.size(); ++i) {
    const PanelPlacement& placement = figure.placements[i];
    const double clip = std::hypot(placement.cell.width, placement.cell.height);
    for (const Item& item : figure.drawings[i].items) {
      ink[item.layer] += std::visit(Ink{placement.transform, clip}, item.shape);
    }
  }
  return {ink.begin(), ink.end()};
}

void check_ink_budget(const scene::Scene& scene, const Figure& figure, double scale, double factor) {
  const auto layers = ink_by_layer(figure);
  double total = 0.0;
  for (const auto& [layer, ink] : layers) total += ink * scale;
  const double budget = kDefaultBudgetInk * factor;
  if (total <= budget) return;
  const auto worst =
      std::max_element(layers.begin(), layers.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  throw RenderError(scene.path, worst->first,
                    fmt::format("the PNG would stroke about {} pixels of lines ({:.0f}% of them "
                                "drawn by this layer), beyond the budget of {}; lower the scale, "
                                "the samples or the shapes' sizes, or raise the budget with --budget F of "
                                "pita render or pita animate",
                                count_text(total), 100.0 * worst->second * scale / total, count_text(budget)));
}

}  // namespace pita::render
