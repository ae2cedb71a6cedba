// Affinities of space (Affine3 = Affine<3>, affine.hpp; SAM paper Sec. 2.1,
// appendix A.6), and the 4x4 homogeneous matrix they are read from.
#pragma once

#include "core/affine.hpp"

namespace pita {

// The affinity of a 4x4 homogeneous matrix [[L, b], [0, 1]] (its last row is
// ignored); homogeneous(A) (affine.hpp) is the way back.
inline Affine3 affine3_of(const Eigen::Matrix4d& H) { return affine_of_homogeneous<3>(H); }

}  // namespace pita
