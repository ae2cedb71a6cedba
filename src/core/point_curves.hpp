// Point curves through n >= 4 timed points (PITA Sec. 7.6, Fig. 29;
// docs/paper-notes.md N34): the PITA-based curve of PITA Eq. 48-50 generalised to n
// points, and the curves Fig. 29 compares it to, the uniform and centripetal
// Neville interpolations and the log-spiral blend.
//
//   pita                 p(t) = (1 - s) X(t).p + s Y(t).q, s = (t - t_0)/(t_{n-1} - t_0),
//                        X and Y arrow tracks through the zero-turn edge arrows
//                        e_i = p_i p_{i+1}, X at knots t_0..t_{n-2}, Y at
//                        t_1..t_{n-1} (PITA Eq. 48-50).
//   neville-uniform      the polynomial of degree n - 1 through all points
//                        (Aitken-Neville recursion, Sec. 2.4, PITA Eq. 12-14) in a
//                        curve parameter u with u_i = i;
//   neville-centripetal  the same with u_{i+1} - u_i = |p_{i+1} - p_i|^{1/2};
//   log-spiral-blend     Neville's recursion with the log-spiral motion LS-
//                        (PITA Eq. 26) through each three consecutive points as its
//                        third level and linear blends above.
//
// Every curve passes through p_i at t_i and is defined for every real t
// (outside [t_0, t_{n-1}] it extrapolates).
#pragma once

#include <functional>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "core/arrow.hpp"
#include "core/keyframe.hpp"
#include "core/pitas/motion.hpp"
#include "core/point_motions.hpp"

namespace pita {

struct TimedPoint {
  double t = 0.0;  // knot
  Point p;
};

// Which curve through timed points (one table: name, title) — the only list
// of them.
enum class PointCurve { pita, neville_uniform, neville_centripetal, log_spiral_blend };

struct PointCurveInfo {
  PointCurve curve;
  std::string_view name;   // "pita", "neville-uniform", "neville-centripetal", "log-spiral-blend"
  std::string_view title;  // "PITA blend of two arrow tracks (PITA Eq. 48-50)"
};

// Every point curve, in display order.
std::span<const PointCurveInfo> all_point_curves();
// The curve of that exact name; nullptr if none.
const PointCurveInfo* find_point_curve(std::string_view name);
const PointCurveInfo& info(PointCurve curve);

// The arrow track a PITA curve is built from: an arrow motion through n >= 3
// timed keyframes (for n = 4 points, three keyframes: a PITA, PITA Eq. 48-49).
using ArrowTrackFactory = std::function<std::unique_ptr<Motion>(std::span<const Keyframe>)>;

// p(t), defined for every real t.
//
// pita (PITA Eq. 48-50 as docs/paper-notes.md N34 reads them). With the edge arrows
// e_i = zero_turn_arrow(p_i, p_{i+1}), i = 0..n-2,
//     X = track({(t_i, e_i)}),  Y = track({(t_{i+1}, e_i)}),
//     p(t) = (1 - s) X(t).p + s Y(t).q,   s = (t - t_0)/(t_{n-1} - t_0).
// PITA Eq. 50 prints (1 - t) X + t Y, mixing arrows with points; this reading passes
// through every point: at t_k (0 < k < n-1) X = e_k starts at p_k and
// Y = e_{k-1} ends at p_k; at t_0, s = 0 and X = e_0 starts at p_0; at
// t_{n-1}, s = 1 and Y = e_{n-2} ends at p_{n-1}. For n = 4 at knots 0, 1/3,
// 2/3, 1 with a PITA P_x as the track it is PITA Eq. 48-50 exactly. The first edge
// is a zero-turn arrow and each next one turns from the previous by the
// principal angle between them (in (-pi, pi]), so the windings depend on the
// shape alone and the curve is similarity-invariant with the track.
//
// neville-uniform, neville-centripetal. Scene time maps to the curve
// parameter piecewise linearly through (t_i, u_i), and beyond the end knots
// with the slopes of the end spans, so that the polynomial in u passes
// through p_i at t_i. The path (the image) is the polynomial's, smooth; in t
// the centripetal curve is only C0 at the knots, where the map's slope
// changes (the uniform one too unless the knots are evenly spaced, when
// u = (t - t_0)/h and the curve is the Lagrange polynomial in t: with the
// paper's even knots, P1's parabola, PITA Eq. 11-12, generalised to n points).
//
// log-spiral-blend. Level 3 entry j is LS(p_j, p_{j+1}, p_{j+2}) at t with
// knots t_j, t_{j+1}, t_{j+2} (PITA Eq. 26, point_motions.hpp); level L > 3 entry j,
// covering points j..j+L-1, is
//     E_L[j] = (1 - s) E_{L-1}[j] + s E_{L-1}[j+1],  s = (t - t_j)/(t_{j+L-1} - t_j)
// (the LERPs of PITA Eq. 12-14); p(t) = E_n[0]. For n = 4,
// p = (1 - s) LS(a, b, c)(t) + s LS(b, c, d)(t). A log spiral's points at
// evenly spaced knots are reproduced exactly (LS- is exact on them, and
// blends of equal values are equal). Every entry is evaluated at every t, far
// from its own three knots too: with very uneven knots LS-'s quadratic time
// map reaches |u| of 10 or more there, a spiral with ratio 0.2 per step is
// then 1e10 times the size of the points, and the blend weights, which vanish
// only at the knots, keep a share of it between them; the curve is then huge
// (and its rounding with it). With even or nearly even knots (Fig. 29's) u
// stays within the points' indices and the curve is tame.
class PointCurveMotion {
 public:
  // points: n >= 4, knots strictly increasing, knots and coordinates finite;
  // at most limits::kMaxNevillePoints for the Neville-type curves (neville-*,
  // log-spiral-blend). pita and neville-centripetal also need consecutive
  // points distinct (a zero-length edge has no arrow, and no centripetal
  // spacing). pita needs `track`, which is used by nothing else; exceptions
  // of the track (MotionDomainError) pass through. Throws
  // std::invalid_argument saying what is wrong otherwise.
  PointCurveMotion(PointCurve curve, std::vector<TimedPoint> points, const ArrowTrackFactory& track = {});

  Point at(double t) const;

  PointCurve curve() const { return curve_; }
  const std::vector<TimedPoint>& points() const { return points_; }

 private:
  double parameter(double t) const;  // u(t) of the Neville curves
  Point neville(double t) const;
  Point log_spiral_blend(double t) const;

  PointCurve curve_;
  std::vector<TimedPoint> points_;
  std::vector<double> parameters_;              // u_i (neville-*)
  std::vector<LogSpiral> spirals_;              // LS(p_j, p_{j+1}, p_{j+2}) (log-spiral-blend)
  std::shared_ptr<const Motion> first_track_;   // X (pita)
  std::shared_ptr<const Motion> second_track_;  // Y (pita)
};

}  // namespace pita
