// The non-chosen -LP candidates of appendix D (docs/paper-notes.md N55), each
// through the three timed keyframes taken in one of six orders (Permutation):
//
//   T1(a, A, b, B, c, C, t) = T_{B->C}^z . M(A, B, y + z)       (PITA Eq. 34; P6's half)
//   T2(a, A, b, B, c, C, t) = T_{A->C}^z . M(A, B, y)           (PITA Eq. D.1)
//   M (a, A, b, B, c, C, t) = M(M(A, B, q), M(B, C, r), s)      (PITA Eq. D.2; P9)
//
// with the Lagrange weights x, y, z of PITA Eq. 10 and the Neville ratios q, r, s
// of PITA Eq. 14 computed from the knots in the permuted order, M the steady morph
// (PITA Eq. 20) and T(X, P, Q, z) = T_{P->Q}^z . X the transport of PITA Eq. D.1.
// "BAC" names T(b, B, a, A, c, C, t) (PITA Eq. D.3's notation).
//
// Symmetrized, the variant is the steady average of itself and its time
// reverse, the permutation with A and C swapped (ABC <-> CBA, BCA <-> BAC,
// CAB <-> ACB): La-T1 "ABC" symmetrized is P6, and Ne-M "ACB" symmetrized is
// the average of M_ACB and M_BAC that Fig. D.35 draws.
#pragma once

#include <array>
#include <string_view>

#include "core/keyframe.hpp"
#include "core/pitas/method_options.hpp"
#include "core/pitas/motion.hpp"

namespace pita {

enum class AppendixDForm { lagrange_t1, lagrange_t2, neville };

// Which keyframe (0 = (a, A), 1 = (b, B), 2 = (c, C)) comes first, second and
// third in the permutation.
std::array<int, 3> permutation_slots(Permutation p);
// Names: permutation_name (core/pitas/method_options.hpp).
// The permutation with A and C swapped: the variant's time reverse.
Permutation time_reverse(Permutation p);

class AppendixDVariant final : public Motion {
 public:
  AppendixDVariant(const KeyframeTriple& k, AppendixDForm form, Permutation permutation, bool symmetrize);
  Arrow at(double t) const override;

 private:
  Arrow permuted(Permutation p, double t) const;

  KeyframeTriple k_;
  AppendixDForm form_;
  Permutation permutation_;
  bool symmetrize_;
};

}  // namespace pita
