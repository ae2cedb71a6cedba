// How far apart two arrows, or two patterns, are in the plane: what Figs. 16,
// 18 and B.30 print besides the discrepancy E of Sec. 6.2 (core/discrepancy.hpp).
#pragma once

#include <span>

#include "core/arrow.hpp"

namespace pita::analysis {

// max(|A.p - B.p|, |A.q - B.q|), in world units: the largest move of an
// endpoint that takes A onto B (docs/paper-notes.md N53). Unlike E it is not
// scale-invariant: it says how far a drawn arrow is from a frame in the
// units of the drawing (Fig. 18: "a slight expansion of one covers the other").
double endpoint_distance(const Arrow& A, const Arrow& B);

// The largest endpoint distance between frames at the same index (Fig. B.30:
// two methods sampled at the same times). Both spans have the same size.
double pattern_distance(std::span<const Arrow> first, std::span<const Arrow> second);

}  // namespace pita::analysis
