// The Average Relative Acceleration (ARA) of an affine motion, the SAM
// paper's measure of unsteadiness (Sec. 1 and 2.4): the mean, over points of
// the moving shape and over time, of the magnitude of the acceleration by
// which a point's velocity expressed in the moving frame,
//     w(u) = L(u)^-1 (L'(u) p + b'(u))        (p in reference coordinates),
// changes over time. A motion is steady (a SAM, SAM Eq. 1) exactly when w is
// constant (Sec. 6.1), so its ARA is 0.
#pragma once

#include <span>
#include <vector>

#include <Eigen/Core>

#include "core/pose_motion.hpp"
#include "core/sam_family_motion.hpp"

namespace pita {

// ARA of `motion` over its knots, time normalised to u in [0, 1] (so the
// measure does not depend on the time unit), averaged over `points`
// (reference coordinates) and over `time_samples` times at the middles of
// equal intervals of u (never at a knot, where a polySAM's velocity jumps).
// dw/du by central differences of the exact (or fourth-order) velocity.
// Poses of the plane (points of R^2) and of space (SamFamilyMotion<Affine3>, points of
// R^3) alike: one template (steadiness.cpp).
double average_relative_acceleration(const PoseMotion& motion, std::span<const Eigen::Vector2d> points,
                                     int time_samples = 64);
double average_relative_acceleration(const SamFamilyMotion<Affine3>& motion, std::span<const Eigen::Vector3d> points,
                                     int time_samples = 64);

// The points ARA averages over (Sec. 2.4: "a regular grid of the shape's
// box"): `per_side` x `per_side` points spanning the bounding box of
// `vertices` (reference coordinates). Both the printed ARA of a figure and
// the one `pita measure` and claims compare use it (docs/paper-notes.md N28).
inline constexpr int kDefaultAraGrid = 11;
std::vector<Eigen::Vector2d> ara_grid(std::span<const Eigen::Vector2d> vertices, int per_side = kDefaultAraGrid);

}  // namespace pita
