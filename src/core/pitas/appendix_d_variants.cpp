#include "core/pitas/appendix_d_variants.hpp"

#include "core/lagrange_weights.hpp"
#include "core/neville_ratios.hpp"
#include "core/steady_morph.hpp"
#include "core/twirl.hpp"

namespace pita {

std::array<int, 3> permutation_slots(Permutation p) {
  switch (p) {
    case Permutation::ABC:
      return {0, 1, 2};
    case Permutation::ACB:
      return {0, 2, 1};
    case Permutation::BAC:
      return {1, 0, 2};
    case Permutation::BCA:
      return {1, 2, 0};
    case Permutation::CAB:
      return {2, 0, 1};
    case Permutation::CBA:
      return {2, 1, 0};
  }
  return {0, 1, 2};
}

Permutation time_reverse(Permutation p) {
  switch (p) {
    case Permutation::ABC:
      return Permutation::CBA;
    case Permutation::CBA:
      return Permutation::ABC;
    case Permutation::BCA:
      return Permutation::BAC;
    case Permutation::BAC:
      return Permutation::BCA;
    case Permutation::CAB:
      return Permutation::ACB;
    case Permutation::ACB:
      return Permutation::CAB;
  }
  return p;
}

AppendixDVariant::AppendixDVariant(const KeyframeTriple& k, AppendixDForm form, Permutation permutation,
                                   bool symmetrize)
    : k_(k), form_(form), permutation_(permutation), symmetrize_(symmetrize) {}

Arrow AppendixDVariant::permuted(Permutation p, double t) const {
  const Keyframe* keys[3] = {&k_.a, &k_.b, &k_.c};
  const std::array<int, 3> slot = permutation_slots(p);
  const Keyframe& k0 = *keys[slot[0]];
  const Keyframe& k1 = *keys[slot[1]];
  const Keyframe& k2 = *keys[slot[2]];
  switch (form_) {
    case AppendixDForm::lagrange_t1: {
      const LagrangeWeights l = lagrange_weights(k0.t, k1.t, k2.t, t);
      // T_{1->2}^{w2} . M(k0, k1, w1 + w2)   (PITA Eq. 34)
      return apply_power(twirl_between(k1.arrow, k2.arrow), l.z,
                         apply_power(twirl_between(k0.arrow, k1.arrow), l.y + l.z, k0.arrow));
    }
    case AppendixDForm::lagrange_t2: {
      const LagrangeWeights l = lagrange_weights(k0.t, k1.t, k2.t, t);
      // T(M(k0, k1, w1), k0, k2, w2) = T_{0->2}^{w2} . M(k0, k1, w1)   (PITA Eq. D.1)
      return apply_power(twirl_between(k0.arrow, k2.arrow), l.z,
                         apply_power(twirl_between(k0.arrow, k1.arrow), l.y, k0.arrow));
    }
    case AppendixDForm::neville: {
      const NevilleRatios n = neville_ratios(k0.t, k1.t, k2.t, t);
      // M(M(k0, k1, q), M(k1, k2, r), s)   (PITA Eq. D.2)
      return steady_morph(steady_morph(k0.arrow, k1.arrow, n.q), steady_morph(k1.arrow, k2.arrow, n.r), n.s);
    }
  }
  return k0.arrow;
}

Arrow AppendixDVariant::at(double t) const {
  if (!symmetrize_) return permuted(permutation_, t);
  return steady_average(permuted(permutation_, t), permuted(time_reverse(permutation_), t));
}

}  // namespace pita
