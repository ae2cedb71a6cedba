#include "core/pose_pitas/morph_and_transport.hpp"

#include <string>

#include "core/number_text.hpp"

namespace pita {
namespace {

// EAR's own reason for A = to o from^-1 (only called when the SAM failed).
template <class Pose>
NoRealLogarithm raw_reason(const Pose& from, const Pose& to) {
  try {
    static_cast<void>(AffinePowers<Pose>(compose(to, inverse(from))));
  } catch (const NoRealLogarithm& error) {
    return error;
  }
  return NoRealLogarithm("no real power", RootCase::G3);  // not reached
}

template <class Pose>
bool mirrored(const Pose& from, const Pose& to) {
  const Pose A = compose(to, inverse(from));
  return !(A.L.determinant() > 0.0) && A.L.allFinite();
}

}  // namespace

// docs/paper-notes.md N74: the wording of the refusals.
template <class Pose>
SteadyAffineMorph<Pose> neighbours_morph(const Pose& from, const Pose& to, std::size_t first) {
  try {
    return SteadyAffineMorph<Pose>(from, to);
  } catch (const NoRealLogarithm&) {
    const NoRealLogarithm raw = raw_reason(from, to);
    if (mirrored(from, to)) throw NoPosePitaPower(no_sam_between_poses(raw, true), first, "", std::nullopt);
    throw NoPosePitaPower(NoRealLogarithm(std::string("no SAM exists between these poses: A = C o B^-1 has no real "
                                                      "power (") +
                                              raw.what() +
                                              "); a pose PITA needs one between neighbouring poses: move the "
                                              "middle pose so that it turns from each neighbour by less than pi",
                                          raw.root_case()),
                          first, "", std::nullopt);
  }
}

template <class Pose>
SteadyAffineMorph<Pose> formed_morph(const Pose& from, const Pose& to, std::string_view where,
                                     std::optional<double> t) {
  try {
    return SteadyAffineMorph<Pose>(from, to);
  } catch (const NoRealLogarithm&) {
    const NoRealLogarithm raw = raw_reason(from, to);
    std::string place(where);
    if (t) place += " at t = " + number_text::g6(*t);
    if (mirrored(from, to)) {
      // Real powers of orientation-preserving poses preserve orientation: a
      // formed pair that looks mirrored lost its sign to rounding (N74).
      throw NoPosePitaPower(NoRealLogarithm("the poses the construction forms are too ill-conditioned for double "
                                            "precision: rounding gave their ratio the determinant " +
                                                number_text::g6(compose(to, inverse(from)).L.determinant()) +
                                                "; times nearer the knots, or poses less stretched, avoid it",
                                            raw.root_case()),
                            0, place, t);
    }
    throw NoPosePitaPower(
        NoRealLogarithm(std::string("no SAM exists between the poses the construction forms (") + raw.what() +
                            "); poses whose neighbours turn by less than pi, or another "
                            "middle pose, avoid it",
                        raw.root_case()),
        0, place, t);
  }
}

template <class Pose>
Pose pose_log(const Pose& pose, std::size_t index) {
  try {
    return AffinePowers<Pose>(pose).log();
  } catch (const NoRealLogarithm& raw) {
    throw NoPosePitaPower(
        NoRealLogarithm(std::string("pose ") + std::to_string(index) + " has no real logarithm (" + raw.what() +
                            "); P5 blends the logs of the poses themselves: give each pose "
                            "a linear part that turns by less than pi and is not mirrored, "
                            "or use P4, P6 or P9, which need SAMs between neighbours only",
                        raw.root_case()),
        index, "pose " + std::to_string(index), std::nullopt);
  }
}

template SteadyAffineMorph<Affine2> neighbours_morph(const Affine2&, const Affine2&, std::size_t);
template SteadyAffineMorph<Affine3> neighbours_morph(const Affine3&, const Affine3&, std::size_t);
template SteadyAffineMorph<Affine2> formed_morph(const Affine2&, const Affine2&, std::string_view,
                                                 std::optional<double>);
template SteadyAffineMorph<Affine3> formed_morph(const Affine3&, const Affine3&, std::string_view,
                                                 std::optional<double>);
template Affine2 pose_log(const Affine2&, std::size_t);
template Affine3 pose_log(const Affine3&, std::size_t);

}  // namespace pita
