// The three Pythagorean means used to interpolate magnitudes (Sec. 2.7, Fig. 4).
#pragma once

namespace pita {

enum class MeanKind {
  arithmetic,  // WAM: (1 - t) a + t b
  geometric,   // WGM: a^(1-t) b^t, the steady choice
  harmonic,    // WHM: 1 / ((1 - t)/a + t/b)
};

}  // namespace pita
