// The Steady Affine Morph (SAM paper Sec. 2.2) of poses of the plane or of
// space: from pose B (time 0) to pose C (time 1), A^u o B with A = C o B^-1,
// the power by EAR (affine_power.hpp in 2D, appendix A.1-A.5;
// affine_power_of_space.hpp in 3D, appendix A.6). Instantiated for Affine2 and
// Affine3 in steady_affine_morph.cpp.
#pragma once

#include "core/affine2.hpp"
#include "core/affine3.hpp"
#include "core/affine_power.hpp"
#include "core/affine_power_of_space.hpp"

namespace pita {

template <class Pose>
class SteadyAffineMorph {
 public:
  // Throws NoRealLogarithm ("no SAM exists between these poses: ...") when
  // C o B^-1 has no real power.
  SteadyAffineMorph(const Pose& B, const Pose& C);
  // A^u o B; exactly B at u = 0 and C at u = 1.
  Pose at(double u) const;
  // d/du of at(u) as (dL/du, db/du): the SAM's velocity field log A applied
  // to the pose (Sec. 2.3 (6)). In 3D it takes a log each call
  // (AffinePowers<Affine3>::velocity); at() never does, so SAMs built per
  // sample (Bezier SAMs, patches) do not pay for it.
  Pose velocity(double u) const;
  // The powers of A = C o B^-1.
  const AffinePowers<Pose>& powers() const { return powers_; }

 private:
  static AffinePowers<Pose> checked(const Pose& B, const Pose& C);
  Pose B_, C_;
  AffinePowers<Pose> powers_;  // of A = C o B^-1
  // Of [L | b_C - b_B] (L the linear part of A): its power's translation is
  // g_u(L) (b_C - b_B), the part of A^u o B's translation that moves.
  AffinePowers<Pose> change_;
};

extern template class SteadyAffineMorph<Affine2>;
extern template class SteadyAffineMorph<Affine3>;

// SteadyAffineMorph(B, C).at(t) (use the class for many t).
template <class Pose>
Pose steady_affine_morph(const Pose& B, const Pose& C, double t);

// The error of a SAM (2D or 3D) whose A = C o B^-1 has no real power (`error`
// from EAR): "no SAM exists between these poses: ...", with the advice that
// fits: mirror both poses or neither (`mirrored`: det A <= 0), or insert a
// middle pose (Sec. 5.3).
NoRealLogarithm no_sam_between_poses(const NoRealLogarithm& error, bool mirrored);

}  // namespace pita
