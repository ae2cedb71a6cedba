#include "core/pitas/p09_ne_lp.hpp"

#include "core/mean_morph.hpp"
#include "core/neville_ratios.hpp"
#include "core/steady_morph.hpp"

namespace pita {

NeLp::NeLp(const KeyframeTriple& k, MeanKind path_mean, MeanKind magnitude_mean)
    : k_(k),
      path_mean_(path_mean),
      magnitude_mean_(magnitude_mean),
      a_to_b_(twirl_between(k.a.arrow, k.b.arrow)),
      b_to_c_(twirl_between(k.b.arrow, k.c.arrow)) {}

Arrow NeLp::at(double t) const {
  const NevilleRatios n = neville_ratios(k_.a.t, k_.b.t, k_.c.t, t);
  if (path_mean_ == MeanKind::geometric && magnitude_mean_ == MeanKind::geometric) {
    return steady_morph(apply_power(a_to_b_, n.q, k_.a.arrow), apply_power(b_to_c_, n.r, k_.b.arrow),
                        n.s);  // PITA Eq. D.2
  }
  const auto morph = [&](const Arrow& X, const Arrow& Y, double s) {
    return mean_morph(X, Y, s, path_mean_, magnitude_mean_);
  };
  return morph(morph(k_.a.arrow, k_.b.arrow, n.q), morph(k_.b.arrow, k_.c.arrow, n.r), n.s);
}

}  // namespace pita
