// Options of the methods that have any.
#pragma once

#include "core/mean_kind.hpp"

namespace pita {

// Where P2's log-spiral is applied: the start point (Sec. 3.1) or the midpoint
// of the arrow (the variant drawn in Fig. 1).
enum class Anchor { start, midpoint };

// Per-method options. Each method reads only the fields that concern it.
struct MethodOptions {
  Anchor anchor = Anchor::start;                  // P2
  MeanKind path_mean = MeanKind::geometric;       // SMA, P9 (Sec. 2.7, Fig. D.36)
  MeanKind magnitude_mean = MeanKind::geometric;  // SMA, P9
};

}  // namespace pita
