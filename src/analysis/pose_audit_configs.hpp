// The triples of timed affine poses `pita audit poses` measures on
// (docs/reference/audit.md "What carries over to affine poses"): crafted cases first, then random
// ones drawn from a seed, tame, wild and near-singular in turn, in the plane
// (Affine2) or in space (Affine3). As for the arrow audit
// (analysis/audit_configs.hpp), configuration i depends only on (seed, i)
// and the dimension. Every linear part has a positive determinant.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "analysis/audit_configs.hpp"
#include "core/pose_pitas/morph_and_transport.hpp"
#include "core/pose_traits.hpp"

namespace pita::analysis {

template <class Pose>
struct PoseAuditConfig {
  int index = 0;  // position in the list (crafted ones first)
  ConfigMix mix = ConfigMix::tame;
  std::string name;  // "tame #12", "crafted: translates"
  PoseTriple<Pose> poses;
};

// The crafted cases (whatever the seed): translates, similarities about one
// point, three poses on one SAM, stretches on uneven knots, a shear.
template <class Pose>
std::vector<PoseAuditConfig<Pose>> crafted_pose_configs();

// The crafted cases then `random_count` random ones: the i-th tame, wild or
// near-singular in turn (i mod 3).
template <class Pose>
std::vector<PoseAuditConfig<Pose>> pose_audit_configs(std::uint64_t seed, int random_count);

// The vertices of the reference simplex (SAM Sec. 2.1): the origin and the
// unit vectors; a pose is the affinity that maps them onto its triangle or
// tetrahedron.
template <class Pose>
typename PoseTraits<Pose>::Simplex reference_simplex();

// The distance between two poses: the largest distance between the images
// of a vertex of the reference simplex (a norm on affinities).
template <class Pose>
double pose_distance(const Pose& X, const Pose& Y);

// The size of a triple: the largest distance from the image of the
// simplex's centroid by B to the image of a vertex by A, B or C. Every
// distance the pose audit reports is in this unit, which a similarity of the
// world scales with the poses.
template <class Pose>
double pose_extent(const PoseTriple<Pose>& poses);

// The largest distance from `from` to the image of a vertex of the simplex by `pose`.
template <class Pose>
double pose_reach(const Pose& pose, const typename PoseTraits<Pose>::Vector& from);

// The image of the simplex's centroid by `pose`, the point extents are measured from.
template <class Pose>
typename PoseTraits<Pose>::Vector pose_centre(const Pose& pose);

// A random affinity with a positive determinant: a rotation by up to `turn`
// radians (about a random axis in space), a symmetric stretch with log
// singular values within +-`stretch`, a translation within +-`shift`.
template <class Pose>
Pose random_affinity(AuditRandom& r, double turn, double stretch, double shift);

}  // namespace pita::analysis
