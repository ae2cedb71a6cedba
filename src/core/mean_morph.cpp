#include "core/mean_morph.hpp"

#include "core/complex_math.hpp"
#include "core/limits.hpp"

namespace pita {

double mean_of_one_and_minus_one(MeanKind kind, double log_lambda, double t) {
  switch (kind) {
    case MeanKind::arithmetic:  // (1 - t) + t lambda - 1 = t (lambda - 1)
      return t * std::expm1(log_lambda);
    case MeanKind::geometric:  // lambda^t - 1
      return std::expm1(t * log_lambda);
    case MeanKind::harmonic: {                               // 1 / ((1 - t) + t / lambda) - 1
      const double inv_lambda_m1 = std::expm1(-log_lambda);  // 1/lambda - 1
      const double den = 1.0 + t * inv_lambda_m1;            // (1 - t) + t/lambda
      return -t * inv_lambda_m1 / den;
    }
  }
  return 0.0;
}

Arrow mean_morph(const Arrow& A, const Arrow& B, double t, MeanKind path_mean, MeanKind magnitude_mean) {
  const double log_lambda = std::log(B.m / A.m);
  const double theta = B.w - A.w;
  const Complex L{log_lambda, theta};
  const Complex spin_m1 = expm1(Complex{0.0, t * theta});
  const Complex spin = spin_m1 + 1.0;
  // s(t) - 1 = (e^{it theta} - 1) + e^{it theta} (g(t) - 1)
  const Complex s_m1 = spin_m1 + spin * mean_of_one_and_minus_one(path_mean, log_lambda, t);
  const Complex den = expm1(L);
  const Complex progress = std::abs(den) < limits::kTwirlTranslation ? Complex{t, 0.0} : s_m1 / den;
  // The magnitude directly (not 1 + (mean - 1)), so that it keeps its relative
  // precision when it becomes tiny.
  double m = 0.0;
  switch (magnitude_mean) {
    case MeanKind::arithmetic:
      m = (1.0 - t) * A.m + t * B.m;
      break;
    case MeanKind::geometric:
      m = A.m * std::exp(t * log_lambda);
      break;
    case MeanKind::harmonic:
      m = 1.0 / ((1.0 - t) / A.m + t / B.m);
      break;
  }
  return {A.p + progress * (B.p - A.p), m, A.w + t * theta};
}

}  // namespace pita
