// Time to draw one figure, from the scene file to the output bytes (nothing
// written to disk). Run: build/pita_bench --benchmark_filter=Render
//   BM_Render/<scene>/<format>: load + build + render, ms per figure
#include <string>

#include <benchmark/benchmark.h>

#include "render/figure.hpp"
#include "scene/scene.hpp"

namespace {

using namespace pita;

// `width` x `height` overrides the scene's canvas when given (the issue's
// target is stated for a Fig. 1-like figure at 1200x900).
void BM_Render(benchmark::State& state, std::string scene_file, render::Format format, int width = 0, int height = 0) {
  const std::string path = std::string(PITA_SOURCE_DIR) + "/scenes/" + scene_file;
  std::size_t bytes = 0;
  for (auto _ : state) {
    scene::Scene scene = scene::load_scene(path);
    if (width > 0) {
      scene.canvas.width = width;
      scene.canvas.height = height;
    }
    const render::Figure figure = render::build_figure(scene);
    bytes = render::render_figure(scene, figure, format).size();
    benchmark::DoNotOptimize(bytes);
  }
  state.counters["bytes"] = static_cast<double>(bytes);
}

BENCHMARK_CAPTURE(BM_Render, fig01_svg_1200x900, "fig01-eight-pitas.json", render::Format::svg, 1200, 900)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Render, fig01_png_1200x900, "fig01-eight-pitas.json", render::Format::png, 1200, 900)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Render, fig01_pdf_1200x900, "fig01-eight-pitas.json", render::Format::pdf, 1200, 900)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Render, fig26_svg, "fig26-banners.json", render::Format::svg)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Render, fig26_png, "fig26-banners.json", render::Format::png)->Unit(benchmark::kMillisecond);

}  // namespace
