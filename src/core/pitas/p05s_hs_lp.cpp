#include "core/pitas/p05s_hs_lp.hpp"

#include "core/homogeneous_log.hpp"
#include "core/lagrange_weights.hpp"
#include "core/steady_morph.hpp"

namespace pita {

HsLp::HsLp(const KeyframeTriple& k) : k_(k) {
  frame_ = steady_average(k.a.arrow, k.c.arrow);
  const Complex frame_linear = frame_.vector();
  const Arrow* arrows[3] = {&k.a.arrow, &k.b.arrow, &k.c.arrow};
  for (int i = 0; i < 3; ++i) {
    // F^{-1} . X: origin (X.p - F.p)/F.vec, magnitude X.m/F.m, winding X.w - F.w.
    const Arrow& X = *arrows[i];
    const SimilarityLog s = similarity_log((X.p - frame_.p) / frame_linear, X.m / frame_.m, X.w - frame_.w);
    log_[i] = s.linear;
    translation_log_[i] = s.translation;
  }
}

Arrow HsLp::at(double t) const {
  const LagrangeWeights l = lagrange_weights(k_.a.t, k_.b.t, k_.c.t, t);
  const SimilarityLog blend{lagrange(l, log_[0], log_[1], log_[2]),
                            lagrange(l, translation_log_[0], translation_log_[1], translation_log_[2])};
  const Arrow local = similarity_exp(blend);
  // Back to the world: F . local.
  return {frame_.p + frame_.vector() * local.p, frame_.m * local.m, frame_.w + local.w};
}

}  // namespace pita
