// Every numeric threshold of the math core, named and justified in one place
// (habit copied from Sophus's small-angle branches).
#pragma once

namespace pita::limits {

// Twirl between two arrows (Eq. 17-19), Sec. 2.5.
// We evaluate T^t.x = a + e^{tL}(x - a) + phi_t(L) (b - a) with
// phi_t(L) = expm1(tL) / expm1(L) (READING-NOTES item 1). When |e^L - 1| falls
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

// LS- point motion (Eq. 26): the log-spiral through a, b, c needs b != a and
// c != b. When |b - a| or |c - b| is below this fraction of |b - a| + |c - b|
// the spiral degenerates and we fall back to the parabolic motion (Eq. 11).
inline constexpr double kLogSpiralDegenerate = 1e-12;

// -Pe vector motion (P7, P8; READING-NOTES item 13): v(tau) = alpha e^{k tau} +
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

}  // namespace pita::limits
