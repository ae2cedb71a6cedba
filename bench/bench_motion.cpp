// The motion stage. Run: build/pita_bench --benchmark_filter='Stage|ArcLength|Eased'
//   BM_StageFrame/P6:    D(t) through motion::SceneMotion (no timing): the
//                        stage's cost over BM_Frame/P6
//   BM_EasedFrame/<ease>: the same under an ease (no arc length)
//   BM_ArcLength1000/P6: 1000 frames of P6 paced by the arc length of p,
//                        building the arc-length table included
#include <string>

#include <benchmark/benchmark.h>

#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"
#include "scene/scene.hpp"

namespace {

using namespace pita;

scene::Scene p6_scene(const std::string& timing) {
  return scene::parse_scene(R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0.4},
      {"t": 0.45, "p": [3, 1.5], "m": 0.6, "w": 2}, {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}])" +
                                timing + "}",
                            "bench.json");
}

// D(t) of P6 through the stage, under `ease` (nullptr: no timing).
void BM_EasedFrame(benchmark::State& state, const char* ease) {
  const scene::Scene scene = p6_scene(ease ? std::string(R"(, "timing": {"ease": )") + ease + "}" : "");
  const motion::SceneMotion motion = motion::build_motion(scene);
  double t = 0.0;
  for (auto _ : state) {
    t += 1.0 / 1024.0;
    if (t > 1.0) t -= 1.0;
    benchmark::DoNotOptimize(motion.arrow_at(t));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK_CAPTURE(BM_EasedFrame, none, nullptr)->Name("BM_StageFrame/P6");
BENCHMARK_CAPTURE(BM_EasedFrame, ease_in_out, R"("ease-in-out")");
BENCHMARK_CAPTURE(BM_EasedFrame, sine, R"("sine")");
BENCHMARK_CAPTURE(BM_EasedFrame, parabolic, R"({"parabolic": {"t1": 0.3, "t2": 0.7}})");

void BM_ArcLength1000(benchmark::State& state) {
  const scene::Scene scene = p6_scene(R"(, "timing": {"arc_length": "p"})");
  const std::vector<double> times = motion::uniform_times(0.0, 1.0, 1000);
  for (auto _ : state) {
    const motion::SceneMotion motion = motion::build_motion(scene);  // builds the table
    benchmark::DoNotOptimize(motion::sample_arrows(motion, times));
  }
  state.SetItemsProcessed(state.iterations() * 1000);
}
BENCHMARK(BM_ArcLength1000)->Name("BM_ArcLength1000/P6")->Unit(benchmark::kMillisecond);

}  // namespace
