// The two steps every pose PITA is built from (docs/paper-notes.md N73): the
// PITA paper's steady morph and transport of similarities (Sec. 2.3-2.6,
// PITA Eq. 9-14) with the similarity's power T_{A,B}^s replaced by the SAM's
// (B o A^-1)^s (SAM paper Sec. 2.2), in the plane (Affine2) or in space
// (Affine3):
//   M(A, B, s) = (B o A^-1)^s o A       SteadyAffineMorph<Pose>(A, B).at(s)
//   T(X, A, B, s) = (B o A^-1)^s o X    transported(SteadyAffineMorph(A, B), X, s)
// and the SAMs a construction needs, checked: a pair with no real power throws
// NoPosePitaPower, which says which step and, where it depends on it, at
// which time (N74). The powers are EAR's (affine_power.hpp,
// affine_power_of_space.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "core/pose_method.hpp"
#include "core/steady_affine_morph.hpp"

namespace pita {

// The three timed poses (a, A), (b, B), (c, C) of a pose PITA; the knots must
// be distinct (a < b < c for scenes).
template <class Pose>
using PoseTriple = std::array<TimedPoseOf<Pose>, 3>;

// No real power for a step of a pose PITA (docs/paper-notes.md N74). first()
// is the index of the first of two given neighbouring poses (0: A and B, 1: B
// and C; for P5 the pose whose log is missing); where() is empty for two
// given poses, "pose N" for P5's pose without a log, else "between ..." names
// the poses the construction formed; time()
// is the time for the steps made at each time.
class NoPosePitaPower : public NoSamBetweenPoses {
 public:
  NoPosePitaPower(const NoRealLogarithm& cause, std::size_t first, std::string where, std::optional<double> t)
      : NoSamBetweenPoses(cause, first, std::move(where)), time_(t) {}
  const std::optional<double>& time() const { return time_; }

 private:
  std::optional<double> time_;
};

// T(X, A, B, s) = (B o A^-1)^s o X, with `morph` the SAM from A to B.
template <class Pose>
Pose transported(const SteadyAffineMorph<Pose>& morph, const Pose& X, double s) {
  return compose(morph.powers().at(s), X);
}

// T(X, A, B, s) (builds the SAM; use transported for many s). Throws
// NoRealLogarithm as SteadyAffineMorph does.
template <class Pose>
Pose steady_affine_transport(const Pose& X, const Pose& A, const Pose& B, double s) {
  return transported(SteadyAffineMorph<Pose>(A, B), X, s);
}

// The SAM between two given neighbouring poses (either order): poses
// `first` and `first + 1` of the triple. Throws NoPosePitaPower.
template <class Pose>
SteadyAffineMorph<Pose> neighbours_morph(const Pose& from, const Pose& to, std::size_t first);

// The SAM between two poses a construction forms, `where` ("between the
// control pose L and B") at time t (nullopt for what is built once). Throws
// NoPosePitaPower.
template <class Pose>
SteadyAffineMorph<Pose> formed_morph(const Pose& from, const Pose& to, std::string_view where,
                                     std::optional<double> t = std::nullopt);

// The homogeneous log {log L, v} of pose `index` of a triple (P5). Throws
// NoPosePitaPower.
template <class Pose>
Pose pose_log(const Pose& pose, std::size_t index);

extern template SteadyAffineMorph<Affine2> neighbours_morph(const Affine2&, const Affine2&, std::size_t);
extern template SteadyAffineMorph<Affine3> neighbours_morph(const Affine3&, const Affine3&, std::size_t);
extern template SteadyAffineMorph<Affine2> formed_morph(const Affine2&, const Affine2&, std::string_view,
                                                        std::optional<double>);
extern template SteadyAffineMorph<Affine3> formed_morph(const Affine3&, const Affine3&, std::string_view,
                                                        std::optional<double>);
extern template Affine2 pose_log(const Affine2&, std::size_t);
extern template Affine3 pose_log(const Affine3&, std::size_t);

}  // namespace pita
