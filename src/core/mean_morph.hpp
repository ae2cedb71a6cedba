// Non-steady variants of the SMA (Sec. 2.7, Fig. 4 and D.36).
#pragma once

#include "core/arrow.hpp"
#include "core/mean_kind.hpp"

namespace pita {

// mean(1, lambda, t) for the chosen Pythagorean mean, minus 1, computed without
// cancellation (log_lambda = ln lambda).
double mean_of_one_and_minus_one(MeanKind kind, double log_lambda, double t);

// The SMA M(A, B, t) splits, about the fixed point f of T_{A,B}, into two
// morphs: of the vectors (A.vec -> B.vec) and of the radii (A.p - f -> B.p - f).
// Both turn by t (B.w - A.w) and scale by lambda^t = WGM(1, lambda, t). This
// variant scales the radius by path_mean(1, lambda, t) and the magnitude by
// magnitude_mean(1, lambda, t) instead. With both geometric it is the SMA.
// Written relative to A.p, p(t) = A.p + (s(t) - 1)/(e^L - 1) (B.p - A.p) with
// s(t) = e^{it theta} path_mean(1, lambda, t), so it stays finite as the twirl
// tends to a translation.
Arrow mean_morph(const Arrow& A, const Arrow& B, double t, MeanKind path_mean, MeanKind magnitude_mean);

}  // namespace pita
