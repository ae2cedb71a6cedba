// Affinities x -> L x + b, with an N x N linear part L and a translation b:
// of the plane (N = 2, PITA Sec. 3.3 and 4.10: a keyframe "triangle" of PAM,
// PITA Eq. 37-39, is one, and an arrow is the special case of a similarity)
// and of space (N = 3, SAM paper Sec. 2.1, appendix A.6). One template over
// the dimension, as Eigen's Transform<Scalar, Dim, Mode> is; what else depends
// on the dimension is in PoseTraits (pose_traits.hpp).
//
// The verbs are the ones every value type of the core shares: apply,
// compose, inverse here; pow, log, exp in affine_power.hpp and
// affine_power_of_space.hpp (EAR). Twirl (twirl.hpp) has the same six.
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>

namespace pita {

template <int N>
struct Affine {
  using Linear = Eigen::Matrix<double, N, N>;
  using Vector = Eigen::Matrix<double, N, 1>;
  using Homogeneous = Eigen::Matrix<double, N + 1, N + 1>;

  Linear L = Linear::Identity();  // linear part
  Vector b = Vector::Zero();      // translation

  static Affine identity() { return {}; }
};

using Affine2 = Affine<2>;
using Affine3 = Affine<3>;

// The image of point x: L x + b. (N comes from the affinity; x may be any
// expression of the point type.)
template <int N>
typename Affine<N>::Vector apply(const Affine<N>& A, const typename Affine<N>::Vector& x) {
  return A.L * x + A.b;
}

// A o B: first B, then A (x -> A(B(x))), the order of homogeneous matrices.
template <int N>
Affine<N> compose(const Affine<N>& A, const Affine<N>& B) {
  return {A.L * B.L, A.L * B.b + A.b};
}

// The inverse affinity x -> L^-1 (x - b). Precondition: L invertible (no
// check: a singular L gives non-finite entries).
template <int N>
Affine<N> inverse(const Affine<N>& A) {
  const typename Affine<N>::Linear Li = A.L.inverse();
  return {Li, -Li * A.b};
}

// The (N + 1) x (N + 1) homogeneous matrix [[L, b], [0, 1]], and back (the
// last row of H is ignored).
template <int N>
typename Affine<N>::Homogeneous homogeneous(const Affine<N>& A) {
  typename Affine<N>::Homogeneous H = Affine<N>::Homogeneous::Identity();
  H.template topLeftCorner<N, N>() = A.L;
  H.template topRightCorner<N, 1>() = A.b;
  return H;
}
template <int N>
Affine<N> affine_of_homogeneous(const typename Affine<N>::Homogeneous& H) {
  return {H.template topLeftCorner<N, N>(), H.template topRightCorner<N, 1>()};
}

}  // namespace pita
