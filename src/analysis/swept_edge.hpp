// The region swept by a moving edge (SAM paper Sec. 7.2, Fig. 10): the
// grazing point of SAM Eq. 8 (core/grazing_point.hpp) traced over time, the
// envelope it draws, and how far it moves along the edge. Under a SAM the
// grazing parameter is constant (its path is the envelope); under rARAP it
// is not, and a point grazing at one instant leaves the envelope at others.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/affine2.hpp"
#include "core/grazing_point.hpp"

namespace pita::analysis {

// A grazing parameter whose spread over a trace is at most this is reported
// as constant (the "swept" layer's claim). s comes from a quotient of
// products of the pose and its velocity, each good to a few ulps of its
// size; under a SAM the measured spread is ~1e-16 (tests), and 1e-12 leaves
// the margin of a badly scaled edge.
inline constexpr double kConstantGrazingSpread = 1e-12;

// A motion of poses: A(t) and dA/dt ({dL/dt, dc/dt}).
struct PoseTrack {
  std::function<Affine2(double)> pose;
  std::function<Affine2(double)> velocity;
};

// The grazing parameter s(t) at `samples` (>= 2) uniform times of [from, to];
// nullopt where the edge has no single grazing point.
struct GrazingTrace {
  std::vector<double> times;
  std::vector<std::optional<double>> s;
};
GrazingTrace trace_grazing(const PoseTrack& motion, const Edge& edge, double from, double to, int samples);

// The smallest and largest s of a trace, over the times where it is defined.
struct GrazingRange {
  int defined = 0;  // times with a grazing point
  int total = 0;    // times of the trace
  double min = 0.0;
  double max = 0.0;
  double spread() const { return max - min; }
};
GrazingRange grazing_range(const GrazingTrace& trace);

// Steps of the bisection that ends a run of the envelope between two trace
// times: 60 halvings reach the time's rounding for any span.
inline constexpr int kCrossingSteps = 60;
// At most this many run ends are refined by bisection (the others end at
// their last sample): the work stays bounded for any trace (render/budget.cpp
// counts kMaxEnvelopeCrossings x kCrossingSteps evaluations).
inline constexpr int kMaxEnvelopeCrossings = 64;

// The envelope: the grazing points A(t) x(s(t)) where s(t) is in [0, 1] (on
// the edge), one polyline per run of the trace's times. A run that leaves the
// edge between two samples is extended to where it leaves, found by
// bisection on "s is defined and on the edge" (so a pole of s, where the
// denominator of SAM Eq. 8 changes sign, is never taken for a crossing: s passes
// 0 or 1 continuously before it), the point's s snapped to the bound it
// reaches (docs/paper-notes.md N67). World coordinates.
std::vector<std::vector<Eigen::Vector2d>> envelope(const PoseTrack& motion, const Edge& edge,
                                                   const GrazingTrace& trace);

// The path of the edge's point x(s) = from + s (to - from) at `times`: for
// the s grazing at one instant, the green trajectory of Fig. 10.
std::vector<Eigen::Vector2d> edge_point_path(const PoseTrack& motion, const Edge& edge, double s,
                                             const std::vector<double>& times);

}  // namespace pita::analysis
