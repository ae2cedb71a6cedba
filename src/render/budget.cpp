#include "render/budget.hpp"

#include "analysis/audit_configs.hpp"

#include "motion/moving_keyframes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <variant>

#include <fmt/format.h>

#include "analysis/measure.hpp"
#include "core/overloaded.hpp"
#include "analysis/swept_edge.hpp"
#include "motion/scene_motion.hpp"
#include "render/figure.hpp"
#include "render/panel_drawing.hpp"
#include "render/spiral.hpp"

namespace pita::render {

namespace {

// A layer's estimate: overloads for every layer type of both scene kinds, so
// that a new layer type without a cost does not compile.
// "sam3d-existence": matrices (angle x axis x perturbation) per unit of work,
// measured: the default layer (49 angles x 81 axes x 3^9) takes 0.85 s on two
// cores, about 1.7 core-seconds or 680 000 units (README "Performance"); the
// searches of p along the curve are included.
constexpr double kSafeCurveMatricesPerUnit = 110.0;

class LayerCost {
 public:
  LayerCost(const scene::Scene& scene, const scene::Panel& panel, std::string layer,
            FigureCost& cost)
      : scene_(scene), panel_(panel), layer_(std::move(layer)), cost_(cost) {}

  // ------------------------------------------------------------ arrow layers
  void operator()(const scene::PatternLayer& l) {
    double per_frame = kShapeUnits + 2;
    if (l.coils) {
      // A coil per frame: its turns bounded by the keyframes' largest winding,
      // scaled by how far the range reaches beyond the knots, plus one turn.
      double w = 0.0;
      for (const Keyframe& key : keyframes()) w = std::max(w, std::abs(key.arrow.w));
      const double span = keyframes().empty() ? 0.0 : keyframes().back().t - keyframes().front().t;
      const double reach =
          l.range && span > 0.0 ? std::max(1.0, (l.range->to - l.range->from) / span) : 1.0;
      const double turns = w * reach / (2.0 * std::numbers::pi) + 1.0;
      per_frame += kShapeUnits + std::min(turns * kSpiralPointsPerTurn + 9.0, static_cast<double>(kMaxSpiralPoints));
    }
    if (!l.times.empty()) {  // exactly these frames, not samples over a range
      add(layer_ + "/times", fmt::format("{} frames of a pattern", l.times.size()),
          static_cast<double>(l.times.size()) * (per_frame + motion::frame_cost(panel_) - 1.0));
      return;
    }
    frames(l.samples, "a pattern", per_frame);
  }
  void operator()(const scene::StrokeLayer& l) { frames(l.samples, "a stroke", kShapeUnits + 4); }
  void operator()(const scene::DiscrepancyLayer& l) {
    frames(l.samples, "discrepancy circles", kShapeUnits + 8);
  }
  void operator()(const scene::BannerLayer& l) {
    // The glyph outlines, split into short edges, then the strip's quads.
    add(layer_ + "/text", fmt::format("{} characters of a banner", l.text.size()),
        400.0 * static_cast<double>(l.text.size()));
    frames(l.samples, "a banner's strip", 4);
  }
  void operator()(const scene::KeyframesLayer&) {
    double units = 0.0;
    for (const Keyframe& key : keyframes()) {
      const double turns = std::abs(key.arrow.w) / (2.0 * std::numbers::pi);
      units += 4 * kShapeUnits +
               std::min(turns * kSpiralPointsPerTurn + 9.0, static_cast<double>(kMaxSpiralPoints));
    }
    add(layer_, "keyframe arrows and winding spirals", units);
  }
  void operator()(const scene::TrajectoryLayer& l) {
    add(layer_ + "/samples", fmt::format("{} points of a trajectory", l.samples),
        kShapeUnits + l.samples * motion::frame_cost(panel_));
  }
  void operator()(const scene::PointTrajectoryLayer& l) {
    // The Neville-type curves blend n(n - 1)/2 times per point.
    const auto* given = std::get_if<scene::PointKeys>(&panel_.keys);
    const double n = given != nullptr ? static_cast<double>(given->points.size()) : 0.0;
    const double per_point = l.curve == PointCurve::pita ? motion::frame_cost(panel_) : 1.0 + n * (n - 1.0) / 2.0;
    add(layer_ + "/samples", fmt::format("{} points of a point trajectory", l.samples),
        kShapeUnits + l.samples * per_point + (l.dots ? n * kShapeUnits : 0.0));
  }
  void operator()(const scene::LabelLayer& l) {
    add(layer_, "a label", kShapeUnits + static_cast<double>(l.text.size()));
  }
  void operator()(const scene::LegendLayer&) { add(layer_, "a legend", 8 * kShapeUnits); }
  void operator()(const scene::MeasuresLayer&) {
    add(layer_, "the measures of the motion", 8 * kShapeUnits + analysis::measure_cost(panel_));
  }
  void operator()(const scene::HandleLayer&) { add(layer_, "the handle and its shapes", kShapeUnits + shapes_units()); }
  void operator()(const scene::PropertyTableLayer& l) {
    // About 10 units (27 us) per property, method and configuration, crafted
    // ones included (pita_bench BM_Audit/1: about 1 s of CPU for 14 x 13 x 208).
    const double methods = l.methods.empty() ? 14.0 : static_cast<double>(l.methods.size());
    add(layer_ + "/configs", fmt::format("{} configurations of a property table", l.configs),
        10.0 * 13.0 * methods * (l.configs + static_cast<double>(analysis::crafted_configs().size())));
  }
  // Each frame evaluates a stencil of five or six more frames (frame_derivatives).
  void operator()(const scene::VectorsLayer& l) { frames(l.samples, "vectors", 7 * kShapeUnits); }
  void operator()(const scene::FixedPointsLayer& l) { frames(l.samples, "fixed-point segments", 7 * kShapeUnits); }
  void operator()(const scene::GuessesLayer& l) {
    add(layer_ + "/guesses", fmt::format("{} guessed arrows", l.guesses.size()),
        static_cast<double>(l.guesses.size()) * (2 * kShapeUnits + motion::frame_cost(panel_)));
  }
  void operator()(const scene::CompareLayer& l) { frames(l.samples, "a compared pattern", kShapeUnits + 1); }
  void operator()(const scene::PlotLayer& l) {
    // An area plot builds and samples one motion per method.
    const double curves = l.of == scene::PlotOf::area ? static_cast<double>(std::max<std::size_t>(1, l.methods.size())) : 1.0;
    const double per_point = l.of == scene::PlotOf::area ? motion::frame_cost(panel_) : 1.0;
    add(layer_ + "/samples", fmt::format("{} points of a plot", l.samples),
        8 * kShapeUnits + curves * l.samples * per_point);
    if (l.marks) frames(std::nullopt, "a plot's marks", curves * (kShapeUnits + 8));
  }

  // ------------------------------------------------------------- pose layers
  void operator()(const scene::ShapesLayer& l) {
    frames(l.samples, "shapes", shapes_units());
  }
  void operator()(const scene::VersusLayer& l) {
    if (!l.at.empty()) {
      add(layer_ + "/at", fmt::format("{} frames of compared shapes", l.at.size()),
          static_cast<double>(l.at.size()) * (shapes_units() + l.power));
      return;
    }
    frames(l.samples, "compared shapes", shapes_units() + l.power);
  }
  void operator()(const scene::PosesLayer& l) {
    // With "inserted", a four-point panel of the plane's last step adds n 2^(steps-1) poses.
    const auto [poses, inserted] = std::visit(
        overloaded{[&](const scene::PlanePoseKeys& given) {
                     const auto n = static_cast<double>(given.poses.size());
                     return std::pair(n, l.inserted && given.subdivisions > 0 ? std::ldexp(n, given.subdivisions - 1) : 0.0);
                   },
                   [](const scene::SpacePoseKeys& given) { return std::pair(static_cast<double>(given.poses.size()), 0.0); },
                   [](const scene::TrackMethod&) { return std::pair(0.0, 0.0); }},
        panel_.keys);
    add(layer_, "the shapes at the poses", (poses + inserted) * shapes_units());
  }
  void operator()(const scene::VelocitiesLayer& l) {
    frames(l.samples, "velocities", shape_points() * (kShapeUnits + 2));
  }
  void operator()(const scene::FieldLayer& l) {
    // An arrow per node; per curve 257 powers, and 33 x 5 more for the check.
    const double nodes = static_cast<double>(l.columns) * l.rows;
    const double curves = l.curves > 0 ? std::ceil(l.columns / static_cast<double>(l.curves)) *
                                             std::ceil(l.rows / static_cast<double>(l.curves))
                                       : 0.0;
    add(layer_ + "/columns", fmt::format("{} x {} arrows of a field", l.columns, l.rows),
        nodes * (kShapeUnits + 2) + curves * (kShapeUnits + 257 + 33 * 5));
  }
  void operator()(const scene::PathsLayer& l) {
    add(layer_ + "/samples", fmt::format("{} points of each vertex's path", l.samples),
        shape_points() * (kShapeUnits + l.samples));
  }
  void operator()(const scene::PatchLayer& l) {
    add(layer_ + "/columns", fmt::format("{} x {} shapes of a patch", l.columns, l.rows),
        static_cast<double>(l.columns) * l.rows * shapes_units());
  }
  void operator()(const scene::AraLayer& l) {
    // core/steadiness.hpp: at each of 64 times and each grid point, two poses
    // and two velocities, each about 1/16 of a unit (measured: ten panels of
    // 100 x 100 points, 25.6 million evaluations, take 4.2 s, ~0.16 us each).
    add(layer_ + "/grid", fmt::format("{} x {} points of an ARA", l.grid, l.grid),
        static_cast<double>(l.grid) * l.grid * 64 * 4 / 16 + kShapeUnits);
  }
  void operator()(const scene::SweptLayer& l) {
    // The copies of the edge; the envelope and the paths of the ends and of
    // the grazing points, each a pose and a velocity per trace time, and the
    // bisections that end the envelope's runs (analysis/swept_edge.hpp).
    frames(l.samples, "copies of a swept edge", kShapeUnits + 2);
    add(layer_ + "/trace_samples", fmt::format("{} times of a swept edge's envelope and paths", l.trace_samples),
        static_cast<double>(l.trace_samples) * (4 + l.instants) + (l.instants + 4) * kShapeUnits +
            static_cast<double>(analysis::kMaxEnvelopeCrossings) * analysis::kCrossingSteps);
  }
  void operator()(const scene::ExistenceLayer& l) {
    // Each cell is one classification by EAR (about 0.1 us), drawn in runs.
    add(layer_ + "/columns", fmt::format("{} x {} cells of an existence map", l.columns, l.rows),
        static_cast<double>(l.columns) * l.rows / 8.0 + 64 * kShapeUnits);
  }
  void operator()(const scene::Sam3dExistenceLayer& l) {
    const double axes = 5.0 * std::pow(4.0, l.subdivisions) + 1.0;  // one per antipodal pair of vertices
    add(layer_ + "/steps",
        fmt::format("{} angles x {:.0f} axes x 3^9 perturbations of the 3D existence experiment", l.steps + 1, axes),
        (l.steps + 1.0) * axes * 19683.0 / kSafeCurveMatricesPerUnit + (2.0 * l.steps + 64.0) * kShapeUnits);
  }

 private:
  // A layer drawn at each of its frames: `per_frame` units each.
  void frames(const std::optional<int>& samples, const char* what, double per_frame) {
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

  // 3D scenes draw solids: a shape per face, each vertex of each face projected.
  double shape_points() const {
    double points = 0.0;
    if (in_space()) {
      for (const scene::Solid& solid : scene_.solids) {
        points += static_cast<double>(solid.vertices.size());
        for (const std::vector<int>& face : solid.faces) points += static_cast<double>(face.size());
      }
      return points;
    }
    for (const scene::ShapeOutline& shape : panel_.shapes) points += static_cast<double>(shape.points.size());
    return points;
  }
  double shapes_units() const {
    double shapes = static_cast<double>(panel_.shapes.size());
    if (in_space()) {
      shapes = 0.0;
      for (const scene::Solid& solid : scene_.solids) shapes += static_cast<double>(solid.faces.size());
    }
    return shapes * kShapeUnits + shape_points();
  }

  // The panel's keyframes (none for the other kinds, which draw no arrow layers).
  const std::vector<Keyframe>& keyframes() const {
    static const std::vector<Keyframe> kNone;
    const auto* given = std::get_if<scene::KeyframeKeys>(&panel_.keys);
    return given != nullptr ? given->keyframes : kNone;
  }
  bool in_space() const { return std::holds_alternative<scene::SpacePoseKeys>(panel_.keys); }

  void add(std::string pointer, std::string what, double units) {
    cost_.units += units;
    cost_.parts.push_back({std::move(pointer), layer_, std::move(what), units});
  }

  const scene::Scene& scene_;
  const scene::Panel& panel_;
  std::string layer_;
  FigureCost& cost_;
};

template <typename LayerType>
void add_layers(const scene::Scene& scene, const scene::Panel& panel,
                const std::optional<std::vector<LayerType>>& own,
                const std::vector<LayerType>& scene_layers, FigureCost& cost) {
  const std::vector<LayerType>& layers = own ? *own : scene_layers;
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const std::string pointer = (own ? panel.pointer : std::string()) + "/layers/" + std::to_string(i);
    std::visit(LayerCost(scene, panel, pointer, cost), layers[i]);
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
    const auto arrows = [&](const auto&) { add_layers(scene, panel, panel.layers, scene.layers, cost); };
    const auto poses = [&](const auto&) { add_layers(scene, panel, panel.pose_layers, scene.pose_layers, cost); };
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
    return *std::max_element(groups.begin(), groups.end(), [](const auto& a, const auto& b) {
      return a.second.first < b.second.first;
    });
  };
  const auto largest = [](const std::vector<const CostPart*>& parts) {
    return *std::max_element(parts.begin(), parts.end(),
                             [](const CostPart* a, const CostPart* b) { return a->units < b->units; });
  };
  std::string pointer, what;
  double units = 0.0;
  if (const auto [field, share] = group([](const CostPart& p) { return p.pointer; });
      share.first >= 0.5 * cost.units) {
    pointer = field;
    units = share.first;
    what = share.second.size() == 1 ? share.second.front()->what
                                    : fmt::format("{} in each of {} places",
                                                  share.second.front()->what, share.second.size());
  } else if (const auto [list, in_list] = group([](const CostPart& p) {
               return p.layer.substr(0, p.layer.rfind("/layers/")) + "/layers";
             });
             in_list.first >= 0.5 * cost.units) {
    pointer = list;
    units = in_list.first;
    what = fmt::format("{} layer drawings, the largest {}", in_list.second.size(),
                       largest(in_list.second)->what);
  } else {
    pointer = scene.panels.size() > 1 ? "/panels" : "";
    units = cost.units;
    what = fmt::format("{} panels, the largest part {}", scene.panels.size(),
                       largest(group([](const CostPart& p) { return p.pointer; }).second.second)->what);
  }
  throw RenderError(scene.path, pointer,
                    fmt::format("{}: the figure would draw about {} points, beyond the budget of "
                                "{} ({:.0f}% of it from here); lower this, or raise the budget "
                                "with `pita render --budget F` (F times the default)",
                                what, count_text(cost.units), count_text(budget),
                                100.0 * units / cost.units));
}

void check_pixel_budget(const scene::Scene& scene, double scale, double factor) {
  const double pixels = std::round(scene.canvas.width * scale) * std::round(scene.canvas.height * scale);
  const double budget = kDefaultBudgetPixels * factor;
  if (pixels <= budget) return;
  throw RenderError(scene.path, "/canvas",
                    fmt::format("a PNG of {} pixels ({}x{} at scale {}) is beyond the budget of {} "
                                "pixels; lower the scale, or raise the budget with `pita render "
                                "--budget F`",
                                count_text(pixels), scene.canvas.width, scene.canvas.height, scale,
                                count_text(budget)));
}

namespace {

// Canvas length of a polyline's segments, each at most `clip` long.
double clipped_length(const std::vector<Point>& points, bool closed, const ViewTransform& view,
                      double clip) {
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
  double operator()(const ArrowShape& s) const {
    return 2.0 * std::min(std::abs(s.to - s.from) * view.scale, clip);
  }
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
  const auto worst = std::max_element(layers.begin(), layers.end(),
                                      [](const auto& a, const auto& b) { return a.second < b.second; });
  throw RenderError(scene.path, worst->first,
                    fmt::format("the PNG would stroke about {} pixels of lines ({:.0f}% of them "
                                "drawn by this layer), beyond the budget of {}; lower the scale, "
                                "the samples or the shapes' sizes, or raise the budget with `pita "
                                "render --budget F`",
                                count_text(total), 100.0 * worst->second * scale / total,
                                count_text(budget)));
}

}  // namespace pita::render
