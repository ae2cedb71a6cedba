// The perseverant (-Pe) machinery shared by P7 and P8 (Sec. 3.3, appendices E
// and F, docs/paper-notes.md N13).
//
// On the normalised time tau (tau = -1, 0, 1 at the knots) the vector of the
// moving zero-turn arrow obeys v'' = K v with a constant complex K = k^2: its
// acceleration is constant in the local frame. Solving the boundary-value
// problem v(-1) = v_a, v(0) = v_b, v(1) = v_c gives
//     cosh k = kappa = (v_a + v_c) / (2 v_b),
//     v(tau) = v_b + (v_a + v_c - 2 v_b)/2 Q(tau) + (v_c - v_a)/2 S(tau),
// with the three even functions of k (hence entire functions of K)
//     S(tau) = sinh(k tau) / sinh k,                       S -> tau,
//     Q(tau) = (cosh(k tau) - 1)/(cosh k - 1),             Q -> tau^2,
//     R(tau) = (S(tau) - tau)/(cosh k - 1),                R -> tau (tau^2 - 1)/3,
// whose limits as k -> 0 give the parabola (P7) and the cubic (P8) of item 13.
// k is the principal acosh (Re k >= 0, Im k in [0, pi]); its branch cut, real
// kappa < -1, is where P7 and P8 pop. At kappa = -1 (sinh k = 0) there is no
// solution and construction throws MotionDomainError.
#pragma once

#include "core/arrow.hpp"

namespace pita {

class Perseverant {
 public:
  // v_a, v_b, v_c are the zero-turn vectors of the three keyframes.
  Perseverant(Vector va, Vector vb, Vector vc);

  struct Values {
    Complex S, Q, R;
  };
  // The series in K while |K| max(1, tau^2) < kPerseverantSeries, else the
  // closed forms. Both forms are public so the tests can compare them.
  Values values(double tau) const;
  Values series_values(double tau) const;
  Values closed_form_values(double tau) const;
  Complex S(double tau) const { return values(tau).S; }
  Complex Q(double tau) const { return values(tau).Q; }
  Complex R(double tau) const { return values(tau).R; }
  Complex kappa() const { return kappa_; }
  Complex k() const { return k_; }
  // The vector motion -Pe itself.
  Vector vector_at(double tau) const;

 private:
  bool use_series(double tau) const;
  Vector va_, vb_, vc_;
  Complex kappa_;
  Complex k_;
  Complex K_;
  Complex sinh_k_;
  Complex sinh_half_k_;
  Complex cosh_k_m1_;  // cosh k - 1 = 2 sinh^2(k/2)
};

}  // namespace pita
