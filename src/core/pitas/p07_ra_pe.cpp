#include "core/pitas/p07_ra_pe.hpp"

#include "core/knot_warp.hpp"
#include "core/limits.hpp"

namespace pita {

RaPe::RaPe(const KeyframeTriple& k) : k_(k), pe_(k.a.arrow.vector(), k.b.arrow.vector(), k.c.arrow.vector()) {}

Arrow RaPe::at(double t) const {
  const double tau = 2.0 * knot_warp(k_.a.t, k_.b.t, k_.c.t, t) - 1.0;
  const Perseverant::Values f = pe_.values(tau);
  const auto move = [&](Point xa, Point xb, Point xc) {
    return xb + 0.5 * (xa + xc - 2.0 * xb) * f.Q + 0.5 * (xc - xa) * f.S;
  };
  const Point p = move(k_.a.arrow.p, k_.b.arrow.p, k_.c.arrow.p);
  const Point q = move(k_.a.arrow.q(), k_.b.arrow.q(), k_.c.arrow.q());
  return arrow_from_vector(p, q - p);
}

std::optional<Point> RaPe::fixed_point() const {
  const Complex kappa_m1 = pe_.kappa() - 1.0;
  if (std::abs(kappa_m1) < limits::kTwirlTranslation) return std::nullopt;
  const Point pa = k_.a.arrow.p, pb = k_.b.arrow.p, pc = k_.c.arrow.p;
  return pb + (2.0 * pb - pa - pc) / (2.0 * kappa_m1);  // PITA Eq. E.12
}

}  // namespace pita
