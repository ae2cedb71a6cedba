#include "core/knot_warp.hpp"

#include "core/lagrange_weights.hpp"

namespace pita {

double knot_warp(double a, double b, double c, double t) {
  const double s = (t - a) / (c - a);
  const double beta = (b - a) / (c - a);
  if (!(beta > 0.0 && beta < 1.0)) {
    const LagrangeWeights l = lagrange_weights(a, b, c, t);
    return 0.5 * l.y + l.z;
  }
  const double kappa = 2.0 * beta - 1.0;
  if (s < 0.0) return 0.5 * (1.0 - kappa) / beta * s;                        // slope u'(0)
  if (s > 1.0) return 1.0 + 0.5 * (1.0 + kappa) / (1.0 - beta) * (s - 1.0);  // slope u'(1)
  if (s <= beta) {
    const double sigma = s / beta;
    return 0.5 * (sigma + kappa * sigma * (sigma - 1.0));
  }
  const double sigma = (s - beta) / (1.0 - beta);
  return 0.5 + 0.5 * (sigma + kappa * sigma * (sigma - 1.0));
}

}  // namespace pita
