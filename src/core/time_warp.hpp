// Time warps: the motion's own time tau as a function of the scene time t
// (the chapter's speed control, Sec. 3.2; docs/paper-notes.md N20).
//
// With knots t_0 < ... < t_n, x = (t - t_0)/(t_n - t_0) and y = ease(x):
//   tau = t_0 + y (t_n - t_0)                    without arc length,
//   tau = U(y L)                                 with arc length: U inverts the
//                                                length s(tau) of the tracked
//                                                point's path, L = s(t_n),
// i.e. p = P(U(S(t))) as in the chapter's Sec. 3.2.2. With per = span the same
// is done on each [t_i, t_{i+1}] on its own, so every keyframe is still
// reached at its knot. Outside [t_0, t_n] the warp is the identity
// (extrapolation is unchanged); so is the linear ease without arc length. An
// ease that overshoots (y outside [0, 1]) evaluates the motion beyond the
// span without arc length, and is clamped to the span's path with it.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "core/arc_length.hpp"
#include "core/ease.hpp"

namespace pita {

// Which span a warp covers: the whole knot range, or each knot span alone.
enum class WarpSpan { motion, span };

class TimeWarp {
 public:
  // The identity.
  TimeWarp() = default;
  // `knots` strictly increasing (at least 2). `path`, when given, is the
  // tracked point's path for arc length; its tables are built here. Throws
  // std::invalid_argument when a span's path has zero length.
  TimeWarp(const Ease& ease, WarpSpan per, std::vector<double> knots, const ArcLengthTable::Path* path = nullptr);
  // The same with the tracked point's path in space (3D pose scenes).
  TimeWarp(const Ease& ease, WarpSpan per, std::vector<double> knots, const ArcLengthTable::Path3* path);

  double operator()(double t) const { return identity_ ? t : warped(t); }
  bool is_identity() const { return identity_; }
  // The arc-length table of span i (every span of per = span, else the one
  // of the whole range); nullptr without arc length.
  const ArcLengthTable* table(std::size_t span) const;

 private:
  double warped(double t) const;
  template <class AnyPath>
  void build(WarpSpan per, std::vector<double> knots, const AnyPath* path);

  bool identity_ = true;
  Ease ease_;
  std::vector<double> knots_;  // t_0, t_n (per = motion) or every knot (per = span)
  std::vector<std::shared_ptr<const ArcLengthTable>> tables_;
};

}  // namespace pita
