// Log and exp of a similarity's homogeneous matrix in complex form (appendix A,
// PITA Eq. A.1-A.8), used by P5 and its variant.
//
// The similarity z -> lambda z + p with lambda = e^l (l = ln m + i theta,
// principal theta) has log [[l, v], [0, 0]] with v = p l / (e^l - 1) (A.7-A.8);
// exp of [[l, v], [0, 0]] is z -> e^l z + (e^l - 1)/l v (A.6). (e^l - 1)/l -> 1
// as l -> 0 (the identity's log); with a principal angle e^l = 1 only at l = 0,
// so every similarity has this log (the remark after A.8).
#pragma once

#include "core/arrow.hpp"
#include "core/complex_math.hpp"
#include "core/limits.hpp"

namespace pita {

// (e^l - 1)/l, with its limit 1 at l = 0.
inline Complex exprel(Complex l) {
  if (std::abs(l) < limits::kTinyScale) return Complex{1.0};
  return expm1(l) / l;
}

struct SimilarityLog {
  Complex linear;       // l
  Complex translation;  // v
};

// The log of the similarity of arrow (p, m, w) (maps the unit arrow at the
// origin onto it), with the principal angle of w.
inline SimilarityLog similarity_log(Point p, double m, double w) {
  const Complex l{std::log(m), principal_angle(w)};
  return {l, p / exprel(l)};
}

// The arrow of exp([[l, v], [0, 0]]); its winding is Im l as blended (not
// reduced).
inline Arrow similarity_exp(const SimilarityLog& s) {
  return {exprel(s.linear) * s.translation, std::exp(s.linear.real()), s.linear.imag()};
}

}  // namespace pita
