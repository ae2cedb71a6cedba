// "ASAP", column (c) of the SAM paper's Fig. 2 (Sec. 2.4): "a logarithmic
// spiral motion, which interpolates the positions, orientations and uniform
// scaling, combined with a linear interpolation of the residue"
// (docs/paper-notes.md N39 on why this, and not the Y^t formula of Sec. 3.3.2,
// is the figure's column).
//
// With A = C o B^-1 and L = R(theta) S its ARAP/polar decomposition
// (core/arap_decomposition.hpp), s = sqrt(det L) the uniform scaling and
// N = S / s the residue (symmetric positive definite, det N = 1):
//   - the similarity part is the twirl Sigma: x -> s R(theta) (x - g0) + g1
//     taking the barycentre g0 = B(c) to g1 = C(c) (c the reference
//     triangle's barycentre), turning by theta and scaling by s; its powers
//     Sigma^u (PITA Eq. 8) are the log-spiral motion;
//   - the residue is interpolated linearly about g0: x -> g0 + ((1-u) I + u N)(x - g0);
//     pose(u) = Sigma^u o [residue(u)] o B.
// At u = 1: s R(theta) N = R(theta) S = L and Sigma(g0) = g1, so pose(1) = C.
// When C o B^-1 is a similarity, N = I and this is the SAM. Similarity-invariant.
#pragma once

#include <Eigen/Core>

#include "core/affine2.hpp"
#include "core/arap_decomposition.hpp"
#include "core/twirl.hpp"

namespace pita {

class SpiralResidueMorph {
 public:
  // Throws std::invalid_argument when det(L) <= 0 (opposite orientations).
  SpiralResidueMorph(const Affine2& from, const Affine2& to, const Eigen::Vector2d& centre);

  Affine2 at(double u) const;
  Affine2 velocity(double u) const;

  // The log-spiral (similarity) part Sigma and the residue N.
  const Twirl& spiral() const { return spiral_; }
  const Eigen::Matrix2d& residue() const { return residue_; }

 private:
  Affine2 from_;
  Eigen::Vector2d g0_;
  Twirl spiral_;
  Eigen::Matrix2d residue_;
};

}  // namespace pita
