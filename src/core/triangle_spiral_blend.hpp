// "TSB", column (d) of the SAM paper's Fig. 2 (Sec. 2.4): "a blending
// (weighted average) of three logarithmic spirals computed from the three
// pairs of sides of the triangles (as used in [Whited et al. 2010])".
//
// On the pose's reference triangle r0 r1 r2 (docs/paper-notes.md N39): its
// vertices are v_j = B(r_j) in the first pose and v_j' = C(r_j) in the second.
// Side j runs from vertex j to vertex j + 1 (indices mod 3); its spiral is the
// twirl T_j = T_{A_j -> A_j'} between the zero-turn arrows A_j = (v_j, v_{j+1} - v_j)
// and A_j' (PITA paper PITA Eq. 17-19), turning by the principal angle
// Arg((v_{j+1}' - v_j') / (v_{j+1} - v_j)) in (-pi, pi] and scaling by the
// ratio of the side lengths. T_j^u carries both ends of side j on log spirals
// from the first pose to the second, so each vertex is carried by the spirals
// of its two sides, and the blend is their average, weight 1/2 each (the
// opposite side's spiral would not bring the vertex to v_j'):
//     v_j(u) = 1/2 T_j^u v_j + 1/2 T_{j-1}^u v_j.
// The pose at u is the affinity taking r0 r1 r2 onto v0(u) v1(u) v2(u), which
// carries any other shape. When C o B^-1 is a similarity (turning by less
// than pi) the three spirals coincide and TSB is the SAM. Similarity-
// invariant, symmetric; it depends on the reference triangle (not
// affine-invariant).
#pragma once

#include <array>

#include <Eigen/Core>

#include "core/affine2.hpp"
#include "core/twirl.hpp"

namespace pita {

class TriangleSpiralBlend {
 public:
  // The weight of each of a vertex's two sides.
  static constexpr double kSideWeight = 0.5;

  // `reference`: the reference triangle (not degenerate), in reference
  // coordinates. Throws std::invalid_argument when det(C o B^-1) <= 0.
  TriangleSpiralBlend(const Affine2& from, const Affine2& to, const std::array<Point, 3>& reference);

  Affine2 at(double u) const;
  Affine2 velocity(double u) const;

  // Side j's spiral T_j, from vertex j to vertex j + 1.
  const Twirl& side_spiral(int j) const { return spirals_[j]; }
  // v_j(u) and its velocity.
  Point vertex(int j, double u) const;
  Vector vertex_velocity(int j, double u) const;

 private:
  // The affinity (or, for velocities, the affinity-shaped rate) taking the
  // reference triangle onto the three points.
  Affine2 through(const std::array<Point, 3>& points) const;

  std::array<Point, 3> start_{};  // v_j = B(r_j)
  std::array<Twirl, 3> spirals_{};
  Affine2 reference_inverse_;  // [r1 - r0, r2 - r0 | r0]^-1
};

}  // namespace pita
