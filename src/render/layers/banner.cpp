// "banner" in an arrow scene (Sec. 7.3): a text's outlines mapped through the
// quad strip of the frames (render/banner.hpp).
#include <utility>
#include <vector>

#include "render/banner.hpp"
#include "render/panel_builder.hpp"

namespace pita::render::detail {

void PanelBuilder::add(const scene::BannerLayer& layer) {
  const std::vector<Arrow> pattern = frames(layer_times(panel_, layer.samples, layer.range));
  const QuadStrip strip(pattern);
  FilledPath glyphs{map_through_strip(text_outline(layer.text, layer.font), strip, layer.padding),
                    layer.fill, layer.opacity, layer.outline};
  push(-1, std::move(glyphs));
}

}  // namespace pita::render::detail
