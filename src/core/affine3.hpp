// Affinities of space (SAM paper Sec. 2.1, appendix A.6): x -> L x + b, with a
// 3x3 linear part L and a translation b, the 3D sibling of Affine2.
//
// The verbs are the ones every value type of the core shares, under the same
// names, so that generic code calls any of them: apply, compose, inverse here;
// pow, log, exp in affine_power3.hpp (EAR in 3D). Affine2 (affine2.hpp) has the
// same six.
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>

namespace pita {

struct Affine3 {
  Eigen::Matrix3d L = Eigen::Matrix3d::Identity();  // linear part
  Eigen::Vector3d b = Eigen::Vector3d::Zero();      // translation

  static Affine3 identity() { return {}; }
};

// The image of point x: L x + b.
inline Eigen::Vector3d apply(const Affine3& A, const Eigen::Vector3d& x) { return A.L * x + A.b; }

// A o B: first B, then A (x -> A(B(x))), the order of homogeneous matrices.
inline Affine3 compose(const Affine3& A, const Affine3& B) { return {A.L * B.L, A.L * B.b + A.b}; }

// The inverse affinity x -> L^-1 (x - b). Precondition: L invertible (no
// check: a singular L gives non-finite entries).
inline Affine3 inverse(const Affine3& A) {
  const Eigen::Matrix3d Li = A.L.inverse();
  return {Li, -Li * A.b};
}

// The 4x4 homogeneous matrix [[L, b], [0, 1]] and back (its last row is
// ignored).
inline Eigen::Matrix4d homogeneous(const Affine3& A) {
  Eigen::Matrix4d H = Eigen::Matrix4d::Identity();
  H.topLeftCorner<3, 3>() = A.L;
  H.topRightCorner<3, 1>() = A.b;
  return H;
}
inline Affine3 affine3_of(const Eigen::Matrix4d& H) {
  return {H.topLeftCorner<3, 3>(), H.topRightCorner<3, 1>()};
}

}  // namespace pita
