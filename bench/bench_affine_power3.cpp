// EAR in 3D (core/affine_power_of_space.hpp) against Eigen's MatrixFunctions pow on the
// 4x4 homogeneous matrix (issue 17 asks >= 10x faster): time per call and the
// worst relative error against a long-double reference, in one run. Run:
//   build/pita_bench --benchmark_filter=Power3
//   BM_Power3Ear:          AffinePowers(A).at(t): split, 2D EARs and power per call
//   BM_Power3EarPrepared:  at(t) of a prepared AffinePowers<Affine3> (sampling a 3D SAM)
//   BM_Power3Eigen:        Eigen::Matrix4d::pow(t) (Schur-Pade)
//   BM_Log3:               log() of a prepared AffinePowers<Affine3> (a 3D SAM's velocity
//                          field): the split's log and, where exp of it misses A
//                          by more than 1e-13, Newton steps (N58)
//   BM_Log3Eigen:          Eigen::Matrix4d::log() (Schur-Pade)
//   (the logs with argument 0 on the samples below, 1 on ill-conditioned ones)
// For the logs, worst_exp_log_error is |exp(X) - H|_F / |H|_F, exp in long double.
// worst_rel_error and mean_rel_error are |X - R|_F / |R|_F over the same 1024
// affinities and times, R from Eigen's pow in long double on affinities at
// least 0.1 from the identity.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <benchmark/benchmark.h>

#include "core/affine_power_of_space.hpp"
#include "support/matrix_functions.hpp"

namespace {
// Named apart from bench_affine_power.cpp's helpers (the unity build
// compiles both in one translation unit).
namespace space {

using namespace pita;
using Eigen::Matrix3d;
using Eigen::Matrix4d;

struct Sample {
  Affine3 A;
  double t;
};

// L = e^k V D V^-1: D positive diagonal or a positive eigenvalue beside a
// rotation-scaling (angle within 0.97 pi), eigenvalue ratios up to 400, V of
// condition up to 10.
const std::vector<Sample>& samples() {
  static const std::vector<Sample> result = [] {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto e = [&] { return std::exp(3.0 * (2.0 * unit(rng) - 1.0)); };
    std::vector<Sample> out;
    while (out.size() < 1024) {
      Matrix3d D = Matrix3d::Zero();
      if (unit(rng) < 0.5) {
        D.diagonal() << e(), e(), e();
      } else {
        const double angle = 0.97 * std::numbers::pi * (2.0 * unit(rng) - 1.0);
        D(0, 0) = e();
        D.block<2, 2>(1, 1) = e() * Eigen::Rotation2Dd(angle).toRotationMatrix();
      }
      const Matrix3d U = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
      const Eigen::Vector3d s(1.0, std::pow(10.0, -unit(rng)), 0.1);
      const Matrix3d V = U * s.asDiagonal();
      Affine3 A;
      A.L = V * D * V.inverse();
      A.b = Eigen::Vector3d(10.0 * unit(rng) - 5.0, 10.0 * unit(rng) - 5.0, 10.0 * unit(rng) - 5.0);
      if ((A.L - Matrix3d::Identity()).norm() < 0.1) continue;
      out.push_back({A, 3.0 * unit(rng) - 1.0});
    }
    return out;
  }();
  return result;
}

// Ill-conditioned ones for the log: eigenvalue ratio exactly 1e4 (its two
// ends taken), V = U diag(1, s, 1/200) W^T, condition numbers to ~1e8 (as in
// tests/core/test_affine_power_of_space.cpp, ExpOfLogHoldsOneE12NearConditionOneE8).
const std::vector<Sample>& ill_conditioned_samples() {
  static const std::vector<Sample> result = [] {
    std::mt19937_64 rng(18);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double half = std::log(1e4) / 2.0;
    std::vector<Sample> out;
    while (out.size() < 1024) {
      Matrix3d D = Matrix3d::Zero();
      const double sign = unit(rng) < 0.5 ? -1.0 : 1.0;
      if (unit(rng) < 0.5) {
        D(0, 0) = std::exp(sign * half);
        D(1, 1) = std::exp(half * (2.0 * unit(rng) - 1.0));
        D(2, 2) = std::exp(-sign * half);
      } else {
        const double angle = 0.97 * std::numbers::pi * (2.0 * unit(rng) - 1.0);
        D(0, 0) = std::exp(sign * half);
        D.block<2, 2>(1, 1) = std::exp(-sign * half) * Eigen::Rotation2Dd(angle).toRotationMatrix();
      }
      const Matrix3d U = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
      const Matrix3d W = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
      const Eigen::Vector3d s(1.0, std::pow(200.0, -unit(rng)), 1.0 / 200.0);
      const Matrix3d V = U * s.asDiagonal() * W.transpose();
      Affine3 A;
      A.L = V * D * V.inverse();
      A.b = Eigen::Vector3d(10.0 * unit(rng) - 5.0, 10.0 * unit(rng) - 5.0, 10.0 * unit(rng) - 5.0);
      out.push_back({A, 0.5});
    }
    return out;
  }();
  return result;
}

const std::vector<Sample>& log_samples(benchmark::State& state) {
  return state.range(0) == 0 ? samples() : ill_conditioned_samples();
}

using Matrix4l = Eigen::Matrix<long double, 4, 4>;

const std::vector<Matrix4l>& references() {
  static const std::vector<Matrix4l> result = [] {
    std::vector<Matrix4l> out;
    for (const Sample& s : samples())
      out.push_back(oracle::pow(Matrix4l(homogeneous(s.A).cast<long double>()), static_cast<long double>(s.t)));
    return out;
  }();
  return result;
}

template <typename Power>
void report_errors(benchmark::State& state, Power power) {
  double worst = 0.0, sum = 0.0;
  for (std::size_t i = 0; i < samples().size(); ++i) {
    const Matrix4l R = references()[i];
    const Matrix4l X = power(samples()[i]).template cast<long double>();
    const double error = static_cast<double>((X - R).norm() / R.norm());
    worst = std::max(worst, error);
    sum += error;
  }
  state.counters["worst_rel_error"] = worst;
  state.counters["mean_rel_error"] = sum / static_cast<double>(samples().size());
}

Matrix4d ear(const Sample& s) { return homogeneous(AffinePowers(s.A).at(s.t)); }
Matrix4d eigen(const Sample& s) { return oracle::pow(homogeneous(s.A), s.t); }

void BM_Power3Ear(benchmark::State& state) {
  const std::vector<Sample>& all = samples();
  std::size_t i = 0;
  for (auto _ : state) {
    const Sample& s = all[i++ & 1023];
    benchmark::DoNotOptimize(AffinePowers(s.A).at(s.t));
  }
  state.SetItemsProcessed(state.iterations());
  report_errors(state, ear);
}

void BM_Power3EarPrepared(benchmark::State& state) {
  std::vector<AffinePowers<Affine3>> prepared;
  for (const Sample& s : samples()) prepared.emplace_back(s.A);
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ & 1023;
    benchmark::DoNotOptimize(prepared[k].at(samples()[k].t));
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_Power3Eigen(benchmark::State& state) {
  const std::vector<Sample>& all = samples();
  std::vector<Matrix4d> matrices;
  for (const Sample& s : all) matrices.push_back(homogeneous(s.A));
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ & 1023;
    Matrix4d P = oracle::pow(matrices[k], all[k].t);
    benchmark::DoNotOptimize(P);
  }
  state.SetItemsProcessed(state.iterations());
  report_errors(state, eigen);
}

template <typename Log>
void report_log_errors(benchmark::State& state, Log log) {
  double worst = 0.0;
  for (const Sample& s : log_samples(state)) {
    const Matrix4l H = homogeneous(s.A).cast<long double>();
    const Matrix4l X = log(s.A).template cast<long double>();
    worst = std::max(worst, static_cast<double>((oracle::exp(X) - H).norm() / H.norm()));
  }
  state.counters["worst_exp_log_error"] = worst;
}

void BM_Log3(benchmark::State& state) {
  std::vector<AffinePowers<Affine3>> prepared;
  for (const Sample& s : log_samples(state)) prepared.emplace_back(s.A);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(prepared[i++ & 1023].log());
  state.SetItemsProcessed(state.iterations());
  report_log_errors(state, [](const Affine3& A) {
    Matrix4d X = homogeneous(AffinePowers(A).log());
    X(3, 3) = 0.0;
    return X;
  });
}

void BM_Log3Eigen(benchmark::State& state) {
  std::vector<Matrix4d> matrices;
  for (const Sample& s : log_samples(state)) matrices.push_back(homogeneous(s.A));
  std::size_t i = 0;
  for (auto _ : state) {
    Matrix4d X = oracle::log(matrices[i++ & 1023]);
    benchmark::DoNotOptimize(X);
  }
  state.SetItemsProcessed(state.iterations());
  report_log_errors(state, [](const Affine3& A) { return oracle::log(homogeneous(A)); });
}

BENCHMARK(BM_Power3Ear);
BENCHMARK(BM_Power3EarPrepared);
BENCHMARK(BM_Power3Eigen);
// Argument 0: the samples above; 1: the ill-conditioned ones.
BENCHMARK(BM_Log3)->Arg(0)->Arg(1);
BENCHMARK(BM_Log3Eigen)->Arg(0)->Arg(1);

}  // namespace space
}  // namespace
