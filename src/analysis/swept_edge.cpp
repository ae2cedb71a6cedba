#include "analysis/swept_edge.hpp"

#include <algorithm>
#include <cmath>

namespace pita::analysis {

namespace {

// Steps of the bisection that ends a run of the envelope where s leaves
// [0, 1]: 60 halvings reach the time's rounding for any span.
constexpr int kCrossingSteps = 60;

Eigen::Vector2d edge_point(const Edge& edge, double s) { return edge.from + s * (edge.to - edge.from); }

bool on_edge(const std::optional<double>& s) { return s && *s >= 0.0 && *s <= 1.0; }

std::optional<double> grazing_at(const PoseTrack& motion, const Edge& edge, double t) {
  return grazing_parameter(motion.pose(t), motion.velocity(t), edge);
}

Eigen::Vector2d grazing_point_at(const PoseTrack& motion, const Edge& edge, double t, double s) {
  return apply(motion.pose(t), edge_point(edge, s));
}

// The time between `inside` (s on the edge) and `outside` (s defined, off the
// edge) where s crosses the bound it leaves by, with that bound's point.
std::optional<Eigen::Vector2d> crossing(const PoseTrack& motion, const Edge& edge, double inside, double outside,
                                        double s_outside) {
  const double bound = s_outside > 1.0 ? 1.0 : 0.0;
  for (int step = 0; step < kCrossingSteps; ++step) {
    const double middle = 0.5 * (inside + outside);
    const std::optional<double> s = grazing_at(motion, edge, middle);
    if (!s) return std::nullopt;  // no grazing point on the way: end at the last sample
    ((*s - bound) * (s_outside - bound) > 0.0 ? outside : inside) = middle;
  }
  return grazing_point_at(motion, edge, inside, bound);
}

}  // namespace

GrazingTrace trace_grazing(const PoseTrack& motion, const Edge& edge, double from, double to, int samples) {
  GrazingTrace trace;
  const int n = std::max(samples, 2);
  for (int i = 0; i < n; ++i) {
    const double t = i == n - 1 ? to : from + (to - from) * i / (n - 1);
    trace.times.push_back(t);
    trace.s.push_back(grazing_at(motion, edge, t));
  }
  return trace;
}

GrazingRange grazing_range(const GrazingTrace& trace) {
  GrazingRange range;
  range.total = static_cast<int>(trace.s.size());
  for (const std::optional<double>& s : trace.s) {
    if (!s) continue;
    range.min = range.defined == 0 ? *s : std::min(range.min, *s);
    range.max = range.defined == 0 ? *s : std::max(range.max, *s);
    ++range.defined;
  }
  return range;
}

std::vector<std::vector<Eigen::Vector2d>> envelope(const PoseTrack& motion, const Edge& edge,
                                                   const GrazingTrace& trace) {
  std::vector<std::vector<Eigen::Vector2d>> runs;
  std::vector<Eigen::Vector2d> run;
  const std::size_t n = trace.times.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!on_edge(trace.s[i])) continue;
    // Entering: from a defined s off the edge, start at the crossing.
    if (run.empty() && i > 0 && trace.s[i - 1]) {
      if (auto start = crossing(motion, edge, trace.times[i], trace.times[i - 1], *trace.s[i - 1])) {
        run.push_back(*start);
      }
    }
    run.push_back(grazing_point_at(motion, edge, trace.times[i], *trace.s[i]));
    const bool last = i + 1 == n || !on_edge(trace.s[i + 1]);
    if (!last) continue;
    if (i + 1 < n && trace.s[i + 1]) {
      if (auto end = crossing(motion, edge, trace.times[i], trace.times[i + 1], *trace.s[i + 1])) {
        run.push_back(*end);
      }
    }
    runs.push_back(std::move(run));
    run.clear();
  }
  return runs;
}

std::vector<Eigen::Vector2d> edge_point_path(const PoseTrack& motion, const Edge& edge, double s,
                                             const std::vector<double>& times) {
  std::vector<Eigen::Vector2d> path;
  path.reserve(times.size());
  for (const double t : times) path.push_back(apply(motion.pose(t), edge_point(edge, s)));
  return path;
}

}  // namespace pita::analysis
