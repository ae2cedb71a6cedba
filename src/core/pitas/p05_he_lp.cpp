#include "core/pitas/p05_he_lp.hpp"

#include "core/homogeneous_log.hpp"
#include "core/lagrange_weights.hpp"

namespace pita {

HeLp::HeLp(const KeyframeTriple& k, HomogeneousCenter center) : k_(k) {
  const Arrow* arrows[3] = {&k.a.arrow, &k.b.arrow, &k.c.arrow};
  // Appendix C: (1) translate the keyframes by o -> g, the centroid of origins
  // (not at all for H(t) about the global origin, He-G).
  centroid_ = center == HomogeneousCenter::centroid ? (k.a.arrow.p + k.b.arrow.p + k.c.arrow.p) / 3.0 : Point{};
  for (int i = 0; i < 3; ++i) {
    const SimilarityLog s = similarity_log(arrows[i]->p - centroid_, arrows[i]->m, arrows[i]->w);
    log_[i] = s.linear;
    translation_log_[i] = s.translation;
  }
}

Arrow HeLp::at(double t) const {
  const LagrangeWeights l = lagrange_weights(k_.a.t, k_.b.t, k_.c.t, t);
  // (2) H(t) = exp(x log H(A) + y log H(B) + z log H(C)) (PITA Eq. 33),
  const SimilarityLog blend{lagrange(l, log_[0], log_[1], log_[2]),
                            lagrange(l, translation_log_[0], translation_log_[1], translation_log_[2])};
  // (3) extract the arrow, (4) translate it back by g -> o.
  Arrow d = similarity_exp(blend);
  d.p += centroid_;
  return d;
}

}  // namespace pita
