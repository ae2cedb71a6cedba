// The stationary velocity field of a SAM (SAM paper Sec. 6.2, Fig. 8, SAM Eq. 7;
// docs/paper-notes.md N47). The SAM A^u carries a point x0 on the trajectory
// x(u) = A^u(x0) (SAM Eq. 9), whose velocity is
//     x'(u) = log(A)(x(u)) = log(L) x(u) + v,        {log L, v} = log A,
// a field of the plane that does not depend on u: the trajectories are its
// integral curves. With the fixed point q of A (A.1) this is SAM Eq. 7,
//     p' = log(L)(p - q) + t_N,
// t_N = 0 when 1 is not an eigenvalue of L; otherwise (S1) there is no unique
// q and the field is log(L) p + v (the translation part of the homogeneous
// log, which is SAM Eq. 7's t_N with the origin on the invariant line).
#pragma once

#include <optional>

#include <Eigen/Core>

#include "core/affine2.hpp"
#include "core/affine_power.hpp"

namespace pita {

class SamVelocityField {
 public:
  // The field of A^u, u the SAM's own time (0 at the identity, 1 at A).
  // Throws NoRealLogarithm when A has no real power (no SAM, G3).
  explicit SamVelocityField(const Affine2& A);
  // The field of the SAM from pose B (u = 0) to pose C (u = 1): that of
  // A = C o B^-1 (Sec. 2.2). Throws NoRealLogarithm.
  static SamVelocityField between(const Affine2& B, const Affine2& C);

  // The velocity at x, per unit of u: log(L) x + v.
  Eigen::Vector2d at(const Eigen::Vector2d& x) const { return generator_.L * x + generator_.b; }
  // The point x0 after time u: A^u(x0), the integral curve through x0.
  Eigen::Vector2d trajectory(const Eigen::Vector2d& x0, double u) const { return apply(powers_.at(u), x0); }
  // The zero of the field, A's fixed point q (A.1); nullopt in S1.
  const std::optional<Eigen::Vector2d>& fixed_point() const { return fixed_point_; }
  // {log L, v}.
  const Affine2& generator() const { return generator_; }

 private:
  AffinePowers<Affine2> powers_;
  Affine2 generator_;
  std::optional<Eigen::Vector2d> fixed_point_;
};

}  // namespace pita
