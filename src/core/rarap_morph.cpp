#include "core/rarap_morph.hpp"

namespace pita {

RarapMorph::RarapMorph(const Affine2& from, const Affine2& to, const Eigen::Vector2d& centre)
    : from_(from),
      decomposition_(arap_decomposition(compose(to, inverse(from)).L)),
      g0_(apply(from, centre)),
      g1_(apply(to, centre)) {}

Eigen::Matrix2d RarapMorph::linear(double u) const {
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  return rotation(u * decomposition_.angle) * ((1.0 - u) * I + u * decomposition_.stretch);
}

Affine2 RarapMorph::at(double u) const {
  const Eigen::Matrix2d Lu = linear(u);
  return {Lu * from_.L, Lu * (from_.b - g0_) + barycentre(u)};
}

Affine2 RarapMorph::velocity(double u) const {
  // d/du [R(u theta) K(u)] = theta J R(u theta) K(u) + R(u theta) (S - I),
  // K(u) = (1 - u) I + u S, J the rotation by pi/2 (dR(a)/da = J R(a)).
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  Eigen::Matrix2d J;
  J << 0.0, -1.0, 1.0, 0.0;
  const double theta = decomposition_.angle;
  const Eigen::Matrix2d R = rotation(u * theta);
  const Eigen::Matrix2d K = (1.0 - u) * I + u * decomposition_.stretch;
  const Eigen::Matrix2d rate = theta * J * R * K + R * (decomposition_.stretch - I);
  return {rate * from_.L, rate * (from_.b - g0_) + (g1_ - g0_)};
}

}  // namespace pita
