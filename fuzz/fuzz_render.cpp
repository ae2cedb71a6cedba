// A parsed scene -> its figure as SVG, in memory (render::build_figure and
// render::render_figure, what `pita render` does before writing). The limits
// are the library's to enforce: nothing is capped here. Refusals are
// SceneError (the scene) and RenderError (the figure: no motion for a panel,
// a drawing that is not finite, ...), both naming the file.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.hpp"
#include "render/figure.hpp"
#include "render/panel_drawing.hpp"
#include "scene/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pita;
  try {
    const scene::Scene s = scene::parse_scene(fuzz::text_of(data, size), "fuzz.json");
    const render::Figure figure = render::build_figure(s);
    const std::string svg = render::render_figure(s, figure, render::Format::svg);
    PITA_FUZZ_CHECK(svg.rfind("<?xml", 0) == 0 || svg.find("<svg") != std::string::npos);
  } catch (const scene::SceneError&) {
  } catch (const render::RenderError&) {
  }
  return 0;
}
