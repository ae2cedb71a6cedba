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

// Per-method options. Each method reads only the fields that concern it.
struct MethodOptions {
  Anchor anchor = Anchor::start;                  // P2
  MeanKind path_mean = MeanKind::geometric;       // SMA, P9 (Sec. 2.7, Fig. D.36)
  MeanKind magnitude_mean = MeanKind::geometric;  // SMA, P9
  KnotOrder knots = KnotOrder::increasing;        // every three-keyframe method
};

}  // namespace pita
