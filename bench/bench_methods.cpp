// ns per frame of every method. Run: build/pita_bench
//   BM_Frame/<method>:   D(t) of a prepared motion (what sampling a figure costs)
//   BM_Prepare/<method>: building the motion from its keyframes plus one frame
//   BM_LoopOverhead:     BM_Frame's loop with no frame in it: what the timing
//                        itself costs per iteration. Debian's libbenchmark is
//                        built without NDEBUG ("Library was built as DEBUG"); the
//                        timed loop is inlined from its header into this -O3
//                        file, so only the code between batches is the library's.
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/pitas/registry.hpp"

namespace {

using namespace pita;

std::vector<Keyframe> keyframes(Method m) {
  std::vector<Keyframe> k{{0.0, {{0, 0}, 1.0, 0.4}}, {0.45, {{3, 1.5}, 0.6, 2.0}}, {1.0, {{6, 0}, 1.2, 3.5}}};
  if (info(m).keyframe_count == 2) k.erase(k.begin() + 1);
  return k;
}

void BM_Frame(benchmark::State& state, Method m) {
  const std::vector<Keyframe> k = keyframes(m);
  const auto motion = make_motion(m, k);
  double t = 0.0;
  for (auto _ : state) {
    t += 1.0 / 1024.0;
    if (t > 1.0) t -= 1.0;
    benchmark::DoNotOptimize(motion->at(t));
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_LoopOverhead(benchmark::State& state) {
  double t = 0.0;
  for (auto _ : state) {
    t += 1.0 / 1024.0;
    if (t > 1.0) t -= 1.0;
    benchmark::DoNotOptimize(t);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LoopOverhead);

void BM_Prepare(benchmark::State& state, Method m) {
  const std::vector<Keyframe> k = keyframes(m);
  for (auto _ : state) {
    const auto motion = make_motion(m, k);
    benchmark::DoNotOptimize(motion->at(0.3));
  }
}

int register_method_benchmarks() {
  for (const MethodInfo& mi : all_methods()) {
    benchmark::RegisterBenchmark(("BM_Frame/" + std::string(mi.id)).c_str(), BM_Frame, mi.method);
  }
  for (const MethodInfo& mi : all_methods()) {
    benchmark::RegisterBenchmark(("BM_Prepare/" + std::string(mi.id)).c_str(), BM_Prepare, mi.method);
  }
  return 0;
}
const int method_benchmarks = register_method_benchmarks();

}  // namespace

BENCHMARK_MAIN();
