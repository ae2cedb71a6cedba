// "swept" (SAM Fig. 10, Sec. 7.2, SAM Eq. 8): an edge swept by the panel's
// motion, the envelope of its grazing points and the paths of points grazing
// at a few instants (analysis/swept_edge.hpp), and what the grazing parameter
// does over the layer's range.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "analysis/swept_edge.hpp"
#include "core/grazing_point.hpp"
#include "core/limits.hpp"
#include "motion/scene_motion.hpp"
#include "render/layer_cost.hpp"
#include "render/layers/pose_layers.hpp"

namespace pita::render {

namespace {

std::string grazing_claim(const analysis::GrazingRange& range) {
  if (range.defined == 0) return fmt::format("no grazing point at any of {} times", range.total);
  const std::string none = range.defined < range.total
                               ? fmt::format(" (none at {} of {} times)", range.total - range.defined, range.total)
                               : "";
  if (range.spread() <= analysis::kConstantGrazingSpread) {
    // The spread itself is rounding noise, whose digits vary between compilers: only its bound is printed.
    return fmt::format("grazing parameter s = {:.5f} at all {} times (spread < {:.0e}): constant{}", range.min,
                       range.defined, analysis::kConstantGrazingSpread, none);
  }
  return fmt::format("grazing parameter s ranges from {:.5f} to {:.5f} over {} times: not constant{}", range.min,
                     range.max, range.defined, none);
}

Point swept_point(const Eigen::Vector2d& x) { return Point(x.x(), x.y()); }

std::vector<Point> swept_polyline(const std::vector<Eigen::Vector2d>& points) {
  std::vector<Point> out;
  out.reserve(points.size());
  for (const Eigen::Vector2d& x : points) out.push_back(swept_point(x));
  return out;
}

}  // namespace

void draw_pose_layer(PosePanel<Affine2>& panel, const scene::SweptLayer& layer) {
  const auto vector = [](Point p) { return Eigen::Vector2d(p.real(), p.imag()); };
  const Edge edge{vector(layer.edge[0]), vector(layer.edge[1])};
  const analysis::PoseTrack track{[&panel](double t) { return panel.pose_at(t); },
                                  [&panel](double t) { return panel.velocity_at(t); }};
  const double from = layer.range ? layer.range->from : panel.motion().first();
  const double to = layer.range ? layer.range->to : panel.motion().last();
  const analysis::GrazingTrace trace = analysis::trace_grazing(track, edge, from, to, layer.trace_samples);
  for (const Affine2& pose : {panel.pose_at(from), panel.pose_at(to)}) {
    if (!pose.L.allFinite() || !pose.b.allFinite()) panel.fail("the swept edge overflows");
  }
  // The size of the swept region, for the dots.
  std::vector<Point> ends[2];
  for (int k = 0; k < 2; ++k) ends[k] = swept_polyline(analysis::edge_point_path(track, edge, k, trace.times));
  Point low = ends[0].front(), high = low;
  for (const auto& path : ends) {
    for (const Point p : path) {
      low = {std::min(low.real(), p.real()), std::min(low.imag(), p.imag())};
      high = {std::max(high.real(), p.real()), std::max(high.imag(), p.imag())};
    }
  }
  const double dot = 0.008 * std::max(std::abs(high - low), limits::kTinyScale);
  if (layer.segments) {
    const std::vector<double> ts = panel.times(layer.samples, layer.range);
    for (std::size_t i = 0; i < ts.size(); ++i) {
      const Affine2 pose = panel.pose_at(ts[i]);
      panel.push(
          static_cast<int>(i),
          Polyline{{pita::apply(pose, layer.edge[0]), pita::apply(pose, layer.edge[1])}, false, *layer.segments});
    }
  }
  if (layer.ends) {
    for (auto& path : ends) panel.push(-1, Polyline{std::move(path), false, *layer.ends});
  }
  if (layer.envelope) {
    for (const auto& run : analysis::envelope(track, edge, trace)) {
      panel.push(-1, Polyline{swept_polyline(run), false, *layer.envelope});
    }
  }
  if (layer.grazing) {
    // The points grazing at instants (k + 1) / (n + 1) of the range, each
    // traced over the whole range, with a dot where it grazes.
    for (int k = 0; k < layer.instants; ++k) {
      const double t = from + (to - from) * (k + 1) / (layer.instants + 1);
      const std::optional<double> s = grazing_parameter(panel.pose_at(t), panel.velocity_at(t), edge);
      if (!s) continue;
      panel.push(
          k, Polyline{swept_polyline(analysis::edge_point_path(track, edge, *s, trace.times)), false, *layer.grazing});
      const Point at = pita::apply(panel.pose_at(t), swept_point(edge.from + *s * (edge.to - edge.from)));
      panel.push(k, Circle{at, dot, *layer.grazing, layer.grazing->color});
    }
  }
  if (layer.claim_at) {
    panel.push(-1, Label{grazing_claim(analysis::grazing_range(trace)), *layer.claim_at, layer.size, layer.color});
  }
}

// Its cost (render/layer_cost.hpp).
namespace detail {

void LayerCost::operator()(const scene::SweptLayer& l) {
  // The copies of the edge; the envelope and the paths of the ends and of
  // the grazing points, each a pose and a velocity per trace time, and the
  // bisections that end the envelope's runs (analysis/swept_edge.hpp).
  frames(l.samples, "copies of a swept edge", kShapeUnits + 2);
  add(layer_ + "/trace_samples", fmt::format("{} times of a swept edge's envelope and paths", l.trace_samples),
      static_cast<double>(l.trace_samples) * (4 + l.instants) + (l.instants + 4) * kShapeUnits +
          static_cast<double>(analysis::kMaxEnvelopeCrossings) * analysis::kCrossingSteps);
}

}  // namespace detail

}  // namespace pita::render
