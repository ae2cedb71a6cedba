#include "analysis/swept_edge.hpp"

#include <algorithm>
#include <cmath>

namespace pita::analysis {

namespace {

// How close to 0 or 1 the s found at the end of a bisection must be to be
// snapped to that bound: s is continuous there (it is on the edge on one
// side, and a pole lies beyond a crossing), so after kCrossingSteps halvings
// it is within rounding of the bound; otherwise s left the edge where the
// grazing point stops being defined, and the run ends at that s.
constexpr double kSnapToBound = 1e-6;

Eigen::Vector2d edge_point(const Edge& edge, double s) { return edge.from + s * (edge.to - edge.from); }

bool on_edge(const std::optional<double>& s) { return s && *s >= 0.0 && *s <= 1.0; }

std::optional<double> grazing_at(const PoseTrack& motion, const Edge& edge, double t) {
  return grazing_parameter(motion.pose(t), motion.velocity(t), edge);
}

Eigen::Vector2d grazing_point_at(const PoseTrack& motion, const Edge& edge, double t, double s) {
  return apply(motion.pose(t), edge_point(edge, s));
}

// Where the run leaves the edge between `inside` (s on the edge) and
// `outside` (s off it, or undefined): bisection on on_edge, then the grazing
// point at the last time inside.
Eigen::Vector2d crossing(const PoseTrack& motion, const Edge& edge, double inside, double outside, double s_inside) {
  for (int step = 0; step < kCrossingSteps; ++step) {
    const double middle = 0.5 * (inside + outside);
    const std::optional<double> s = grazing_at(motion, edge, middle);
    if (on_edge(s)) {
      inside = middle;
      s_inside = *s;
    } else {
      outside = middle;
    }
  }
  for (const double bound : {0.0, 1.0}) {
    if (std::abs(s_inside - bound) < kSnapToBound) s_inside = bound;
  }
  return grazing_point_at(motion, edge, inside, s_inside);
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
  int crossings = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!on_edge(trace.s[i])) continue;
    // Entering: from off the edge, start where the run enters.
    if (run.empty() && i > 0 && crossings < kMaxEnvelopeCrossings) {
      run.push_back(crossing(motion, edge, trace.times[i], trace.times[i - 1], *trace.s[i]));
      ++crossings;
    }
    run.push_back(grazing_point_at(motion, edge, trace.times[i], *trace.s[i]));
    const bool last = i + 1 == n || !on_edge(trace.s[i + 1]);
    if (!last) continue;
    if (i + 1 < n && crossings < kMaxEnvelopeCrossings) {
      run.push_back(crossing(motion, edge, trace.times[i], trace.times[i + 1], *trace.s[i]));
      ++crossings;
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
