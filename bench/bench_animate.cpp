// Animation outputs of `pita animate` (src/animate). Run:
//   build/pita_bench --benchmark_filter=Animate
//   BM_AnimateFrames/120:  Fig. 23's 120 PNG frames at 800x600 written into a
//                          directory, frames rendered on every core (PITA_THREADS)
//   BM_AnimateSvg/120:     Fig. 23's animated SVG (120 frames), in memory
//   BM_AnimateFrame:       one frame of Fig. 23 as a PNG, one thread
// Peak memory is measured outside the benchmark (docs/reference/animate.md "Animation"):
//   /usr/bin/time -v build/pita animate scenes/fig23-image-motion.json -o /tmp/f --frames N
#include <algorithm>
#include <filesystem>
#include <thread>

#include <benchmark/benchmark.h>
#include <unistd.h>

#include "animate/frame.hpp"
#include "animate/frame_runner.hpp"
#include "animate/output.hpp"
#include "animate/svg_animation.hpp"
#include "scene/scene.hpp"

namespace {

using namespace pita;
namespace fs = std::filesystem;

scene::Scene fig23() { return scene::load_scene(fs::path(PITA_SOURCE_DIR) / "scenes" / "fig23-image-motion.json"); }

void BM_AnimateFrames(benchmark::State& state) {
  const scene::Scene scene = fig23();
  const animate::Timeline timeline =
      animate::make_timeline(scene, {std::nullopt, std::nullopt, static_cast<int>(state.range(0))});
  const fs::path dir = fs::temp_directory_path() / ("pita-bench-frames-" + std::to_string(::getpid()));
  animate::Request request;
  request.out = dir / "frames";
  request.kind = animate::AnimationOutput::directory;
  request.progress = false;
  request.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));  // every core
  for (auto _ : state) animate::write_animation(scene, timeline, request);
  fs::remove_all(dir);
  state.counters["threads"] = request.threads;
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_AnimateFrames)->Arg(120)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_AnimateSvg(benchmark::State& state) {
  const scene::Scene scene = fig23();
  const animate::Timeline timeline =
      animate::make_timeline(scene, {std::nullopt, std::nullopt, static_cast<int>(state.range(0))});
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string svg = animate::animated_svg(scene, timeline);
    bytes = svg.size();
    benchmark::DoNotOptimize(svg.data());
  }
  state.counters["bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_AnimateSvg)->Arg(120)->Unit(benchmark::kMillisecond);

void BM_AnimateFrame(benchmark::State& state) {
  const scene::Scene scene = fig23();
  const animate::Timeline timeline = animate::make_timeline(scene);
  const auto placements = animate::animation_layout(scene, timeline);
  int k = 0;
  for (auto _ : state) {
    const render::Figure figure = animate::frame_figure(scene, timeline, timeline.time(k), placements);
    const std::string png = render::render_figure(scene, figure, render::Format::png);
    benchmark::DoNotOptimize(png.data());
    k = (k + 37) % timeline.frames;
  }
}
BENCHMARK(BM_AnimateFrame)->Unit(benchmark::kMillisecond);

}  // namespace
