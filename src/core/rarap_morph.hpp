// "rARAP", column (b) of the SAM paper's Fig. 2 (Sec. 2.4): ARAP [Alexa et
// al. 2000] between two poses, with "a constant-speed translation along the
// line joining the barycenters ... added (because ARAP only deals with the
// evolution of the shape and its orientation, but not with its position)".
//
// With A = C o B^-1 the affinity from the first pose B to the second C, its
// linear part L = R(alpha + beta) S (core/arap_decomposition.hpp, Sec. 3.3.2)
// is animated as
//     L(u) = R(u (alpha + beta)) o ((1 - u) I + u S)       (Sec. 3.3.2)
// about the barycentre g0 = B(c) of the shape, c the barycentre of the
// reference triangle, which moves on the segment to g1 = C(c) = A(g0):
//     M(u): x -> L(u) (x - g0) + (1 - u) g0 + u g1,    pose(u) = M(u) o B.
// Rotation angle linear in u, barycentre at constant speed on a line
// (docs/paper-notes.md N39). Similarity-invariant (the polar decomposition
// commutes with rotations and scalings) but not affine-invariant, and not
// steady: a rotation with a dilation s makes L(u) = R(u theta)((1-u) + u s),
// whose scale grows linearly rather than geometrically.
#pragma once

#include <Eigen/Core>

#include "core/affine2.hpp"
#include "core/arap_decomposition.hpp"

namespace pita {

class RarapMorph {
 public:
  // `centre` in reference coordinates (the reference triangle's barycentre).
  // Throws std::invalid_argument when det(L) <= 0 (the poses have opposite
  // orientations: ARAP interpolates no reflection).
  RarapMorph(const Affine2& from, const Affine2& to, const Eigen::Vector2d& centre);

  // pose(u) = M(u) o B; B at u = 0 and C at u = 1 (up to rounding).
  Affine2 at(double u) const;
  // d/du of at(u), as (dL/du, db/du).
  Affine2 velocity(double u) const;

  const ArapDecomposition& decomposition() const { return decomposition_; }
  // M(u)'s linear part L(u), and the barycentre g(u) = (1 - u) g0 + u g1.
  Eigen::Matrix2d linear(double u) const;
  Eigen::Vector2d barycentre(double u) const { return (1.0 - u) * g0_ + u * g1_; }

 private:
  Affine2 from_;
  ArapDecomposition decomposition_;
  Eigen::Vector2d g0_, g1_;
};

}  // namespace pita
