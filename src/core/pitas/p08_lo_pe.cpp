#include "core/pitas/p08_lo_pe.hpp"

#include "core/knot_warp.hpp"

namespace pita {

LoPe::LoPe(const KeyframeTriple& k) : k_(k), pe_(k.a.arrow.vector(), k.b.arrow.vector(), k.c.arrow.vector()) {}

Arrow LoPe::at(double t) const {
  const double tau = 2.0 * knot_warp(k_.a.t, k_.b.t, k_.c.t, t) - 1.0;
  const Perseverant::Values f = pe_.values(tau);
  const Point pa = k_.a.arrow.p, pb = k_.b.arrow.p, pc = k_.c.arrow.p;
  const Vector va = k_.a.arrow.vector(), vb = k_.b.arrow.vector(), vc = k_.c.arrow.vector();
  const Complex bend = pa + pc - 2.0 * pb;
  const Point p = pb + 0.5 * (pc - pa) * tau + 0.5 * bend * f.Q + bend * (vc - va) / (4.0 * vb) * f.R;
  const Vector v = vb + 0.5 * (va + vc - 2.0 * vb) * f.Q + 0.5 * (vc - va) * f.S;
  return arrow_from_vector(p, v);
}

}  // namespace pita
