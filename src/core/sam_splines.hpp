// Motions through more than two poses built from SAMs (SAM paper Sec. 5.3 and
// 7.3): the polySAM, the quadratic and cubic Bezier SAMs, the bi-arc
// retrofit, the SAM patch and the four-point subdivision. Each uses SAM
// (core/steady_affine_morph.hpp) as its only interpolation primitive, so each throws
// NoRealLogarithm ("no SAM exists between these poses: ...") when a SAM it
// needs does not exist.
//
// The paper states them for poses of the plane and of space alike (Sec. 7):
// each is a template over the pose, Affine2 (2D EAR) or Affine3 (EAR in 3D,
// appendix A.6), instantiated for both in sam_splines.cpp.
#pragma once

#include <vector>

#include "core/affine2.hpp"
#include "core/affine3.hpp"
#include "core/steady_affine_morph.hpp"

namespace pita {

// SAM(F_A, t, F_B): the pose at time t of the SAM from F_A to F_B (Sec. 5.3).
template <class Pose>
Pose sam(const Pose& from, double t, const Pose& to);

// SAM(F_X, F_A, t, F_B): F_X moved by the motion that takes F_A along its SAM
// to time t, A^t o F_X with A = F_B o F_A^-1 (Sec. 5.3).
template <class Pose>
Pose sam_moved(const Pose& pose, const Pose& from, double t, const Pose& to);

// The quadratic Bezier motion with control poses A, B, C (Sec. 5.3):
// SAM(SAM(A, t, B), t, SAM(B, t, C)). Passes through A and C, not through B.
template <class Pose>
Pose bezier_sam(const Pose& A, const Pose& B, const Pose& C, double t);

// The cubic one (Sec. 7.3, Fig. 12).
template <class Pose>
Pose bezier_sam(const Pose& A, const Pose& B, const Pose& C, const Pose& D, double t);

// leftControl (Sec. 5.3): SAM(SAM(A, 0.75, B), C, 0.25, B).
template <class Pose>
Pose left_control(const Pose& A, const Pose& B, const Pose& C);

// The SAM bi-arc retrofit (Sec. 5.3, Fig. 7d): two quadratic Bezier motions
// (A, L, B) and (B, R, C) joined at B at u = 1/2, with L = leftControl(A, B, C)
// and R = leftControl(C, B, A). C1 at B; needs only the SAMs A-B and B-C.
template <class Pose>
class SamBiarcOf {
 public:
  SamBiarcOf(const Pose& A, const Pose& B, const Pose& C);
  Pose at(double u) const;  // u in [0, 1]: A at 0, B at 1/2, C at 1
  const Pose& left() const { return left_; }
  const Pose& right() const { return right_; }

 private:
  Pose A_, B_, C_, left_, right_;
};
using SamBiarc = SamBiarcOf<Affine2>;

// The SAM patch (Sec. 7.3, Fig. 11) with control poses A (top left), B (top
// right), C (bottom left), D (bottom right): rows of SAMs A-B and C-D, and a
// SAM between the poses of each column, SAM(SAM(A, u, B), v, SAM(C, u, D)).
template <class Pose>
Pose sam_patch(const Pose& A, const Pose& B, const Pose& C, const Pose& D, double u, double v);

// The corner that makes a SAM patch regular in both directions (Sec. 7.3):
// D = SAM(C, A, 1, B) = (B o A^-1) o C. Then the patch is G^u H^v A with
// G = B o A^-1, H = C o A^-1: every row is the same regular pattern.
template <class Pose>
Pose regular_patch_corner(const Pose& A, const Pose& B, const Pose& C);

// One four-point subdivision step of a polySAM's control poses (Sec. 7.3):
// n poses -> 2n - 1, the old ones kept, each new one the SAM average of two
// parabolic predictions left(...) = SAM(SAM(A, 0.625, B), C, 0.125, B).
template <class Pose>
std::vector<Pose> subdivide_four_point(const std::vector<Pose>& poses);

}  // namespace pita
