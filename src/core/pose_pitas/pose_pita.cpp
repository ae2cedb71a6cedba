#include "core/pose_pitas/pose_pita.hpp"

#include <stdexcept>
#include <string>

namespace pita {

// The pose PITAs are the entries of the table with the arrow PITA's mnemonic.
bool is_pose_pita(PoseMethod method) { return !info(method).mnemonic.empty(); }

template <class Pose>
PosePita<Pose> make_pose_pita(PoseMethod method, const PoseTriple<Pose>& poses) {
  switch (method) {
    case PoseMethod::p4:
      return PoseBeLp<Pose>(poses);
    case PoseMethod::p5:
      return PoseHeLp<Pose>(poses);
    case PoseMethod::p6:
      return PoseLaLp<Pose>(poses);
    case PoseMethod::p9:
      return PoseNeLp<Pose>(poses);
    case PoseMethod::sam:
    case PoseMethod::poly_sam:
    case PoseMethod::bezier_sam:
    case PoseMethod::biarc_sam:
    case PoseMethod::linear:
    case PoseMethod::four_point:
    case PoseMethod::rarap:
    case PoseMethod::asap:
    case PoseMethod::tsb:
    case PoseMethod::alexa:
      break;
  }
  throw std::invalid_argument(std::string(info(method).id) + " is not a pose PITA");
}

template PosePita<Affine2> make_pose_pita(PoseMethod, const PoseTriple<Affine2>&);
template PosePita<Affine3> make_pose_pita(PoseMethod, const PoseTriple<Affine3>&);

}  // namespace pita
