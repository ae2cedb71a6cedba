// Neville ratios of three knots (Sec. 2.4).
#pragma once

namespace pita {

// q, r, s of PITA Eq. 14: p(t) = L(L(p_a, p_b, q), L(p_b, p_c, r), s) (PITA Eq. 12).
struct NevilleRatios {
  double q;  // (t - a)/(b - a)
  double r;  // (t - b)/(c - b)
  double s;  // (t - a)/(c - a)
};

inline NevilleRatios neville_ratios(double a, double b, double c, double t) {
  return {(t - a) / (b - a), (t - b) / (c - b), (t - a) / (c - a)};
}

}  // namespace pita
