// ns per frame of keyframe tracks (core/chains). Run:
//   build/pita_bench --benchmark_filter='Chain|PlainFrame'
//   BM_ChainFrame/<chain>/<method>: D(t) of a prepared 12-keyframe track
//   BM_PlainFrame/<method>:         D(t) of the plain method through its own
//                                   3 keyframes (2 for SMA), the baseline the
//                                   chain/plain ratio is read against
//   BM_ChainPrepare/blend/P6:       building the 12-keyframe blend track
// Times cycle through kTimes values spread over the knot range, offset so that
// no sample falls on a knot.
#include <cmath>
#include <cstddef>
#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/chains/chain.hpp"
#include "core/pitas/registry.hpp"

namespace {

using namespace pita;

constexpr std::size_t kTrackKeyframes = 12;
constexpr std::size_t kTimes = 1024;  // a power of two: the cycle is a mask

// 12 keyframes from a fixed seed: arrows scattered over a few units, knot
// gaps in [0.6, 1.4] (uneven, not wild), windings drifting by 1 to 3 rad
// per keyframe either way.
std::vector<Keyframe> track_keyframes() {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> coord(-4.0, 4.0);
  std::uniform_real_distribution<double> log_mag(-0.6, 0.6);
  std::uniform_real_distribution<double> gap(0.6, 1.4);
  std::uniform_real_distribution<double> drift(1.0, 3.0);
  std::bernoulli_distribution turn_left(0.5);
  std::vector<Keyframe> k;
  double t = 0.0;
  double w = 0.3;
  for (std::size_t i = 0; i < kTrackKeyframes; ++i) {
    if (i > 0) {
      t += gap(rng);
      w += turn_left(rng) ? drift(rng) : -drift(rng);
    }
    k.push_back({t, {{coord(rng), coord(rng)}, std::exp(log_mag(rng)), w}});
  }
  return k;
}

// The same three keyframes as bench_methods.cpp's BM_Frame (two for SMA).
std::vector<Keyframe> plain_keyframes(Method m) {
  std::vector<Keyframe> k{{0.0, {{0, 0}, 1.0, 0.4}}, {0.45, {{3, 1.5}, 0.6, 2.0}}, {1.0, {{6, 0}, 1.2, 3.5}}};
  if (info(m).keyframe_count == 2) k.erase(k.begin() + 1);
  return k;
}

// kTimes times over [t_0, t_last], at the midpoints of kTimes equal cells
// (never exactly a knot for these knots), in increasing order as sampling a
// figure visits them (BM_Frame's sweep, with a table instead of a running t).
std::vector<double> sample_times(const std::vector<Keyframe>& k) {
  const double t0 = k.front().t;
  const double t1 = k.back().t;
  std::vector<double> times(kTimes);
  for (std::size_t j = 0; j < kTimes; ++j) {
    times[j] = t0 + (t1 - t0) * (static_cast<double>(j) + 0.5) / static_cast<double>(kTimes);
  }
  return times;
}

void run_frames(benchmark::State& state, const Motion& motion, const std::vector<double>& times) {
  std::size_t j = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(motion.at(times[j]));
    j = (j + 1) & (kTimes - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_ChainFrame(benchmark::State& state, Chain chain, Method m) {
  const std::vector<Keyframe> k = track_keyframes();
  const auto motion = make_motion(m, k, {}, chain);
  run_frames(state, *motion, sample_times(k));
}

void BM_PlainFrame(benchmark::State& state, Method m) {
  const std::vector<Keyframe> k = plain_keyframes(m);
  const auto motion = make_motion(m, k);
  run_frames(state, *motion, sample_times(k));
}

void BM_ChainPrepare(benchmark::State& state, Chain chain, Method m) {
  const std::vector<Keyframe> k = track_keyframes();
  for (auto _ : state) {
    const auto motion = make_motion(m, k, {}, chain);
    benchmark::DoNotOptimize(motion.get());
  }
}

int register_chain_benchmarks() {
  struct Case {
    Chain chain;
    Method method;
  };
  const Case cases[] = {
      {Chain::blend, Method::P6},          {Chain::blend, Method::P8},   {Chain::blend, Method::P3},
      {Chain::blend, Method::P9},          {Chain::neville, Method::P6}, {Chain::spiral, Method::SMA},
      {Chain::bezier_spiral, Method::SMA},
  };
  for (const Case& c : cases) {
    const std::string name = "BM_ChainFrame/" + std::string(info(c.chain).name) + "/" + std::string(info(c.method).id);
    benchmark::RegisterBenchmark(name.c_str(), BM_ChainFrame, c.chain, c.method);
  }
  for (const Method m : {Method::P6, Method::P8, Method::P3, Method::P9, Method::SMA}) {
    benchmark::RegisterBenchmark(("BM_PlainFrame/" + std::string(info(m).id)).c_str(), BM_PlainFrame, m);
  }
  benchmark::RegisterBenchmark("BM_ChainPrepare/blend/P6", BM_ChainPrepare, Chain::blend, Method::P6);
  return 0;
}
const int chain_benchmarks = register_chain_benchmarks();

}  // namespace
