// Helpers of the pose PITA tests (src/core/pose_pitas/): random affine
// triples of the plane and of space, and an INDEPENDENT computation of each
// construction with Eigen's unsupported MatrixFunctions (log, exp of the
// homogeneous matrices), sharing nothing with EAR but the scalar weights.
#pragma once

#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <unsupported/Eigen/MatrixFunctions>

#include "core/affine.hpp"
#include "core/knot_warp.hpp"
#include "core/lagrange_weights.hpp"
#include "core/neville_ratios.hpp"
#include "core/pose_pitas/morph_and_transport.hpp"

namespace pita::test {

template <int N>
using Hom = Eigen::Matrix<double, N + 1, N + 1>;

template <int N>
Hom<N> hom(const Affine<N>& A) {
  Hom<N> H = Hom<N>::Identity();
  H.template topLeftCorner<N, N>() = A.L;
  H.template topRightCorner<N, 1>() = A.b;
  return H;
}

template <int N>
Affine<N> of_hom(const Hom<N>& H) {
  return {H.template topLeftCorner<N, N>(), H.template topRightCorner<N, 1>()};
}

template <int N>
double pose_distance(const Affine<N>& X, const Affine<N>& Y) {
  return (X.L - Y.L).norm() + (X.b - Y.b).norm();
}

// Whether M has a real principal log: no real eigenvalue <= 0 (the oracle's
// own test, by Eigen's eigensolver).
template <class Matrix>
bool has_real_log(const Matrix& M) {
  const auto values = M.eigenvalues();
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    const std::complex<double> e = values(i);
    if (std::abs(e.imag()) <= 1e-9 * std::abs(e) && e.real() <= 0.0) return false;
  }
  return true;
}

// The oracle's T(X, A, B, s) = exp(s log(B A^-1)) X and M(A, B, s) =
// T(A, A, B, s). Where B A^-1 has no real log it is NaN (a refusal, which
// propagates), except at s = 0 and 1, where the power is I and B A^-1
// whatever the log.
template <class H>
H oracle_transport(const H& X, const H& A, const H& B, double s) {
  if (!X.allFinite() || !A.allFinite() || !B.allFinite()) return H::Constant(std::nan(""));
  const H step = B * A.inverse();
  if (s == 0.0) return X;
  if (s == 1.0) return step * X;
  if (!has_real_log(step)) return H::Constant(std::nan(""));
  return H((step.log() * s).exp()) * X;
}
template <class H>
H oracle_morph(const H& A, const H& B, double s) {
  return oracle_transport(A, A, B, s);
}

template <int N>
struct OracleTriple {
  double a, b, c;
  Hom<N> A, B, C;
};

template <int N>
OracleTriple<N> oracle_of(const PoseTriple<Affine<N>>& k) {
  return {k[0].t, k[1].t, k[2].t, hom(k[0].pose), hom(k[1].pose), hom(k[2].pose)};
}

// P6 (PITA Eq. 34).
template <int N>
Affine<N> oracle_p6(const OracleTriple<N>& k, double t) {
  const LagrangeWeights l = lagrange_weights(k.a, k.b, k.c, t);
  const Hom<N> L = oracle_transport(oracle_morph(k.A, k.B, l.y + l.z), k.B, k.C, l.z);
  const Hom<N> R = oracle_transport(oracle_morph(k.C, k.B, l.x + l.y), k.B, k.A, l.x);
  return of_hom<N>(oracle_morph(L, R, 0.5));
}

// P9 (PITA Eq. D.2).
template <int N>
Affine<N> oracle_p9(const OracleTriple<N>& k, double t) {
  const NevilleRatios n = neville_ratios(k.a, k.b, k.c, t);
  return of_hom<N>(oracle_morph(oracle_morph(k.A, k.B, n.q), oracle_morph(k.B, k.C, n.r), n.s));
}

// P4 (PITA Eq. 27-32, controls of N3).
template <int N>
Affine<N> oracle_p4(const OracleTriple<N>& k, double t) {
  const Hom<N> L = oracle_transport(oracle_morph(k.A, k.B, 0.75), k.C, k.B, 0.25);
  const Hom<N> R = oracle_transport(oracle_morph(k.C, k.B, 0.75), k.A, k.B, 0.25);
  const auto bezier = [](const Hom<N>& P0, const Hom<N>& P1, const Hom<N>& P2, double s) {
    return oracle_morph(oracle_morph(P0, P1, s), oracle_morph(P1, P2, s), s);
  };
  const double u = knot_warp(k.a, k.b, k.c, t);
  if (u <= 0.5) return of_hom<N>(bezier(k.A, L, k.B, 2.0 * u));
  return of_hom<N>(bezier(k.B, R, k.C, 2.0 * u - 1.0));
}

// P5 (PITA Eq. 33 about the centroid g of the translations).
template <int N>
Affine<N> oracle_p5(const OracleTriple<N>& k, double t) {
  const LagrangeWeights l = lagrange_weights(k.a, k.b, k.c, t);
  Hom<N> G = Hom<N>::Identity();
  G.template topRightCorner<N, 1>() = (k.A.template topRightCorner<N, 1>() + k.B.template topRightCorner<N, 1>() +
                                       k.C.template topRightCorner<N, 1>()) /
                                      3.0;
  const Hom<N> Gi = G.inverse();
  if (!has_real_log(k.A) || !has_real_log(k.B) || !has_real_log(k.C)) return of_hom<N>(Hom<N>::Constant(std::nan("")));
  const Hom<N> blend = l.x * Hom<N>((Gi * k.A).log()) + l.y * Hom<N>((Gi * k.B).log()) + l.z * Hom<N>((Gi * k.C).log());
  return of_hom<N>(G * Hom<N>(blend.exp()));
}

// A random rotation of the plane or of space by an angle of at most max_angle.
template <int N>
Eigen::Matrix<double, N, N> random_rotation(std::mt19937& rng, double max_angle) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double angle = max_angle * u(rng);
  if constexpr (N == 2) {
    return Eigen::Rotation2Dd(angle).toRotationMatrix();
  } else {
    // One draw per statement (a call's arguments have no order), in the
    // order the tests were written against.
    const double z = u(rng), y = u(rng), x = u(rng);
    const Eigen::Vector3d axis(x, y, z);
    return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  }
}

// A random affinity near a rotation: R (I + stretch E), E entries in (-1, 1),
// scaled by e^{+-0.5}, translated within (-3, 3).
template <int N>
Affine<N> random_step(std::mt19937& rng, double max_angle, double stretch) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::Matrix<double, N, N> E;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) E(i, j) = u(rng);
  Affine<N> G;
  const Eigen::Matrix<double, N, N> R = random_rotation<N>(rng, max_angle);
  const double scale = std::exp(0.5 * u(rng));
  G.L = scale * R * (Eigen::Matrix<double, N, N>::Identity() + stretch * E);
  for (int i = 0; i < N; ++i) G.b(i) = 3.0 * u(rng);
  return G;
}

// The shape of random triples: A turns by at most first_angle, B = G1 o A and
// C = G2 o B with steps G that turn by at most step_angle and stretch by
// `stretch`; knots 0 < b < 1 (b = 1/2 when even).
struct Shape {
  double first_angle = 3.0;
  double step_angle = 1.2;
  double stretch = 0.25;
  bool even = false;
};

template <int N>
PoseTriple<Affine<N>> random_triple(std::mt19937& rng, const Shape& shape = {}) {
  std::uniform_real_distribution<double> knot(0.25, 0.75);
  const Affine<N> A = random_step<N>(rng, shape.first_angle, shape.stretch);
  const Affine<N> B = compose(random_step<N>(rng, shape.step_angle, shape.stretch), A);
  const Affine<N> C = compose(random_step<N>(rng, shape.step_angle, shape.stretch), B);
  return {{{0.0, A}, {shape.even ? 0.5 : knot(rng), B}, {1.0, C}}};
}

// Whether the oracle finds a real power for each given neighbouring pair
// and a real log of each pose (P5).
template <int N>
bool neighbours_have_powers(const PoseTriple<Affine<N>>& k) {
  const OracleTriple<N> o = oracle_of<N>(k);
  return has_real_log(Hom<N>(o.B * o.A.inverse())) && has_real_log(Hom<N>(o.C * o.B.inverse())) && has_real_log(o.A) &&
         has_real_log(o.B) && has_real_log(o.C);
}

// The times the tests sample: before a, the knots, between, after c.
template <class Triple>
std::vector<double> times_of(const Triple& k) {
  const double a = k[0].t, b = k[1].t, c = k[2].t;
  return {a - 0.2, a, 0.5 * (a + b), b, 0.3 * b + 0.7 * c, c, c + 0.2};
}

// The triple with each pose G o X o H.
template <int N>
PoseTriple<Affine<N>> moved(const Affine<N>& G, PoseTriple<Affine<N>> k, const Affine<N>& H) {
  for (auto& p : k) p.pose = compose(G, compose(p.pose, H));
  return k;
}

// The triple with time reversed: (-c, C), (-b, B), (-a, A).
template <int N>
PoseTriple<Affine<N>> reversed(const PoseTriple<Affine<N>>& k) {
  return {{{-k[2].t, k[2].pose}, {-k[1].t, k[1].pose}, {-k[0].t, k[0].pose}}};
}

}  // namespace pita::test
