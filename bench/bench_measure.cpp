// `pita measure` on every scene of scenes/, in process (load + every panel's
// measures; no output). Run: build/pita_bench --benchmark_filter=Measure
//   BM_Measure/<scene>: ms per scene (the target: <= 200 ms each)
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "analysis/measure.hpp"
#include "scene/scene.hpp"

namespace {

using namespace pita;

void BM_Measure(benchmark::State& state, const std::string& path) {
  std::size_t motions = 0;
  for (auto _ : state) {
    const scene::Scene scene = scene::load_scene(path);
    const std::vector<analysis::MotionMeasures> all = analysis::measure_scene(scene);
    motions = all.size();
    benchmark::DoNotOptimize(all.data());
  }
  state.counters["motions"] = static_cast<double>(motions);
}

int register_measure_benchmarks() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(PITA_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  for (const std::filesystem::path& file : files) {
    benchmark::RegisterBenchmark(("BM_Measure/" + file.stem().string()).c_str(), BM_Measure, file.string())
        ->Unit(benchmark::kMillisecond);
  }
  return 0;
}
const int measure_benchmarks = register_measure_benchmarks();

}  // namespace
