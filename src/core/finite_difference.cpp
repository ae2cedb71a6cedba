#include "core/finite_difference.hpp"

namespace pita {

// Fornberg, "Generation of finite difference formulas on arbitrarily spaced
// grids", Math. Comp. 51 (1988), the recurrence of his Table 1.
std::vector<std::vector<double>> fornberg_weights(double x0, const std::vector<double>& nodes, int max_order) {
  const std::size_t n = nodes.size();
  const std::size_t orders = static_cast<std::size_t>(max_order) + 1;
  std::vector<std::vector<double>> c(orders, std::vector<double>(n, 0.0));
  if (n == 0) return c;
  double c1 = 1.0;
  double c4 = nodes[0] - x0;
  c[0][0] = 1.0;
  for (std::size_t i = 1; i < n; ++i) {
    const std::size_t mn = std::min(i, orders - 1);
    double c2 = 1.0;
    const double c5 = c4;
    c4 = nodes[i] - x0;
    for (std::size_t j = 0; j < i; ++j) {
      const double c3 = nodes[i] - nodes[j];
      c2 *= c3;
      if (j == i - 1) {
        for (std::size_t k = mn; k >= 1; --k) {
          c[k][i] = c1 * (static_cast<double>(k) * c[k - 1][i - 1] - c5 * c[k][i - 1]) / c2;
        }
        c[0][i] = -c1 * c5 * c[0][i - 1] / c2;
      }
      for (std::size_t k = mn; k >= 1; --k) {
        c[k][j] = (c4 * c[k][j] - static_cast<double>(k) * c[k - 1][j]) / c3;
      }
      c[0][j] = c4 * c[0][j] / c3;
    }
    c1 = c2;
  }
  return c;
}

}  // namespace pita
