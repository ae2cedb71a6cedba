// pita sweep in process (src/sweep): whole sweeps of Fig. 1's scene, the
// middle knot swept, into a scratch folder (--force: every variant redone).
// Run: build/pita_bench --benchmark_filter=Sweep
//   BM_Sweep/<format>/<jobs>: items_per_second = variants per second (the
//     manifest, index.html and the contact sheet included)
// The comparisons (1000 variants against one process per variant,
// peak memory of 10 000 variants) are scripts/bench-sweep.sh.
#include <filesystem>
#include <string>

#include <benchmark/benchmark.h>

#include "sweep/sweep.hpp"

namespace {

using namespace pita;
namespace fs = std::filesystem;

constexpr int kVariants = 100;

void BM_Sweep(benchmark::State& state, sweep::OutputKind kind) {
  const fs::path dir = fs::temp_directory_path() / "pita-bench-sweep";
  fs::remove_all(dir);
  sweep::SweepOptions options;
  options.scene_path = std::string(PITA_SOURCE_DIR) + "/scenes/fig01-eight-pitas.json";
  options.vary = {"/keyframes/1/t=0.05:0.95:" + std::to_string(kVariants)};
  options.output = dir.string();
  options.formats = {kind};
  options.jobs = static_cast<int>(state.range(0));
  options.force = true;
  options.progress = false;
  for (auto _ : state) {
    const sweep::SweepSummary summary = sweep::run_sweep(options);
    if (summary.ok != kVariants) state.SkipWithError("a variant failed");
  }
  state.SetItemsProcessed(state.iterations() * kVariants);
  fs::remove_all(dir);
}

BENCHMARK_CAPTURE(BM_Sweep, svg, sweep::OutputKind::svg)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Sweep, png, sweep::OutputKind::png)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Sweep, csv, sweep::OutputKind::csv)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
