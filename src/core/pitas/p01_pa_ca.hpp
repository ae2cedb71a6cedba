// P1:Pa-Ca (Sec. 3.1): parabolic point (PITA Eq. 11), Cartesian vector (-Ca).
// p and the zero-turn vector are Lagrange interpolants, so q = p + vector is
// one too: affine-invariant, handle-invariant, globally perseverant, not
// winding-aware (the output winding is the principal angle of the vector).
#pragma once

#include "core/keyframe.hpp"
#include "core/pitas/motion.hpp"

namespace pita {

class PaCa final : public Motion {
 public:
  explicit PaCa(const KeyframeTriple& k);
  Arrow at(double t) const override;

 private:
  KeyframeTriple k_;
};

}  // namespace pita
