#include "core/spiral_residue_morph.hpp"

#include <cmath>

namespace pita {

namespace {

// Multiplication by the complex number z as a 2x2 matrix.
Eigen::Matrix2d matrix_of(Complex z) {
  Eigen::Matrix2d M;
  M << z.real(), -z.imag(), z.imag(), z.real();
  return M;
}

Point point_of(const Eigen::Vector2d& x) { return {x.x(), x.y()}; }
Eigen::Vector2d vector_of(Point p) { return {p.real(), p.imag()}; }

}  // namespace

SpiralResidueMorph::SpiralResidueMorph(const Affine2& from, const Affine2& to, const Eigen::Vector2d& centre)
    : from_(from), g0_(apply(from, centre)) {
  const Eigen::Matrix2d L = compose(to, inverse(from)).L;
  const ArapDecomposition d = arap_decomposition(L);
  const double s = std::sqrt(d.singular(0) * d.singular(1));  // sqrt(det L)
  residue_ = d.stretch / s;
  const Eigen::Vector2d g1 = apply(to, centre);
  spiral_ = Twirl(point_of(g0_), point_of(g1 - g0_), Complex{std::log(s), d.angle});
}

Affine2 SpiralResidueMorph::at(double u) const {
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  // Sigma^u (y) = e^{uL} (y - g0) + Sigma^u (g0), L = ln s + i theta.
  const Eigen::Matrix2d Lu = matrix_of(std::exp(u * spiral_.log())) * ((1.0 - u) * I + u * residue_);
  const Eigen::Vector2d centre = vector_of(apply_power(spiral_, u, point_of(g0_)));
  return {Lu * from_.L, Lu * (from_.b - g0_) + centre};
}

Affine2 SpiralResidueMorph::velocity(double u) const {
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  const Complex e = std::exp(u * spiral_.log());
  const Eigen::Matrix2d rate =
      matrix_of(spiral_.log() * e) * ((1.0 - u) * I + u * residue_) + matrix_of(e) * (residue_ - I);
  const Eigen::Vector2d centre_rate = vector_of(power_velocity(spiral_, u, point_of(g0_)));
  return {rate * from_.L, rate * (from_.b - g0_) + centre_rate};
}

}  // namespace pita
