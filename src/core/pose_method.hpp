// The methods of pose scenes (SAM paper, and the PITAs P4, P5, P6 and P9 over
// affine poses, docs/paper-notes.md N73), one table (pose_method.cpp): their
// ids, titles, how many poses each takes and whether it also moves poses of
// space (3D scenes). Shared by the plane's PoseMotion (pose_motion.hpp) and
// the SAM family of both dimensions (sam_family_motion.hpp).
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "core/affine_power.hpp"

namespace pita {

enum class PoseMethod {
  sam,
  poly_sam,
  bezier_sam,
  biarc_sam,
  linear,
  four_point,
  p4,  // Be-LP over affine poses (core/pose_pitas/be_lp.hpp)
  p5,  // He-LP (core/pose_pitas/he_lp.hpp)
  p6,  // La-LP (core/pose_pitas/la_lp.hpp)
  p9,  // Ne-LP (core/pose_pitas/ne_lp.hpp)
  rarap,
  asap,
  tsb,
  alexa
};

// Subdivision steps of the four-point polySAM (Sec. 7.3: "4 subdivision steps
// suffice to produce polySAMs that appear smooth"), and the most a scene may ask.
inline constexpr int kDefaultSubdivisions = 4;
inline constexpr int kMaxSubdivisions = 6;

struct PoseMethodInfo {
  PoseMethod method;
  std::string_view id;     // as scenes spell it: "SAM"
  std::string_view title;  // "Steady Affine Morph"
  int min_poses;
  int max_poses;
  bool in_space;  // also for 3D scenes (the SAM family: SamFamilyMotion<Affine3>)
  // The PITA's mnemonic ("La-LP") for the pose PITAs, which share the arrow
  // PITA's id ("P6"); empty for the SAM paper's methods.
  std::string_view mnemonic = {};
};

std::span<const PoseMethodInfo> all_pose_methods();
const PoseMethodInfo& info(PoseMethod method);
// Names are resolved by core/methods.hpp, the one registry of both kinds.

// A pose at a time: Affine2 in the plane, Affine3 in space.
template <class Pose>
struct TimedPoseOf {
  double t = 0.0;
  Pose pose;
};

// No SAM between poses `first` and `first + 1` of the motion (indices into
// its poses), which the method needs.
// `where` is empty for a pair of given poses, else it says which intermediate
// poses of a Bezier SAM or bi-arc construction have no SAM between them.
class NoSamBetweenPoses : public NoRealLogarithm {
 public:
  NoSamBetweenPoses(const NoRealLogarithm& cause, std::size_t first, std::string where = "")
      : NoRealLogarithm(cause.what(), cause.root_case()), first_(first), where_(std::move(where)) {}
  std::size_t first() const { return first_; }
  const std::string& where() const { return where_; }

 private:
  std::size_t first_;
  std::string where_;
};

}  // namespace pita
