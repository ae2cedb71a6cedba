// The Steady Affine Morph of space (SAM paper Sec. 2.2 with appendix A.6):
// from pose B (time 0) to pose C (time 1), A^u o B with A = C o B^-1 and the
// power by EAR in 3D (affine_power3.hpp). The 3D sibling of
// SteadyAffineMorph (affine_power.hpp), with the same verbs.
#pragma once

#include "core/affine3.hpp"
#include "core/affine_power3.hpp"

namespace pita {

class SteadyAffineMorph3 {
 public:
  // Throws NoRealLogarithm ("no SAM exists between these poses: ...") when
  // C o B^-1 has no real power.
  SteadyAffineMorph3(const Affine3& B, const Affine3& C);
  // A^u o B; exactly B at u = 0 and C at u = 1.
  Affine3 at(double u) const;
  // d/du of at(u) as (dL/du, db/du): the SAM's velocity field log A applied
  // to the pose (Sec. 2.3 (6)). Takes a 3D log each call (about 2 us, more
  // where its Newton steps are needed, N58); at() never does, so SAMs built
  // per sample (Bezier SAMs, patches) do not pay for it.
  Affine3 velocity(double u) const;
  const AffinePowers3& powers() const { return powers_; }

 private:
  static AffinePowers3 checked(const Affine3& B, const Affine3& C);
  Affine3 B_, C_;
  AffinePowers3 powers_;  // of A = C o B^-1
  // Of [L | b_C - b_B] (L the linear part of A): its power's translation is
  // g_u(L) (b_C - b_B), the part of A^u o B's translation that moves.
  AffinePowers3 change_;
};

}  // namespace pita
