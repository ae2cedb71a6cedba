#include "core/steady_affine_morph3.hpp"

namespace pita {

AffinePowers3 SteadyAffineMorph3::checked(const Affine3& B, const Affine3& C) {
  const Affine3 A = compose(C, inverse(B));
  try {
    return AffinePowers3(A);
  } catch (const NoRealLogarithm& error) {
    throw no_sam_between_poses(error, !(A.L.determinant() > 0.0) && A.L.allFinite());
  }
}

SteadyAffineMorph3::SteadyAffineMorph3(const Affine3& B, const Affine3& C)
    : B_(B),
      C_(C),
      powers_(checked(B, C)),
      change_(Affine3{powers_.affinity().L, C.b - B.b}) {}

// A^u o B = [L^u L_B | b_B + g_u(L) (b_C - b_B)], g_u(L) = (L^u - I)(L - I)^-1
// (as in 2D, affine_power.cpp): the translation written without A's own
// b_C - L b_B, which is huge when B is small (a motion from a pose 1e-50 the
// size of the other) and would cancel in L^u b_B + g_u(L) b (N59).
Affine3 SteadyAffineMorph3::at(double u) const {
  if (u == 0.0) return B_;
  if (u == 1.0) return C_;
  const Affine3 power = change_.at(u);
  return {power.L * B_.L, B_.b + power.b};
}

Affine3 SteadyAffineMorph3::velocity(double u) const {
  // d/du: L' = log(L) L^u L_B; b' = d/du g_u(L) d = log(L) g_u(L) d + l(L) d,
  // d = b_C - b_B (Sec. 2.3 (6): log A applied to the pose, rewritten).
  // log [L | d] = {log L, l(L) d}, l(L) = log L (L - I)^-1.
  const Affine3 generator = change_.log();
  const Affine3 power = change_.at(u);
  return {generator.L * power.L * B_.L, generator.L * power.b + generator.b};
}

}  // namespace pita
