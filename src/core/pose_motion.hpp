// The motions of a pose scene (SAM paper): timed affine poses interpolated by
// a SAM, a polySAM, a Bezier SAM, the SAM bi-arc, or linear interpolation of
// the matrices (the "linear" column of Fig. 2: every vertex moves on a
// straight line at constant speed), and the other morphs Fig. 2 compares
// with SAM (Sec. 2.4): rARAP, ASAP (log spiral and linear residue) and TSB
// (blend of the sides' log spirals), and Alexa's log-matrix blend that Sec.
// 3.3.2 and Figs. 4, 5 compare with SAM. What registry.hpp is to the PITAs.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/affine2.hpp"
#include "core/affine_power.hpp"
#include "core/log_matrix_blend.hpp"
#include "core/pose_method.hpp"
#include "core/rarap_morph.hpp"
#include "core/sam_family_motion.hpp"
#include "core/sam_splines.hpp"
#include "core/spiral_residue_morph.hpp"
#include "core/triangle_spiral_blend.hpp"

namespace pita {

// The reference triangle of a pose scene when it gives none: (0,0), (1,0), (0,1).
std::array<Point, 3> default_reference_triangle();

using TimedPose = TimedPoseOf<Affine2>;

// The motion through the poses (as many as the method takes, knots strictly
// increasing). Throws NoSamBetweenPoses from the constructor when a SAM the
// method needs does not exist: for SAM and polySAM those between consecutive
// poses; for the Bezier SAM also those between the intermediate poses, which
// the constructor checks at 65 parameters in [0, 1] (Sec. 5.3 notes they
// usually exist when the consecutive ones do); for the bi-arc those from each
// pose to the next and those of its Bezier arcs, checked the same way.
//
// Times: SAM and polySAM map [t_i, t_{i+1}] onto [0, 1] per span; the Bezier
// SAM maps [t_0, t_n] onto [0, 1]; the bi-arc maps [t_0, t_1] onto [0, 1/2]
// and [t_1, t_2] onto [1/2, 1], so that it passes through the middle pose at
// its knot. Times outside the knots extrapolate (SAM, polySAM, linear) or
// are clamped (Bezier, bi-arc, whose arcs are not defined beyond).
//
// rARAP, ASAP and TSB (Fig. 2 b-d, two poses, extrapolated outside the knots)
// need the reference triangle: rARAP and ASAP move its barycentre, TSB blends
// the spirals of its sides (docs/paper-notes.md N39); they throw
// std::invalid_argument when the two poses have opposite orientations.
//
// Alexa (Sec. 3.3.2, Figs. 4, 5; two poses, extrapolated outside the knots)
// is e^{(1-u) log B + u log C} of the absolute poses (core/log_matrix_blend.hpp,
// docs/paper-notes.md N45); it throws NoSamBetweenPoses (first 0) when either
// pose has no real logarithm.
//
// The four-point polySAM (Sec. 7.3, Fig. 13) subdivides its control poses
// `subdivisions` times with subdivide_four_point (a new pose at the middle
// time of each span) and is the polySAM through the result: it still passes
// through every control pose.
class PoseMotion {
 public:
  PoseMotion(PoseMethod method, std::vector<TimedPose> poses, int subdivisions = kDefaultSubdivisions,
             const std::array<Point, 3>& reference = default_reference_triangle());

  Affine2 at(double t) const;

  // The derivative dA/dt as an affinity-shaped pair (dL/dt, db/dt), so that
  // the velocity of the point A(t) p0 is apply(velocity(t), p0). Exact for
  // SAM and polySAM ((log A_span) A(t) / span duration, Sec. 2.3 (6)), for
  // linear, rARAP, ASAP, TSB and Alexa (the Frechet derivative of exp); for the Bezier SAM and the bi-arc a
  // fourth-order central difference (one-sided second order at the ends). At an interior knot, where a polySAM's
  // velocity jumps, the outgoing one; at the last, the incoming one.
  Affine2 velocity(double t) const;

  PoseMethod method() const { return method_; }
  const std::vector<TimedPose>& poses() const { return poses_; }

 private:
  Affine2 evaluate(double t) const;

  PoseMethod method_;
  std::vector<TimedPose> poses_;
  std::optional<SamFamilyMotion<Affine2>> family_;  // SAM, polySAM, Bezier, bi-arc, linear, four-point
  std::optional<std::variant<RarapMorph, SpiralResidueMorph, TriangleSpiralBlend, LogMatrixBlend>>
      morph_;  // Fig. 2 b-d, Alexa
};

}  // namespace pita
