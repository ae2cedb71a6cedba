// PNG encoding alone (src/render/png_writer.cpp): one painted figure encoded
// again and again, by cairo's writer (libpng's defaults: adaptive filtering)
// and by pita's with several row filters and zlib levels, to choose the
// default. Run: build/pita_bench --benchmark_filter=PngEncode
//   BM_PngEncode/<scene>/<writer>: ms per encoding; "bytes": the file's size
#include <cmath>
#include <string>

#include <benchmark/benchmark.h>
#include <png.h>

#include "render/cairo_handles.hpp"
#include "render/figure.hpp"
#include "render/png_writer.hpp"
#include "scene/scene.hpp"

namespace {

using namespace pita;

render::SurfacePtr painted(const std::string& scene_file) {
  const scene::Scene scene = scene::load_scene(std::string(PITA_SOURCE_DIR) + "/scenes/" + scene_file);
  const render::Figure figure = render::build_figure(scene);
  render::SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, scene.canvas.width, scene.canvas.height));
  render::ContextPtr cr(cairo_create(surface.get()));
  render::paint_figure(cr.get(), scene, figure);
  cairo_surface_flush(surface.get());
  return surface;
}

// filters < 0: cairo's own writer.
void BM_PngEncode(benchmark::State& state, std::string scene_file, int filters, int level, int strategy = 0) {
  const render::SurfacePtr surface = painted(scene_file);
  std::size_t size = 0;
  for (auto _ : state) {
    std::string bytes;
    if (filters < 0) {
      cairo_surface_write_to_png_stream(surface.get(), render::append_to_string, &bytes);
    } else {
      render::write_png(surface.get(), bytes, render::PngSettings{filters, level, strategy});
    }
    size = bytes.size();
    benchmark::DoNotOptimize(bytes.data());
  }
  state.counters["bytes"] = static_cast<double>(size);
}

#define PITA_PNG_BENCH(name, file)                                                                                \
  BENCHMARK_CAPTURE(BM_PngEncode, name##_cairo, file, -1, 0)->Unit(benchmark::kMillisecond);                      \
  BENCHMARK_CAPTURE(BM_PngEncode, name##_all_6, file, PNG_ALL_FILTERS, 6)->Unit(benchmark::kMillisecond);         \
  BENCHMARK_CAPTURE(BM_PngEncode, name##_none_6, file, PNG_FILTER_NONE, 6)->Unit(benchmark::kMillisecond);        \
  BENCHMARK_CAPTURE(BM_PngEncode, name##_none_1, file, PNG_FILTER_NONE, 1)->Unit(benchmark::kMillisecond);        \
  BENCHMARK_CAPTURE(BM_PngEncode, name##_none_3, file, PNG_FILTER_NONE, 3)->Unit(benchmark::kMillisecond);        \
  BENCHMARK_CAPTURE(BM_PngEncode, name##_none_4, file, PNG_FILTER_NONE, 4)->Unit(benchmark::kMillisecond);        \
  BENCHMARK_CAPTURE(BM_PngEncode, name##_none_6_rle, file, PNG_FILTER_NONE, 6, 3)->Unit(benchmark::kMillisecond); \
  BENCHMARK_CAPTURE(BM_PngEncode, name##_up_6, file, PNG_FILTER_UP, 6)->Unit(benchmark::kMillisecond);            \
  BENCHMARK_CAPTURE(BM_PngEncode, name##_sub_6, file, PNG_FILTER_SUB, 6)->Unit(benchmark::kMillisecond)

PITA_PNG_BENCH(fig01, "fig01-eight-pitas.json");
PITA_PNG_BENCH(fig23_image, "fig23-image-motion.json");
PITA_PNG_BENCH(fig25_strokes, "fig25-strokes.json");

}  // namespace
