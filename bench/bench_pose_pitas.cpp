// One frame of each pose PITA (core/pose_pitas, docs/paper-notes.md N73-N78)
// in the plane and in space, beside the unit it is built from: one steady
// affine morph, built (the EAR analysis of B o A^-1) and evaluated. A frame
// of P6, P9 or P4 builds one SAM between the poses it forms at t and
// evaluates a few prepared ones; P5 takes one exp. Run:
//   build/pita_bench --benchmark_filter=PosePita
//   BM_PosePitaFrame2/P4 ... /P9   at(t) of a prepared pose PITA, 2D (t cycles over [0, 1])
//   BM_PosePitaFrame3/P4 ... /P9   the same in space
//   BM_PosePitaSam2, BM_PosePitaSam3   SteadyAffineMorph(A, B).at(t): one SAM built and evaluated
//   BM_PosePitaPrepare2/P4 ... , BM_PosePitaPrepare3/...   building the pose PITA
#include <random>
#include <string>

#include <Eigen/Geometry>
#include <benchmark/benchmark.h>

#include "core/pose_pitas/be_lp.hpp"
#include "core/pose_pitas/he_lp.hpp"
#include "core/pose_pitas/la_lp.hpp"
#include "core/pose_pitas/ne_lp.hpp"

namespace {
// Named apart from the other benches' helpers (the unity build).
namespace pose_pitas {

using namespace pita;

// A tame triple: steps that turn by 0.9 rad about skew axes and stretch a little.
template <int N>
PoseTriple<Affine<N>> triple() {
  Affine<N> A, B, C;
  if constexpr (N == 2) {
    A.L = 1.2 * Eigen::Rotation2Dd(0.3).toRotationMatrix();
    B.L = Eigen::Rotation2Dd(1.2).toRotationMatrix() * Eigen::Vector2d(1.5, 0.8).asDiagonal();
    C.L = 0.9 * Eigen::Rotation2Dd(2.0).toRotationMatrix();
    A.b << 0, 0;
    B.b << 3, 1;
    C.b << 5, 4;
  } else {
    A.L = 1.2 * Eigen::AngleAxisd(0.3, Eigen::Vector3d(0, 0, 1)).toRotationMatrix();
    B.L = Eigen::AngleAxisd(1.2, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix() *
          Eigen::Vector3d(1.5, 0.8, 1.1).asDiagonal();
    C.L = 0.9 * Eigen::AngleAxisd(2.0, Eigen::Vector3d(0, 1, 1).normalized()).toRotationMatrix();
    A.b << 0, 0, 0;
    B.b << 3, 1, -1;
    C.b << 5, 4, 2;
  }
  return {{{0.0, A}, {0.4, B}, {1.0, C}}};
}

template <class Pita, int N>
void Frame(benchmark::State& state) {
  const Pita pita(triple<N>());
  double t = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(pita.at(t));
    t += 0.0137;
    if (t > 1.0) t -= 1.0;
  }
}

template <class Pita, int N>
void Prepare(benchmark::State& state) {
  const PoseTriple<Affine<N>> k = triple<N>();
  for (auto _ : state) benchmark::DoNotOptimize(Pita(k));
}

template <int N>
void Sam(benchmark::State& state) {
  const PoseTriple<Affine<N>> k = triple<N>();
  double t = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(SteadyAffineMorph<Affine<N>>(k[0].pose, k[1].pose).at(t));
    t += 0.0137;
    if (t > 1.0) t -= 1.0;
  }
}

BENCHMARK(Frame<PoseBeLp<Affine2>, 2>)->Name("BM_PosePitaFrame2/P4");
BENCHMARK(Frame<PoseHeLp<Affine2>, 2>)->Name("BM_PosePitaFrame2/P5");
BENCHMARK(Frame<PoseLaLp<Affine2>, 2>)->Name("BM_PosePitaFrame2/P6");
BENCHMARK(Frame<PoseNeLp<Affine2>, 2>)->Name("BM_PosePitaFrame2/P9");
BENCHMARK(Frame<PoseBeLp<Affine3>, 3>)->Name("BM_PosePitaFrame3/P4");
BENCHMARK(Frame<PoseHeLp<Affine3>, 3>)->Name("BM_PosePitaFrame3/P5");
BENCHMARK(Frame<PoseLaLp<Affine3>, 3>)->Name("BM_PosePitaFrame3/P6");
BENCHMARK(Frame<PoseNeLp<Affine3>, 3>)->Name("BM_PosePitaFrame3/P9");
BENCHMARK(Sam<2>)->Name("BM_PosePitaSam2");
BENCHMARK(Sam<3>)->Name("BM_PosePitaSam3");
BENCHMARK(Prepare<PoseBeLp<Affine2>, 2>)->Name("BM_PosePitaPrepare2/P4");
BENCHMARK(Prepare<PoseHeLp<Affine2>, 2>)->Name("BM_PosePitaPrepare2/P5");
BENCHMARK(Prepare<PoseLaLp<Affine2>, 2>)->Name("BM_PosePitaPrepare2/P6");
BENCHMARK(Prepare<PoseNeLp<Affine2>, 2>)->Name("BM_PosePitaPrepare2/P9");
BENCHMARK(Prepare<PoseBeLp<Affine3>, 3>)->Name("BM_PosePitaPrepare3/P4");
BENCHMARK(Prepare<PoseHeLp<Affine3>, 3>)->Name("BM_PosePitaPrepare3/P5");
BENCHMARK(Prepare<PoseLaLp<Affine3>, 3>)->Name("BM_PosePitaPrepare3/P6");
BENCHMARK(Prepare<PoseNeLp<Affine3>, 3>)->Name("BM_PosePitaPrepare3/P9");

}  // namespace pose_pitas
}  // namespace
