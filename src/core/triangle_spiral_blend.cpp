#include "core/triangle_spiral_blend.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/LU>

namespace pita {

namespace {

// The frame [p1 - p0, p2 - p0 | p0]: the affinity taking (0,0), (1,0), (0,1)
// to the points (any affine combination of its columns for rates).
Affine2 frame_of(const std::array<Point, 3>& p) {
  Affine2 F;
  F.L << (p[1] - p[0]).real(), (p[2] - p[0]).real(), (p[1] - p[0]).imag(), (p[2] - p[0]).imag();
  F.b << p[0].real(), p[0].imag();
  return F;
}

}  // namespace

TriangleSpiralBlend::TriangleSpiralBlend(const Affine2& from, const Affine2& to, const std::array<Point, 3>& reference)
    : reference_inverse_(inverse(frame_of(reference))) {
  // Between poses of opposite orientations the blended triangle would flatten
  // on the way (its signed area changes sign continuously).
  const double det = compose(to, inverse(from)).L.determinant();
  if (!std::isfinite(det) || !(det > 0.0)) {
    throw std::invalid_argument("the triangle spiral blend needs poses of the same orientation (det L > 0)");
  }
  std::array<Point, 3> end{};
  for (int j = 0; j < 3; ++j) {
    start_[j] = apply(from, reference[j]);
    end[j] = apply(to, reference[j]);
  }
  for (int j = 0; j < 3; ++j) {
    const Vector side = start_[(j + 1) % 3] - start_[j];
    const Vector side_end = end[(j + 1) % 3] - end[j];
    // PITA Eq. 17-18 with the principal angle (reading notes, docs/paper-notes.md N39).
    const Complex ratio = side_end / side;
    spirals_[j] = Twirl(start_[j], end[j] - start_[j], Complex{std::log(std::abs(ratio)), std::arg(ratio)});
  }
}

Point TriangleSpiralBlend::vertex(int j, double u) const {
  const int before = (j + 2) % 3;  // side j - 1 ends at vertex j
  return kSideWeight * apply_power(spirals_[j], u, start_[j]) +
         kSideWeight * apply_power(spirals_[before], u, start_[j]);
}

Vector TriangleSpiralBlend::vertex_velocity(int j, double u) const {
  const int before = (j + 2) % 3;
  return kSideWeight * power_velocity(spirals_[j], u, start_[j]) +
         kSideWeight * power_velocity(spirals_[before], u, start_[j]);
}

Affine2 TriangleSpiralBlend::through(const std::array<Point, 3>& points) const {
  // Linear in the points, so the same map takes vertex velocities to the pose's rate.
  return compose(frame_of(points), reference_inverse_);
}

Affine2 TriangleSpiralBlend::at(double u) const { return through({vertex(0, u), vertex(1, u), vertex(2, u)}); }

Affine2 TriangleSpiralBlend::velocity(double u) const {
  return through({vertex_velocity(0, u), vertex_velocity(1, u), vertex_velocity(2, u)});
}

}  // namespace pita
