// The SAM family of pose motions (SAM paper Sec. 5.3, 7.3), in the plane and
// in space alike: the SAM, the polySAM, the Bezier SAM, the SAM bi-arc, the
// four-point polySAM, linear interpolation of the matrices, and the PITAs
// P4, P5, P6 and P9 built from steady affine morphs (core/pose_pitas,
// docs/paper-notes.md N73), over timed
// poses of type Affine2 or Affine3 (instantiated for both in
// sam_family_motion.cpp). The plane's PoseMotion (pose_motion.hpp) adds the
// 2D-only morphs of Fig. 2 and Alexa's blend; 3D scenes ("dimension": 3) use SamFamilyMotion<Affine3>.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/affine2.hpp"
#include "core/affine3.hpp"
#include "core/pose_method.hpp"
#include "core/pose_pitas/blend_chain.hpp"
#include "core/sam_splines.hpp"

namespace pita {

// Throws std::invalid_argument unless there are as many poses as `method`
// takes and their knots strictly increase.
template <class Pose>
void check_poses(PoseMethod method, const std::vector<TimedPoseOf<Pose>>& poses);

// The motion through the poses, for the methods with PoseMethodInfo::in_space
// (SAM, polySAM, bezier-SAM, biarc-SAM, linear, four-point-SAM, P4, P5, P6,
// P9): every promise of PoseMotion (pose_motion.hpp) about errors and times
// holds here. The pose PITAs extrapolate outside their knots as the arrow
// PITAs do, and past three poses follow the blend chain (C1, docs/paper-notes.md
// N79); the powers they form at a time are checked at that time: at() and
// velocity() throw NoPosePitaPower, which names it (N74).
template <class Pose>
class SamFamilyMotion {
 public:
  using Timed = TimedPoseOf<Pose>;

  // Throws std::invalid_argument for another method, a wrong number of poses,
  // knots that do not increase; NoSamBetweenPoses as PoseMotion does.
  SamFamilyMotion(PoseMethod method, std::vector<Timed> poses, int subdivisions = kDefaultSubdivisions);

  Pose at(double t) const;
  // dA/dt as an affinity-shaped pair (dL/dt, db/dt); see PoseMotion::velocity.
  Pose velocity(double t) const;

  PoseMethod method() const { return method_; }
  const std::vector<Timed>& poses() const { return poses_; }

 private:
  double bezier_parameter(double t) const;
  std::size_t span_of(double t) const;  // outgoing span at interior knots

  PoseMethod method_;
  std::vector<Timed> poses_;
  std::vector<Timed> span_poses_;               // the polySAM's poses (SAM, polySAM, linear, four-point)
  std::vector<SteadyAffineMorph<Pose>> spans_;  // between span_poses_
  std::optional<SamBiarcOf<Pose>> biarc_;
  std::optional<PoseBlendChain<Pose>> pitas_;  // P4, P5, P6, P9: one triple, or the blend chain past three
};

}  // namespace pita
