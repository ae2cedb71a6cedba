#include "analysis/existence.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/Dense>

#include "core/affine_power.hpp"

namespace pita::analysis {

namespace {}  // namespace

bool sam_exists(double a, double s) {
  Eigen::Matrix2d scaling;
  scaling << 1.0 / s, 0.0, 0.0, s;
  Eigen::Matrix2d rotation;
  rotation << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return select_case(rotation * scaling) != RootCase::G3;
}

double existence_boundary(double s) { return std::acos(-2.0 * s / (s * s + 1.0)); }

double existence_trapezoid(double s) { return (1.0 + s) * kPi / 2.0; }

ExistenceGrid classify_existence(int columns, int rows) {
  ExistenceGrid grid{columns, rows, std::vector<bool>(static_cast<std::size_t>(columns) * rows)};
  const double da = 2.0 * kPi / columns, ds = 1.0 / rows;
  for (int j = 0; j < rows; ++j) {
    const double s = (j + 0.5) * ds;
    for (int i = 0; i < columns; ++i) {
      const double a = -kPi + (i + 0.5) * da;
      grid.no_sam[static_cast<std::size_t>(j) * columns + i] = !sam_exists(a, s);
    }
  }
  return grid;
}

}  // namespace pita::analysis
