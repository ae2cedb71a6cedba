#include "core/perseverant.hpp"

#include <algorithm>

#include "core/limits.hpp"
#include "core/pitas/motion.hpp"

namespace pita {

Perseverant::Perseverant(Vector va, Vector vb, Vector vc) : va_(va), vb_(vb), vc_(vc) {
  kappa_ = (va + vc) / (2.0 * vb);
  // On the real axis, pick the upper side of acosh's cut deterministically
  // (a signed zero from rounding would otherwise choose the side).
  if (kappa_.imag() == 0.0) kappa_.imag(0.0);
  if (std::abs(kappa_ + 1.0) < limits::kPerseverantSingular) {
    throw MotionDomainError(
        "the perseverant (-Pe) vector motion of P7/P8 does not exist for these keyframes: "
        "their vectors satisfy v_A + v_C = -2 v_B (cosh k = -1)");
  }
  k_ = std::acosh(kappa_);
  K_ = k_ * k_;
  sinh_k_ = std::sinh(k_);
  sinh_half_k_ = std::sinh(0.5 * k_);
  cosh_k_m1_ = 2.0 * sinh_half_k_ * sinh_half_k_;
}

bool Perseverant::use_series(double tau) const {
  return std::abs(K_) * std::max(1.0, tau * tau) < limits::kPerseverantSeries;
}

namespace {

// Power series in K of the three even functions (see perseverant.hpp).
struct SeriesValues {
  Complex S, Q, R;
};

SeriesValues series(Complex K, double tau) {
  // sinh(k tau)/k = sum K^n tau^(2n+1)/(2n+1)!, sinh(k)/k = sum K^n/(2n+1)!
  // (cosh(k tau)-1)/K = sum_{n>=1} K^(n-1) tau^(2n)/(2n)!, (cosh k - 1)/K likewise.
  Complex sinh_tau{0.0}, sinh_one{0.0}, cosh_tau{0.0}, cosh_one{0.0}, rem{0.0};
  Complex Kn{1.0};              // K^n
  double tau_pow = tau;         // tau^(2n+1)
  double fact_odd = 1.0;        // (2n+1)!
  double fact_even = 2.0;       // (2n+2)!
  double tau_even = tau * tau;  // tau^(2n+2)
  for (int n = 0; n < 30; ++n) {
    sinh_tau += Kn * (tau_pow / fact_odd);
    sinh_one += Kn / fact_odd;
    cosh_tau += Kn * (tau_even / fact_even);
    cosh_one += Kn / fact_even;
    // R's numerator: sum_{n>=1} K^(n-1) (tau^(2n+1) - tau)/(2n+1)!; here index n+1.
    const double fact_next_odd = fact_odd * (2.0 * n + 2.0) * (2.0 * n + 3.0);
    rem += Kn * ((tau_pow * tau * tau - tau) / fact_next_odd);
    if (std::abs(Kn) * std::max(1.0, std::abs(tau_even)) / fact_odd < limits::kSeriesTermCutoff) break;
    Kn *= K;
    tau_pow *= tau * tau;
    tau_even *= tau * tau;
    fact_odd = fact_next_odd;
    fact_even *= (2.0 * n + 3.0) * (2.0 * n + 4.0);
  }
  return {sinh_tau / sinh_one, cosh_tau / cosh_one, rem / (sinh_one * cosh_one)};
}

}  // namespace

Perseverant::Values Perseverant::values(double tau) const {
  return use_series(tau) ? series_values(tau) : closed_form_values(tau);
}

Perseverant::Values Perseverant::series_values(double tau) const {
  const SeriesValues v = series(K_, tau);
  return {v.S, v.Q, v.R};
}

Perseverant::Values Perseverant::closed_form_values(double tau) const {
  // One complex exponential gives sinh(k tau / 2) and cosh(k tau / 2).
  const Complex e = std::exp(0.5 * tau * k_);
  const Complex ei = 1.0 / e;
  const Complex sh = 0.5 * (e - ei);
  const Complex ch = 0.5 * (e + ei);
  const Complex S = 2.0 * sh * ch / sinh_k_;
  const Complex r = sh / sinh_half_k_;
  return {S, r * r, (S - tau) / cosh_k_m1_};
}

Vector Perseverant::vector_at(double tau) const {
  const Values v = values(tau);
  return vb_ + 0.5 * (va_ + vc_ - 2.0 * vb_) * v.Q + 0.5 * (vc_ - va_) * v.S;
}

}  // namespace pita
