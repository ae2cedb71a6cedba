// Options of the methods that have any.
#pragma once

#include "core/mean_kind.hpp"

namespace pita {

// Where P2's log-spiral is applied: the start point (Sec. 3.1) or the midpoint
// of the arrow (the variant drawn in Fig. 1).
enum class Anchor { start, midpoint };

// How the keyframes reach a three-keyframe method: sorted by knot (the
// default; the knots must increase), or in the order given, so that
// P(b, B, a, A, c, C, t) of order-independence (Sec. 4, Eq. 42) can be
// evaluated (docs/paper-notes.md N41).
enum class KnotOrder { increasing, as_given };

// The order in which the appendix-D variants (La-T1, La-T2, Ne-M) take the
// timed keyframes: "BAC" evaluates T1(b, B, a, A, c, C, t) (appendix D.1,
// Eq. D.3's notation; docs/paper-notes.md N55).
enum class Permutation { ABC, ACB, BAC, BCA, CAB, CBA };

// Per-method options. Each method reads only the fields that concern it.
struct MethodOptions {
  Anchor anchor = Anchor::start;                  // P2
  MeanKind path_mean = MeanKind::geometric;       // SMA, P9 (Sec. 2.7, Fig. D.36)
  MeanKind magnitude_mean = MeanKind::geometric;  // SMA, P9
  KnotOrder knots = KnotOrder::increasing;        // every three-keyframe method
  Permutation permutation = Permutation::ABC;     // La-T1, La-T2, Ne-M (appendix D)
  bool symmetrize = false;                        // La-T1, La-T2, Ne-M: average with the time reverse
};

}  // namespace pita
