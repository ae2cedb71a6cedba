#include "core/time_warp.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace pita {

TimeWarp::TimeWarp(const Ease& ease, WarpSpan per, std::vector<double> knots, const ArcLengthTable::Path* path)
    : ease_(ease) {
  build(per, std::move(knots), path);
}

TimeWarp::TimeWarp(const Ease& ease, WarpSpan per, std::vector<double> knots, const ArcLengthTable::Path3* path)
    : ease_(ease) {
  build(per, std::move(knots), path);
}

template <class AnyPath>
void TimeWarp::build(WarpSpan per, std::vector<double> knots, const AnyPath* path) {
  const Ease& ease = ease_;
  if (knots.size() < 2) throw std::invalid_argument("a time warp needs at least two knots");
  for (std::size_t i = 1; i < knots.size(); ++i) {
    if (!(knots[i - 1] < knots[i])) throw std::invalid_argument("the knots of a time warp must increase");
  }
  knots_ = per == WarpSpan::span ? std::move(knots) : std::vector<double>{knots.front(), knots.back()};
  identity_ = ease.kind == EaseKind::linear && path == nullptr;
  if (path != nullptr) {
    for (std::size_t i = 0; i + 1 < knots_.size(); ++i) {
      try {
        tables_.push_back(std::make_shared<const ArcLengthTable>(*path, knots_[i], knots_[i + 1]));
      } catch (const std::invalid_argument& error) {
        if (knots_.size() == 2) throw;
        throw std::invalid_argument(std::string(error.what()) + " between the knots " + std::to_string(knots_[i]) +
                                    " and " + std::to_string(knots_[i + 1]));
      }
    }
  }
}

const ArcLengthTable* TimeWarp::table(std::size_t span) const {
  return span < tables_.size() ? tables_[span].get() : nullptr;
}

double TimeWarp::warped(double t) const {
  if (!(t > knots_.front() && t < knots_.back())) return t;
  // The span of t: the last knot at or before it.
  const std::size_t i =
      static_cast<std::size_t>(std::upper_bound(knots_.begin(), knots_.end(), t) - knots_.begin() - 1);
  const double from = knots_[i], to = knots_[i + 1];
  if (t == from) return t;
  const double y = ease(ease_, (t - from) / (to - from));
  // An ease may overshoot (CSS cubic-bezier with y outside [0, 1]): without
  // arc length the motion is then evaluated beyond the span (extrapolated);
  // with it, the fraction is clamped to the path over the span, whose table
  // covers that span only (docs/paper-notes.md N20).
  if (!tables_.empty()) return tables_[i]->parameter_at(y);
  if (y == 1.0) return to;
  return from + y * (to - from);
}

}  // namespace pita
