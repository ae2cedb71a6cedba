#include "core/point_curves.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/lagrange_weights.hpp"
#include "core/limits.hpp"

namespace pita {
namespace {

constexpr std::array<PointCurveInfo, 4> kPointCurves{{
    {PointCurve::pita, "pita", "PITA blend of two arrow tracks (PITA Eq. 48-50)"},
    {PointCurve::neville_uniform, "neville-uniform", "Neville interpolation, uniform parameter"},
    {PointCurve::neville_centripetal, "neville-centripetal", "Neville interpolation, centripetal parameter"},
    {PointCurve::log_spiral_blend, "log-spiral-blend", "Neville blend of log-spiral three-point motions"},
}};

// Scratch row of a Neville triangle, on the stack (no allocation per time).
using NevilleRow = std::array<Point, limits::kMaxNevillePoints>;

// The LERP of PITA Eq. 13, a + s (b - a), written (1 - s) a + s b: exactly a at
// s = 0 and exactly b at s = 1 however far apart a and b are (an entry of the
// log-spiral blend may be a spiral extrapolated far from its knots).
Point lerp(Point a, Point b, double s) { return (1.0 - s) * a + s * b; }

}  // namespace

std::span<const PointCurveInfo> all_point_curves() { return kPointCurves; }

const PointCurveInfo* find_point_curve(std::string_view name) {
  for (const PointCurveInfo& entry : kPointCurves) {
    if (entry.name == name) return &entry;
  }
  return nullptr;
}

const PointCurveInfo& info(PointCurve curve) {
  for (const PointCurveInfo& entry : kPointCurves) {
    if (entry.curve == curve) return entry;
  }
  throw std::logic_error("unregistered point curve");
}

PointCurveMotion::PointCurveMotion(PointCurve curve, std::vector<TimedPoint> points, const ArrowTrackFactory& track)
    : curve_(curve), points_(std::move(points)) {
  const std::string name(info(curve).name);
  const std::size_t n = points_.size();
  if (n < 4) {
    throw std::invalid_argument(name + " needs at least 4 points, got " + std::to_string(n));
  }
  if (curve != PointCurve::pita && n > static_cast<std::size_t>(limits::kMaxNevillePoints)) {
    throw std::invalid_argument(name + " takes at most " + std::to_string(limits::kMaxNevillePoints) +
                                " points (Neville's recursion costs n^2 per time), got " + std::to_string(n));
  }
  for (std::size_t i = 0; i < n; ++i) {
    const TimedPoint& x = points_[i];
    if (!std::isfinite(x.t) || !std::isfinite(x.p.real()) || !std::isfinite(x.p.imag())) {
      throw std::invalid_argument(name + ": point " + std::to_string(i) +
                                  " must have a finite knot and finite coordinates");
    }
    if (i > 0 && !(points_[i - 1].t < x.t)) {
      throw std::invalid_argument(name + ": knots must be strictly increasing (point " + std::to_string(i) +
                                  " at t = " + std::to_string(x.t) +
                                  " does not follow t = " + std::to_string(points_[i - 1].t) + ")");
    }
  }
  // pita and the centripetal parameter need an edge between consecutive points.
  if (curve == PointCurve::pita || curve == PointCurve::neville_centripetal) {
    for (std::size_t i = 0; i + 1 < n; ++i) {
      if (!(std::abs(points_[i + 1].p - points_[i].p) > 0.0)) {
        throw std::invalid_argument(
            name + ": point " + std::to_string(i) + " and point " + std::to_string(i + 1) + " coincide" +
            (curve == PointCurve::pita ? " (the edge arrow between them would have no direction)"
                                       : " (no centripetal parameter step between them)"));
      }
    }
  }

  switch (curve) {
    case PointCurve::pita: {
      if (!track) throw std::invalid_argument("pita needs an arrow track to build its curve from");
      // PITA Eq. 48-49: X at knots t_0..t_{n-2}, Y at t_1..t_{n-1}, both through the
      // edge arrows e_i = p_i p_{i+1}. e_0 is the zero-turn arrow; each next
      // edge turns from the previous one by the principal angle between them,
      // so the windings depend on the shape only and a rotation of all the
      // points rotates the curve (docs/paper-notes.md N34).
      std::vector<Keyframe> first, second;
      Arrow previous;
      for (std::size_t i = 0; i + 1 < n; ++i) {
        Arrow edge = zero_turn_arrow(points_[i].p, points_[i + 1].p);
        if (i > 0) edge.w = previous.w + principal_angle(edge.w - previous.w);
        previous = edge;
        first.push_back({points_[i].t, edge});
        second.push_back({points_[i + 1].t, edge});
      }
      first_track_ = track(first);
      second_track_ = track(second);
      if (!first_track_ || !second_track_) {
        throw std::invalid_argument("pita: the arrow track factory built no motion");
      }
      break;
    }
    case PointCurve::neville_uniform:
      for (std::size_t i = 0; i < n; ++i) parameters_.push_back(static_cast<double>(i));
      break;
    case PointCurve::neville_centripetal:
      // Barry-Goldman's centripetal parameter: steps |p_{i+1} - p_i|^{1/2}.
      parameters_.push_back(0.0);
      for (std::size_t i = 0; i + 1 < n; ++i) {
        parameters_.push_back(parameters_.back() + std::sqrt(std::abs(points_[i + 1].p - points_[i].p)));
      }
      break;
    case PointCurve::log_spiral_blend:
      for (std::size_t j = 0; j + 2 < n; ++j) {
        spirals_.emplace_back(points_[j].p, points_[j + 1].p, points_[j + 2].p);
      }
      break;
  }
}

Point PointCurveMotion::at(double t) const {
  switch (curve_) {
    case PointCurve::pita: {
      // PITA Eq. 50 read as a blend of the start of X and the end of Y.
      const double s = (t - points_.front().t) / (points_.back().t - points_.front().t);
      return (1.0 - s) * first_track_->at(t).p + s * second_track_->at(t).q();
    }
    case PointCurve::neville_uniform:
    case PointCurve::neville_centripetal:
      return neville(t);
    case PointCurve::log_spiral_blend:
      return log_spiral_blend(t);
  }
  throw std::logic_error("unregistered point curve");
}

// u(t): piecewise linear through (t_i, u_i); before t_0 and after t_{n-1} the
// end spans' lines continue. At a knot the span starting there is used, so
// u(t_i) = u_i exactly for i < n - 1.
double PointCurveMotion::parameter(double t) const {
  const auto after = std::upper_bound(points_.begin(), points_.end(), t,
                                      [](double value, const TimedPoint& x) { return value < x.t; });
  const std::size_t last_span = points_.size() - 2;
  const auto index = static_cast<std::size_t>(after - points_.begin());
  const std::size_t i = index == 0 ? 0 : std::min(index - 1, last_span);
  const double ratio = (t - points_[i].t) / (points_[i + 1].t - points_[i].t);
  return parameters_[i] + ratio * (parameters_[i + 1] - parameters_[i]);
}

// Aitken-Neville over all points in u (PITA Eq. 12-14 extended to n points): row
// entry j of level L covers points j..j+L and is the LERP of the two entries
// of level L - 1 below it with ratio (u - u_j)/(u_{j+L} - u_j).
Point PointCurveMotion::neville(double t) const {
  const double u = parameter(t);
  const std::size_t n = points_.size();
  NevilleRow row;
  for (std::size_t j = 0; j < n; ++j) row[j] = points_[j].p;
  for (std::size_t level = 1; level < n; ++level) {
    for (std::size_t j = 0; j + level < n; ++j) {
      const double s = (u - parameters_[j]) / (parameters_[j + level] - parameters_[j]);
      row[j] = lerp(row[j], row[j + 1], s);
    }
  }
  return row[0];
}

// Neville's triangle from its third level up: LS- through points j, j+1, j+2
// (PITA Eq. 26), then LERPs in scene time; entry j of the level covering L points
// blends with s = (t - t_j)/(t_{j+L-1} - t_j).
Point PointCurveMotion::log_spiral_blend(double t) const {
  const std::size_t n = points_.size();
  NevilleRow row;
  for (std::size_t j = 0; j + 2 < n; ++j) {
    row[j] = spirals_[j].at(lagrange_weights(points_[j].t, points_[j + 1].t, points_[j + 2].t, t));
  }
  for (std::size_t covered = 4; covered <= n; ++covered) {
    for (std::size_t j = 0; j + covered <= n; ++j) {
      const double s = (t - points_[j].t) / (points_[j + covered - 1].t - points_[j].t);
      row[j] = lerp(row[j], row[j + 1], s);
    }
  }
  return row[0];
}

}  // namespace pita
