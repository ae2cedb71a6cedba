// EAR's A^t (core/affine_power.hpp) against Eigen's MatrixFunctions pow on the
// 3x3 homogeneous matrix (issue 5): time per call and worst relative error
// against a long-double reference, in one run. Run:
//   build/pita_bench --benchmark_filter=Power
//   BM_PowerEar:          AffinePowers(A).at(t): case selection, log and power per call
//   BM_PowerEarPrepared:  at(t) of a prepared AffinePowers<Affine2> (sampling a SAM)
//   BM_PowerEigen:        Eigen::Matrix3d::pow(t) (Schur-Pade)
// The counters worst_rel_error and mean_rel_error are |X - R|_F / |R|_F over
// the same 1024 random affinities and times, R from Eigen's pow in long double
// (64-bit mantissa) on affinities at least 0.1 from the identity, where that
// reference is good to ~1e-18 (near the identity it is not; see
// tests/core/test_affine_power.cpp).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Dense>
#include <benchmark/benchmark.h>

#include "core/affine_power.hpp"
#include "support/matrix_functions.hpp"

namespace {

using namespace pita;

struct Sample {
  Affine2 A;
  double t;
};

// Orientation-preserving affinities with a real log, R(a) R(-c) diag(1/s, s) R(c)
// scaled by e^k, every EAR case among them but S1/S2 (measure zero).
const std::vector<Sample>& samples() {
  static const std::vector<Sample> result = [] {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Sample> out;
    while (out.size() < 1024) {
      const double s = 0.05 + 0.95 * unit(rng);
      const double a = (2.0 * unit(rng) - 1.0) * (1.0 + s) * std::numbers::pi / 2.0 * 0.98;
      const double c = 2.0 * std::numbers::pi * unit(rng);
      const double k = 3.0 * (2.0 * unit(rng) - 1.0);
      const Eigen::Rotation2Dd R(a), Rc(c);
      Eigen::Matrix2d D;
      D << 1.0 / s, 0.0, 0.0, s;
      Affine2 A;
      A.L = std::exp(k) * R.toRotationMatrix() * Rc.toRotationMatrix().transpose() * D * Rc.toRotationMatrix();
      A.b = Eigen::Vector2d(10.0 * unit(rng) - 5.0, 10.0 * unit(rng) - 5.0);
      if ((A.L - Eigen::Matrix2d::Identity()).norm() < 0.1) continue;
      out.push_back({A, 3.0 * unit(rng) - 1.0});
    }
    return out;
  }();
  return result;
}

Eigen::Matrix3d homogeneous(const Affine2& A) {
  Eigen::Matrix3d H = Eigen::Matrix3d::Identity();
  H.topLeftCorner<2, 2>() = A.L;
  H.topRightCorner<2, 1>() = A.b;
  return H;
}

using Matrix3l = Eigen::Matrix<long double, 3, 3>;

const std::vector<Matrix3l>& references() {
  static const std::vector<Matrix3l> result = [] {
    std::vector<Matrix3l> out;
    for (const Sample& s : samples()) {
      const Matrix3l H = homogeneous(s.A).cast<long double>();
      out.push_back(oracle::pow(H, static_cast<long double>(s.t)));
    }
    return out;
  }();
  return result;
}

template <typename Power>
void report_errors(benchmark::State& state, Power power) {
  double worst = 0.0, sum = 0.0;
  for (std::size_t i = 0; i < samples().size(); ++i) {
    const Matrix3l R = references()[i];
    const Matrix3l X = power(samples()[i]).template cast<long double>();
    const double error = static_cast<double>((X - R).norm() / R.norm());
    worst = std::max(worst, error);
    sum += error;
  }
  state.counters["worst_rel_error"] = worst;
  state.counters["mean_rel_error"] = sum / static_cast<double>(samples().size());
}

Eigen::Matrix3d ear(const Sample& s) { return homogeneous(AffinePowers(s.A).at(s.t)); }
Eigen::Matrix3d eigen(const Sample& s) { return oracle::pow(homogeneous(s.A), s.t); }

void BM_PowerEar(benchmark::State& state) {
  const std::vector<Sample>& all = samples();
  std::size_t i = 0;
  for (auto _ : state) {
    const Sample& s = all[i++ & 1023];
    benchmark::DoNotOptimize(AffinePowers(s.A).at(s.t));
  }
  state.SetItemsProcessed(state.iterations());
  report_errors(state, ear);
}

void BM_PowerEarPrepared(benchmark::State& state) {
  std::vector<AffinePowers<Affine2>> prepared;
  for (const Sample& s : samples()) prepared.emplace_back(s.A);
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ & 1023;
    benchmark::DoNotOptimize(prepared[k].at(samples()[k].t));
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_PowerEigen(benchmark::State& state) {
  const std::vector<Sample>& all = samples();
  std::vector<Eigen::Matrix3d> matrices;
  for (const Sample& s : all) matrices.push_back(homogeneous(s.A));
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ & 1023;
    Eigen::Matrix3d P = oracle::pow(matrices[k], all[k].t);
    benchmark::DoNotOptimize(P);
  }
  state.SetItemsProcessed(state.iterations());
  report_errors(state, eigen);
}

BENCHMARK(BM_PowerEar);
BENCHMARK(BM_PowerEarPrepared);
BENCHMARK(BM_PowerEigen);

}  // namespace
