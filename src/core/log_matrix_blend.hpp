// "Alexa", the "linear combination of transformations" of [Alexa 2002] that
// the SAM paper compares SAM with (Sec. 3.3.2, Fig. 4 and 5): between the
// poses B (u = 0) and C (u = 1),
//     X(u) = e^{(1 - u) log B + u log C} = e^{log B + u (log C - log B)}
// with the logs of the poses themselves (absolute, not of C o B^-1), each the
// log of the 3x3 homogeneous matrix [[L, b], [0, 1]] (Alexa's Eq. 7 with the
// weights 1 - u and u of two poses). The SAM paper notes it equals the SAM
// e^{u log(C o B^-1)} o B "only in singular cases when B and C commute"
// (for example B = I), and is not steady otherwise: for B = Rotate(90 deg),
// C = Translate(6, 0) its mid-way transformation X_Alexa = X(1/2) o B^-1
// squared, X_Alexa^2 o B, is a translation by 12 sqrt(2)/pi ~ 5.402 instead
// of C's 6 (docs/paper-notes.md N45).
//
// The logs and exp are EAR's closed forms (core/affine_power.hpp: log and exp
// of a generator {C, v}), not Alexa's series and Denman-Beavers square roots:
// the motion is the same, only the way of computing it differs. Both poses
// need a real log (det L > 0 and not case G3 of appendix A.5): unlike SAM, a
// pair of mirrored poses has no blend, and neither has a pose that is, say,
// -diag(2, 1/2), even when a SAM to it exists.
#pragma once

#include <stdexcept>

#include "core/affine2.hpp"
#include "core/affine_power.hpp"

namespace pita {

class LogMatrixBlend {
 public:
  // Throws NoRealLogarithm ("no Alexa blend of these poses: the first pose
  // has no real logarithm (...)") when B or C has none.
  LogMatrixBlend(const Affine2& B, const Affine2& C);

  // e^{log B + u (log C - log B)}: B at u = 0, C at u = 1 (to rounding);
  // any real u (extrapolates).
  Affine2 at(double u) const;

  // d/du of at(u), as (dL/du, db/du): the Frechet derivative of exp at
  // M(u) = log B + u D in the direction D = log C - log B, the top-right
  // block of exp([[M, D], [0, M]]) (Higham, Functions of Matrices, Thm 3.6;
  // M and D do not commute in general, so it is not D e^M).
  Affine2 velocity(double u) const;

  // The generators {log L, v} of the two poses.
  const Affine2& log_first() const { return log_B_; }
  const Affine2& log_second() const { return log_C_; }

 private:
  Affine2 generator(double u) const;  // log B + u (log C - log B)
  Affine2 log_B_, log_C_;
};

}  // namespace pita
