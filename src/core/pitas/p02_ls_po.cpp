#include "core/pitas/p02_ls_po.hpp"

#include "core/point_motions.hpp"
#include "core/vector_motions.hpp"

namespace pita {

LsPo::LsPo(const KeyframeTriple& k, Anchor anchor) : k_(k), anchor_(anchor) {}

Arrow LsPo::at(double t) const {
  const LagrangeWeights l = lagrange_weights(k_.a.t, k_.b.t, k_.c.t, t);
  const Arrow& A = k_.a.arrow;
  const Arrow& B = k_.b.arrow;
  const Arrow& C = k_.c.arrow;
  const PolarVector v = polar_vector(l, A, B, C);
  if (anchor_ == Anchor::start) return {log_spiral_point(l, A.p, B.p, C.p), v.m, v.w};
  // Fig. 1 variant: the log-spiral carries the midpoint.
  const Point mid = log_spiral_point(l, A.p + 0.5 * A.vector(), B.p + 0.5 * B.vector(),
                                     C.p + 0.5 * C.vector());
  return {mid - 0.5 * std::polar(v.m, v.w), v.m, v.w};
}

}  // namespace pita
