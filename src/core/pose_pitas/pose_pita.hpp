// The pose PITAs as one value (docs/paper-notes.md N73): P4, P5, P6 or P9
// through three timed affine poses of the plane or of space, built from the
// pose method that names it. SamFamilyMotion (sam_family_motion.hpp) holds
// one for the methods PoseMethod::p4, p5, p6 and p9.
#pragma once

#include <variant>

#include "core/pose_method.hpp"
#include "core/pose_pitas/be_lp.hpp"
#include "core/pose_pitas/he_lp.hpp"
#include "core/pose_pitas/la_lp.hpp"
#include "core/pose_pitas/ne_lp.hpp"

namespace pita {

template <class Pose>
using PosePita = std::variant<PoseBeLp<Pose>, PoseHeLp<Pose>, PoseLaLp<Pose>, PoseNeLp<Pose>>;

// Whether `method` is one of the pose PITAs.
bool is_pose_pita(PoseMethod method);

// The pose PITA `method` names, through the three poses. Throws
// NoPosePitaPower as its constructor does, std::invalid_argument for a method
// that is not a pose PITA.
template <class Pose>
PosePita<Pose> make_pose_pita(PoseMethod method, const PoseTriple<Pose>& poses);

extern template PosePita<Affine2> make_pose_pita(PoseMethod, const PoseTriple<Affine2>&);
extern template PosePita<Affine3> make_pose_pita(PoseMethod, const PoseTriple<Affine3>&);

}  // namespace pita
