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
    : B_(B), C_(C), powers_(checked(B, C)), log_(powers_.log()) {}

Affine3 SteadyAffineMorph3::at(double u) const {
  if (u == 0.0) return B_;
  if (u == 1.0) return C_;
  return compose(powers_.at(u), B_);
}

Affine3 SteadyAffineMorph3::velocity(double u) const {
  // d/du A^u B x = G(A^u B x) with G = {log L, v}: the linear part C L(u),
  // the translation C b(u) + v.
  const Affine3 pose = at(u);
  return {log_.L * pose.L, log_.L * pose.b + log_.b};
}

}  // namespace pita
