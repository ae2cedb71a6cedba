// The 3D existence experiment (analysis/sam3d_existence.hpp, SAM paper Sec.
// 5.2): the per-matrix test and the figure's curve. Run:
//   build/pita_bench --benchmark_filter=Existence3
//   BM_Existence3Test:        has_real_logarithm on perturbed rotations like the experiment's
//   BM_Existence3EigenSolver: the same answer from Eigen's general eigensolver (the tests' oracle)
//   BM_Existence3Curve/N:     largest_safe_perturbation_curve(N) over 21 axes, one thread
// agree_percent: how often the two tests agree on the same 4096 matrices (100 expected).
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <benchmark/benchmark.h>

#include "analysis/sam3d_existence.hpp"

namespace {

using Eigen::Matrix3d;

// Rotations by angles in [0, pi] about random axes, every entry moved by
// -p, 0 or +p, p in [0, 0.5]: about a third have no real log.
const std::vector<Matrix3d>& matrices() {
  static const std::vector<Matrix3d> result = [] {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> angle(0.0, std::numbers::pi), size(0.0, 0.5);
    std::normal_distribution<double> normal;
    std::uniform_int_distribution<int> sign(-1, 1);
    std::vector<Matrix3d> all;
    for (int i = 0; i < 4096; ++i) {
      const double x = normal(rng), y = normal(rng), z = normal(rng);
      const double a = angle(rng), p = size(rng);
      Matrix3d L = Eigen::AngleAxisd(a, Eigen::Vector3d(x, y, z).normalized()).toRotationMatrix();
      for (int k = 0; k < 9; ++k) {
        const int s = sign(rng);
        L(k / 3, k % 3) += p * s;
      }
      all.push_back(L);
    }
    return all;
  }();
  return result;
}

bool eigen_solver_test(const Matrix3d& L) {
  const Eigen::Vector3cd values = Eigen::EigenSolver<Matrix3d>(L, false).eigenvalues();
  for (int i = 0; i < 3; ++i) {
    if (std::abs(values(i).imag()) <= 1e-12 * L.norm() && values(i).real() <= 0.0) return false;
  }
  return true;
}

void BM_Existence3Test(benchmark::State& state) {
  const std::vector<Matrix3d>& all = matrices();
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(pita::analysis::has_real_logarithm(all[k]));
    k = (k + 1) % all.size();
  }
  int agree = 0;
  for (const Matrix3d& L : all) agree += pita::analysis::has_real_logarithm(L) == eigen_solver_test(L) ? 1 : 0;
  state.counters["agree_percent"] = 100.0 * agree / static_cast<double>(all.size());
}

void BM_Existence3EigenSolver(benchmark::State& state) {
  const std::vector<Matrix3d>& all = matrices();
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(eigen_solver_test(all[k]));
    k = (k + 1) % all.size();
  }
}

void BM_Existence3Curve(benchmark::State& state) {
  pita::analysis::Sam3dExistenceOptions options;
  options.subdivisions = 1;
  options.jobs = 1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        pita::analysis::largest_safe_perturbation_curve(static_cast<int>(state.range(0)), options));
  }
}

}  // namespace

BENCHMARK(BM_Existence3Test);
BENCHMARK(BM_Existence3EigenSolver);
BENCHMARK(BM_Existence3Curve)->Arg(12)->Unit(benchmark::kMillisecond);
