// EAR in 3D (core/affine_power3.hpp) against Eigen's MatrixFunctions pow on the
// 4x4 homogeneous matrix (issue 17 asks >= 10x faster): time per call and the
// worst relative error against a long-double reference, in one run. Run:
//   build/pita_bench --benchmark_filter=Power3
//   BM_Power3Ear:          AffinePowers3(A).at(t): split, 2D EARs and power per call
//   BM_Power3EarPrepared:  at(t) of a prepared AffinePowers3 (sampling a 3D SAM)
//   BM_Power3Eigen:        Eigen::Matrix4d::pow(t) (Schur-Pade)
// worst_rel_error and mean_rel_error are |X - R|_F / |R|_F over the same 1024
// affinities and times, R from Eigen's pow in long double on affinities at
// least 0.1 from the identity.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <unsupported/Eigen/MatrixFunctions>

#include "core/affine_power3.hpp"

namespace {

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

using Matrix4l = Eigen::Matrix<long double, 4, 4>;

const std::vector<Matrix4l>& references() {
  static const std::vector<Matrix4l> result = [] {
    std::vector<Matrix4l> out;
    for (const Sample& s : samples()) out.push_back(homogeneous(s.A).cast<long double>().pow(static_cast<long double>(s.t)));
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

Matrix4d ear(const Sample& s) { return homogeneous(AffinePowers3(s.A).at(s.t)); }
Matrix4d eigen(const Sample& s) { return homogeneous(s.A).pow(s.t); }

void BM_Power3Ear(benchmark::State& state) {
  const std::vector<Sample>& all = samples();
  std::size_t i = 0;
  for (auto _ : state) {
    const Sample& s = all[i++ & 1023];
    benchmark::DoNotOptimize(AffinePowers3(s.A).at(s.t));
  }
  state.SetItemsProcessed(state.iterations());
  report_errors(state, ear);
}

void BM_Power3EarPrepared(benchmark::State& state) {
  std::vector<AffinePowers3> prepared;
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
    Matrix4d P = matrices[k].pow(all[k].t);
    benchmark::DoNotOptimize(P);
  }
  state.SetItemsProcessed(state.iterations());
  report_errors(state, eigen);
}

BENCHMARK(BM_Power3Ear);
BENCHMARK(BM_Power3EarPrepared);
BENCHMARK(BM_Power3Eigen);

}  // namespace
