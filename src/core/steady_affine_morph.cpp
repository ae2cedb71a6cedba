#include "core/steady_affine_morph.hpp"

#include <string>

namespace pita {

NoRealLogarithm no_sam_between_poses(const NoRealLogarithm& error, bool mirrored) {
  if (mirrored) {
    return NoRealLogarithm(std::string("no SAM exists between these poses: one is mirrored and "
                                       "the other is not (") +
                               error.what() + "); no middle pose can help: mirror both poses or neither",
                           error.root_case());
  }
  return NoRealLogarithm(std::string("no SAM exists between these poses: A = C o B^-1 has no "
                                     "real power (") +
                             error.what() +
                             "); insert a middle pose between them and use a polySAM or a "
                             "SAM bi-arc through it (Sec. 5.3)",
                         error.root_case());
}

template <class Pose>
AffinePowers<Pose> SteadyAffineMorph<Pose>::checked(const Pose& B, const Pose& C) {
  const Pose A = compose(C, inverse(B));
  try {
    return AffinePowers<Pose>(A);
  } catch (const NoRealLogarithm& error) {
    throw no_sam_between_poses(error, !(A.L.determinant() > 0.0) && A.L.allFinite());
  }
}

template <class Pose>
SteadyAffineMorph<Pose>::SteadyAffineMorph(const Pose& B, const Pose& C)
    : B_(B), C_(C), powers_(checked(B, C)), change_(powers_.with_translation(C.b - B.b)) {}

// A^u o B = [L^u L_B | b_B + g_u(L) (b_C - b_B)], L the linear part of A and
// g_u(L) = (L^u - I)(L - I)^-1: the translation of A^u o B written without
// A's own translation b_C - L b_B, which is huge when B is small and would
// cancel in L^u b_B + g_u(L) b. No size ratio is a cut-off: from a pose 1e-8
// the size of the other the cancelling form loses up to half the digits of
// the translation, from one 1e-50 the size all of them; this form is exact
// to rounding at both (tested, FromATinyPose; docs/paper-notes.md N59).
template <class Pose>
Pose SteadyAffineMorph<Pose>::at(double u) const {
  if (u == 0.0) return B_;
  if (u == 1.0) return C_;
  const Pose power = change_.at(u);
  return {power.L * B_.L, B_.b + power.b};
}

// d/du: L' = log(L) L^u L_B and b' = d/du g_u(L) (b_C - b_B), the derivative
// of the power of [L | b_C - b_B] (Sec. 2.3 (6): log A applied to the pose,
// rewritten). Each dimension keeps its own form of b' (L^u l(L) d in 2D,
// log(L) g_u(L) d + l(L) d in 3D; equal in exact arithmetic).
template <class Pose>
Pose SteadyAffineMorph<Pose>::velocity(double u) const {
  const Pose rate = change_.velocity(u);
  return {rate.L * B_.L, rate.b};
}

template <class Pose>
Pose steady_affine_morph(const Pose& B, const Pose& C, double t) {
  return SteadyAffineMorph<Pose>(B, C).at(t);
}

template class SteadyAffineMorph<Affine2>;
template class SteadyAffineMorph<Affine3>;
template Affine2 steady_affine_morph(const Affine2&, const Affine2&, double);
template Affine3 steady_affine_morph(const Affine3&, const Affine3&, double);

}  // namespace pita
