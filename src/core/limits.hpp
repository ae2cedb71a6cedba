// Every numeric threshold of the math core, named and justified in one place
// (habit copied from Sophus's small-angle branches).
#pragma once

namespace pita::limits {

// Twirl between two arrows (PITA Eq. 17-19), Sec. 2.5.
// We evaluate T^t.x = a + e^{tL}(x - a) + phi_t(L) (b - a) with
// phi_t(L) = expm1(tL) / expm1(L) (docs/paper-notes.md N1). When |e^L - 1| falls
// below this value the fixed point f = a - (b - a)/(e^L - 1) is numerically at
// infinity and we use the translation fallback phi_t = t (its exact limit as
// L -> 0). Near L = 0 the fallback differs from the exact formula by at most
// |t (t - 1) L / 2| |b - a| ~ 1e-12 |b - a|, so frames stay continuous across
// the threshold (tests/core/test_twirl.cpp checks both sides). When L tends to
// 2*pi*i*k with k != 0 (equal magnitudes, windings a whole number of turns
// apart, distinct origins) no twirl maps A to B at all: the same fallback then
// spins the vector by e^{tL} while the origin moves on the segment; this is
// the "isolated singular case" of Sec. 4.1 and is the one place where a steady
// morph is not continuous in its keyframes.
inline constexpr double kTwirlTranslation = 1e-12;

// LS- point motion (PITA Eq. 26): the log-spiral through a, b, c needs b != a and
// c != b. When |b - a| or |c - b| is below this fraction of |b - a| + |c - b|
// the spiral degenerates and we fall back to the parabolic motion (PITA Eq. 11).
inline constexpr double kLogSpiralDegenerate = 1e-12;

// -Pe vector motion (P7, P8; docs/paper-notes.md N13): v(tau) = alpha e^{k tau} +
// beta e^{-k tau} with cosh k = kappa = (v_a + v_c) / (2 v_b). At kappa = -1
// (v_a + v_c = -2 v_b, e.g. A and C both pointing against B with the same
// magnitude) sinh k = 0 and the boundary-value problem has no solution; near it
// the motion's amplitude grows like 1/sqrt(|kappa + 1|). Within this distance
// of -1 (amplitude ~ 1e5 |v_b|) the motion is refused with a domain error.
inline constexpr double kPerseverantSingular = 1e-10;

// P8's stable remainder R(tau) = (sinh(k tau)/sinh k - tau) / (cosh k - 1) is
// summed as a power series in K = k^2 while |K| max(1, tau^2) is below this
// bound (30 terms reach full precision); beyond it the closed form loses at
// most one digit to cancellation.
inline constexpr double kPerseverantSeries = 0.5;

// Persistent Affine Motion (pam.hpp, PITA Eq. 37-39): the matrix functions of the
// 2x2 matrix K = L_B^-1 (L_A + L_C)/2 (eigenvalues m +- s, s^2 real).
//
// The scalar functions C, S, Q, R of kappa (and acosh^2 for E) are summed as
// Taylor series in x = kappa - 1 (hypergeometric, radius 2) while
// |x| max(1, tau^2) is below this bound: every term is then at most 3/8 of the
// one before (about 35 terms to full precision), and beyond it the closed
// forms in k = acosh kappa lose at most one digit to cancellation in S - tau.
inline constexpr double kPamSeries = 0.25;

// Imaginary step h used when K has a double (or a numerically double)
// eigenvalue m: the Sylvester coefficient is then the derivative
// phi'(m) = Im phi(m + i h) / h + O(h^2) (complex step, exact to rounding for
// h this small; phi is real on the real axis right of -1).
inline constexpr double kPamComplexStep = 1e-20;

// Two real eigenvalues m +- s closer than this fraction of their distance
// m + 1 to the singularity kappa = -1: the divided difference
// (phi(m + s) - phi(m - s)) / (2 s) would lose log10(1/fraction) digits, so
// we extrapolate it from two complex steps, 2 phi'(m) - Im phi(m + i s) / s,
// whose error is about phi^(5)(m) s^4 / 60. At 5e-4 both errors are about
// 4e-13 relative to phi'.
inline constexpr double kPamCloseEigenvalues = 5e-4;

// K has the eigenvalue -1 (sinh k = 0, no solution; the PAM analogue of
// kPerseverantSingular, with the same value so that P8 and PAM refuse the
// same similarities).
inline constexpr double kPamSingular = 1e-10;

// Complex eigenvalues m +- i t with m < -1 and t below this fraction of |m|
// lie on acosh's branch cut for all practical purposes: the Sylvester
// coefficient grows like 1/t, so rounding in K (~1e-16 |K|) would give errors
// of 1e-16/t relative. We refuse them (P8 takes the upper side of the cut,
// which an affinity, having no orientation of its own, cannot).
inline constexpr double kPamBranchCut = 1e-8;

// The middle affinity B must be invertible: |det L_B| above this fraction of
// |L_B|_F^2 (the determinant of a rotation-scaling is |L|_F^2 / 2).
inline constexpr double kPamSingularMiddle = 1e-12;

// ------------------------------------------------------------------ EAR
// Steady Affine Morphs (affine_power.hpp): the case selection of the SAM
// paper's appendix A.5 (Algorithm 1), with tolerances where the paper writes
// ==, and the switches between formulas that compute the same A^t.

// S2: L has real negative eigenvalues (delta >= 0, r < 0) and is within this
// relative distance of a uniform scaling by a negative factor -rho (a
// rotation by pi with uniform scale): max |L - r I| entry <= kHalfTurn * |r|,
// r = trace/2. Such L get the log log(rho) I + pi J (the rotation by +pi,
// docs/paper-notes.md N15, N23), although beyond exact -rho I their eigenvalues are
// two distinct negatives or a negative Jordan block (no real log): the
// tolerance absorbs the rounding of A = C o B^-1 (seen up to 1.5e-14 for
// half turns built in doubles from scaled poses), with room to spare.
// Complex eigenvalues are never snapped: a rotation by pi - 1e-15 is G1 with
// the principal angle, and so is a rotation by -pi + 1e-15 (angle -pi + 1e-15),
// so that A^t is continuous in A everywhere but across the branch cut itself.
// Beyond the tolerance, real negative eigenvalues are G3.
inline constexpr double kHalfTurn = 1e-12;

// S1: an eigenvalue lambda of L with |lambda - 1| <= kUnitEigenvalue. The
// affinity then has no unique fixed point (a pure translation, a shear, or a
// scaling along one direction combined with a translation along another,
// appendix A.4), so fixed_point() says so. A^t itself is continuous across
// this boundary: it is never computed through the fixed point near it.
inline constexpr double kUnitEigenvalue = 1e-12;

// The translation part of A^t is g_t(L) b with g_t(lambda) =
// (lambda^t - 1)/(lambda - 1) (SAM Eq. 9 rewritten so that it stays exact at
// lambda = 1; docs/paper-notes.md N15 asks for expm1). Three formulas compute
// g_t(L), each where it is exact to rounding:
//  - the binomial series sum_{n>=1} C(t, n) E^{n-1}, E = L - I, while the
//    spectral radius of E is at most kUnitSeriesRadius (near the identity:
//    translations, shears, S1); the series converges like n 4^-n, ~30 terms;
//  - through the fixed point, (I - L^t) q with q = (I - L)^-1 b (SAM Eq. 9), when
//    both eigenvalues are at least kUnitFixedPointDistance from 1 (then
//    I - L is well conditioned);
//  - otherwise by the divided difference of g_t at the two eigenvalues, which
//    are then real and at least 1/8 apart (one within 1/8 of 1, the other
//    more than 1/4 from it).
// |t| above kUnitSeriesMaxTime is reached by squaring A^{t/2^k} (the series
// loses (1 + radius)^|t| to cancellation).
inline constexpr double kUnitSeriesRadius = 0.25;
inline constexpr double kUnitFixedPointDistance = 0.125;
inline constexpr double kUnitSeriesMaxTime = 16.0;

// The log coefficient k (log L = c I + k (L - r I)) is summed as the series
// sum u^n/(2n+1), u = delta/r^2, while |u| is below this bound (r > 0, around
// the double eigenvalue where G1 meets G2; 12 terms reach full precision).
// Beyond it the closed forms atan2(omega, r)/omega (G1) and atanh(s/r)/s (G2)
// lose nothing to cancellation.
inline constexpr double kDoubleEigenvalueSeries = 1e-2;

// The functions cosh(sqrt z) and sinh(sqrt z)/sqrt z of e^{tC} (SAM Eq. 11
// written with the discriminant z = t^2 gamma of tC) are summed as series
// while |z| is below this bound.
inline constexpr double kExpSeries = 1e-2;

// e^{tC} with real eigenvalues c +- sigma of C = log L: through the spectral
// projectors (I +- M/sigma)/2 when sigma exceeds this (the eigenvalues of L
// differ by a factor e^{2 sigma} > 2.7), where cosh/sinh would cancel; below,
// by cosh and sinh(sqrt z)/sqrt z, which stay exact as sigma -> 0 (Jordan
// blocks) where the projectors would not.
inline constexpr double kExpProjectors = 0.5;

// ------------------------------------------------------------ EAR in 3D
// Real powers of 3D affinities (affine_power_of_space.hpp, SAM paper appendix A.6,
// docs/paper-notes.md N58). The 2D block reuses every threshold above; the
// corner's series uses kUnitSeriesRadius and kUnitSeriesMaxTime, the fixed
// point kUnitEigenvalue, as in 2D.
//
// The three computed eigenvalues of L within this fraction of the largest
// magnitude of each other (three reals, or a real one and a complex pair
// that rounding made of a triple one) are one triple eigenvalue, whose
// eigenvector is sought at tr L / 3: a triple root of the characteristic
// cubic is only good to about the cube root of rounding times
// |L - tr L/3 I|^(2/3) (a shear beside 1 with entry 1.3, rotated, gave roots
// 1e-5 apart), while the mean of the three is exact to rounding. The factor
// 10 is room. A genuinely distinct cluster within 1e-4 loses nothing: the
// split only needs a vector with a small residual |L u - (u.L u) u|, which
// inverse iteration from that start provides (affine_power_of_space.cpp,
// eigenvector()). The plane block within kHalfTurn of -rho I is set to
// -rho I, as 2D snaps its real negative eigenvalues.
inline constexpr double kEigenvalueCluster = 1e-4;

// EAR in 3D near the identity (spectral radius of L - I at most
// kUnitSeriesRadius): when the column the split drops exceeds this many times
// |L|_F, the split's eigenvector is not one to working precision, and L^t is
// summed as the binomial series instead (docs/paper-notes.md N80). A split
// that inverse iteration finished leaves at most 4 ulps of |L|.
inline constexpr double kSplitResidual = 64.0 * 0x1p-52;

// log(): the lean row comes from the Sylvester equation (log T commutes with
// T) when lambda is at least this fraction of the largest eigenvalue modulus
// away from both eigenvalues of the plane block, so that lambda I - M is well
// conditioned; closer, the 2D EAR's l(M / lambda) / lambda, exact in the
// confluent limit. 0.1 is a round value, checked only on the random tests of
// test_affine_power_of_space.cpp, not tuned (N58).
inline constexpr double kSylvesterLeanGap = 0.1;

// log() ends with up to kLogRefineSteps Newton steps on exp(X) = A whose
// residual is computed in long double (N58, "refinement"): taken only while
// exp(X) misses A by more than kLogRefineResidual (relative,
// |.|_F / max(|H|_F, 1) on the homogeneous matrices); a step that moves X
// more than kLogRefineStep |X|_F from the split's log ends them (a Newton
// step near a singular Frechet derivative, as at rotations by pi, must not
// move the log to another branch), and the log kept is the one with the
// smallest residual after rounding to double. 1e-13 is a tenth of the 1e-12
// the log is held to; the step bound is far above any correction of
// rounding (1e-12 relative) and far below any other log. Six steps: on
// 3000 random affinities at condition numbers to 1.4e8 one step left 68
// beyond 1e-12, three 18, six 5 (worst 1.65e-12; all but one within 8 times
// the error of the correctly rounded log). The steps converge linearly, not
// quadratically: the derivative, an exp of an 8x8 non-normal matrix, is
// itself only good to a few digits there.
inline constexpr double kLogRefineResidual = 1e-13;
inline constexpr double kLogRefineStep = 1e-8;
inline constexpr int kLogRefineSteps = 6;

// ---------------------------------------------------------------- time warps
// Arc-length reparameterisation (arc_length.hpp; the chapter's Sec. 3.2.1).
//
// The speed |P'(tau)| is an eighth-order central difference with this step, as
// a fraction of the table interval being sampled: truncation ~ (step)^8 ~ 1e-16
// and rounding ~ 1e-16 |P| / (step width |P'|), relative, so about 1e-12 for
// paths whose coordinates are of the size of their length (far from the
// origin, rounding grows with |P| / length). Within four steps of an end
// (motions clamped outside their knots must not be sampled beyond them) a
// one-sided difference of order 4 with a tenth of the step.
inline constexpr double kDerivativeStep = 1e-2;

// An interval of the arc-length table is accepted when its two checks (whole
// against halves, interpolated midpoint against the left half) agree within
// this fraction of the total length times the interval's share of [from, to]:
// above the finite differences' rounding (~1e-12, so refinement stops) and a
// hundredth of the 1e-9 of the path length that lengths must be right to.
inline constexpr double kArcLengthTolerance = 1e-11;

// The table starts from this many equal intervals (so that no feature between
// the first Gauss nodes is missed) and halves an interval at most this deep
// (beyond, the finite differences' rounding would grow faster than the
// quadrature improves).
inline constexpr int kArcLengthInitialCells = 16;
inline constexpr int kArcLengthMaxDepth = 8;
// ... nor below this fraction of the size of the points (the largest |P| and
// |P - P(from)|): the rounding of the motion's evaluation, through the finite
// differences, makes each interval's length uncertain by about 1e-13 |P|
// whatever its width, so a short span far from the origin (a span of a long
// track paced per span) could never meet a tolerance relative to its own
// small length, and would refine to kArcLengthMaxDepth everywhere
// (docs/paper-notes.md N20). 1e-13 was not enough (a 100-keyframe track still
// took 11 s); a rule that stopped where the disagreement stopped shrinking
// was, but cost the timing oracle its 1e-8 near bursts of speed.
inline constexpr double kArcLengthNoise = 1e-12;
// At most this many intervals in all (a path whose speed is noisy at the
// tolerance, e.g. far from the origin, stops refining there).
inline constexpr int kArcLengthMaxCells = 1 << 14;

// A path shorter than this fraction of the largest |P - P(from)| plus the
// largest |P| (rounding of the finite differences makes a still point appear
// to move by ~1e-13 |P|) has zero length: arc length cannot be spread over
// time, and the scene is refused.
inline constexpr double kArcLengthZero = 1e-10;

// Keyframe tracks (core/chains/chain.hpp): Neville's recursion costs
// (n - 2)(n - 3)/2 steady blends per frame and, like every global polynomial
// interpolation, swings ever wider as n grows; past this many keyframes use
// the local "blend" chain.
inline constexpr int kMaxNevilleKeyframes = 64;

// ---------------------------------------------------------------- point curves
// The Neville-type curves through n timed points (point_curves.hpp: the
// uniform and centripetal Neville interpolations and the log-spiral blend of
// PITA Sec. 7.6, Fig. 29; docs/paper-notes.md N34) evaluate a triangle of
// n (n - 1) / 2 blends at every time, and the Neville polynomials have degree
// n - 1. At most this many points: 2016 blends per evaluation, a bound on work
// (a scene cannot make one frame cost more than that). It is not a promise of
// accuracy: at evenly spaced parameters a polynomial of degree n - 1 amplifies
// rounding of its points by up to the Lebesgue constant, about
// 2^n / (e n ln n), which passes 1e7 (the curve then good to only 1e-9 of its
// size) near 32 points; beyond that the polynomial curves are of no use, and
// the limit only keeps them cheap.
inline constexpr int kMaxNevillePoints = 64;

// ---------------------------------------------------- derivatives of D(t)
// Velocities and accelerations of arrow motions (analysis/frame_derivatives.hpp,
// docs/paper-notes.md N40) are fourth-order differences with the step
// h = (knot span) / kDerivativeStepsPerSpan: truncation ~ (h |L|)^4 / 30
// (about 1e-10 of the value for a turn of 1 rad per span), rounding of
// a second derivative ~ 1e-16 |x| / h^2 (about 1e-11).
inline constexpr double kDerivativeStepsPerSpan = 256.0;
// An instantaneous center (core/instant_center.hpp) farther than this many
// arrow lengths |v| from p is taken as none: the motion is then a translation
// to within rounding, and a segment to the center would fill the figure.
inline constexpr double kFarCenter = 1e6;

// ------------------------------------------------------ grazing points
// The grazing point of a moving edge (core/grazing_point.hpp, SAM paper
// SAM Eq. 8) is s = -n.v(from) / n.(dL d) along the edge. When the edge's
// direction does not turn (a translation, or a stretch along the edge) the
// denominator vanishes and every point of its line grazes, or none; a point
// farther than this many edge lengths from the edge's start is taken as
// none (it would fill the figure, like kFarCenter's centers).
inline constexpr double kFarGrazingPoint = 1e6;

// Series and iterations (perseverant.cpp, pam.cpp, affine_power.cpp,
// affine_power_of_space.cpp) stop when a term falls below this fraction of the sum
// (or of the sum's scale): two orders of magnitude under double's unit
// roundoff, 1.1e-16, so that the terms left out cannot change the sum.
inline constexpr double kSeriesTermCutoff = 1e-18;

// A floor that keeps a scale strictly positive (a divisor, or the size a
// relative test compares against) without changing any scale a motion can
// have: far below every number pita evaluates, far above the least double.
inline constexpr double kTinyScale = 1e-300;

// Coordinates and magnitudes below this in absolute value cannot overflow
// when q = p + m e^{iw} is formed (motion/scene_motion.cpp checks frames
// against it before computing q).
inline constexpr double kHugeCoordinate = 1e300;

// Finite-difference steps, each a fraction of the span of time it
// differences (the stencils are written beside each use):
// - the time warp's rate d tau / d t (motion/scene_motion.cpp), a central
//   difference: the eases and the arc-length inverse are smooth in a span;
inline constexpr double kWarpRateStep = 1e-6;
// - the velocity of the Bezier and bi-arc SAMs, which has no closed form
//   (sam_family_motion.cpp): five-point stencil inside, second order at ends;
inline constexpr double kPoseVelocityStep = 1e-3;
// - the relative acceleration of the steadiness measure (steadiness.cpp), a
//   fraction of one time sample of its midpoint rule.
inline constexpr double kSteadinessStep = 1e-4;
// - the accelerations of the audit's "perseverant" probe (analysis/
//   properties.cpp), a fraction of the motion's span (A to C).
inline constexpr double kPerseveranceStep = 1e-3;

// Two real negative eigenvalues of a 3x3 linear part closer than this, relative
// to |L|_F, are taken as one double eigenvalue, which EAR then decides exactly
// (analysis/sam3d_existence.cpp): farther apart, no real log exists.
inline constexpr double kDoubleNegativeEigenvalue = 1e-6;

}  // namespace pita::limits
