// "banner" in an arrow scene (Sec. 7.3): a text's outlines mapped through the
// quad strip of the frames (render/text_outline.hpp).
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "render/layer_cost.hpp"
#include "render/panel_builder.hpp"
#include "render/text_outline.hpp"

namespace pita::render::detail {

void PanelBuilder::add(const scene::BannerLayer& layer) {
  const std::vector<Arrow> pattern = frames(layer_times(panel_, layer.samples, layer.range));
  const QuadStrip strip(pattern);
  FilledPath glyphs{map_through_strip(text_outline(layer.text, layer.font), strip, layer.padding), layer.fill,
                    layer.opacity, layer.outline};
  push(-1, std::move(glyphs));
}

// Its cost (render/layer_cost.hpp).
void LayerCost::operator()(const scene::BannerLayer& l) {
  // The glyph outlines, split into short edges, then the strip's quads.
  add(layer_ + "/text", fmt::format("{} characters of a banner", l.text.size()),
      400.0 * static_cast<double>(l.text.size()));
  frames(l.samples, "a banner's strip", 4);
}

}  // namespace pita::render::detail
