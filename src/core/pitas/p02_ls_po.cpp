#include "core/pitas/p02_ls_po.hpp"

#include "core/point_motions.hpp"
#include "core/vector_motions.hpp"

namespace pita {

namespace {
Point anchor_point(const Arrow& A, Anchor anchor) { return anchor == Anchor::start ? A.p : A.p + 0.5 * A.vector(); }
}  // namespace

LsPo::LsPo(const KeyframeTriple& k, Anchor anchor)
    : k_(k),
      anchor_(anchor),
      spiral_(anchor_point(k.a.arrow, anchor), anchor_point(k.b.arrow, anchor), anchor_point(k.c.arrow, anchor)) {}

Arrow LsPo::at(double t) const {
  const LagrangeWeights l = lagrange_weights(k_.a.t, k_.b.t, k_.c.t, t);
  const Arrow& A = k_.a.arrow;
  const Arrow& B = k_.b.arrow;
  const Arrow& C = k_.c.arrow;
  const PolarVector v = polar_vector(l, A, B, C);
  if (anchor_ == Anchor::start) return {spiral_.at(l), v.m, v.w};
  // Fig. 1 variant: the log-spiral carries the midpoint.
  return {spiral_.at(l) - 0.5 * std::polar(v.m, v.w), v.m, v.w};
}

}  // namespace pita
