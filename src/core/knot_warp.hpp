// The time warp used by the PITAs whose construction assumes evenly spaced
// knots (P4, P7, P8; docs/paper-notes.md N11, N17).
//
// Our choice. With s = (t - a)/(c - a) and beta = (b - a)/(c - a), the warp
// u(t) sends a, b, c to 0, 1/2, 1. On [0, beta] and [beta, 1] it is quadratic,
//     u = 1/2 h(s/beta)                       for s <= beta,
//     u = 1/2 + 1/2 h((s - beta)/(1 - beta))  for s >= beta,
//     h(sigma) = sigma + kappa sigma (sigma - 1),   kappa = 2 beta - 1,
// which makes du/ds = 1 at b from both sides: the warp is C1, strictly
// increasing (du/ds >= min(beta, 1 - beta) / max(beta, 1 - beta) > 0), the
// identity for even knots (beta = 1/2, so P4, P7, P8 are then exactly the
// paper's), and symmetric: u(1 - s; 1 - beta) = 1 - u(s; beta), so PITA Eq. 41
// holds. Outside [a, c] it continues linearly with the end slopes, so every
// real t still maps to a finite parameter (extrapolation, Sec. 7.5).
// For knots that are not monotone (b outside (a, c), only reached by the
// order-independence test of PITA Eq. 42) the warp is the quadratic Lagrange map
// through (a, 0), (b, 1/2), (c, 1).
#pragma once

namespace pita {

double knot_warp(double a, double b, double c, double t);

}  // namespace pita
