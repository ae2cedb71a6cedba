// "compare" in an arrow scene (appendix B, Fig. B.30): another method's
// pattern over the panel's own, and their largest endpoint distance.
#include <cmath>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "analysis/arrow_distance.hpp"
#include "render/layer_cost.hpp"
#include "render/panel_builder.hpp"

namespace pita::render::detail {

// "compare" (appendix B, Fig. B.30): the pattern of another method through
// the panel's keyframes over the panel's own, and the printed line
// "max |P3 - P10| = 2.1e-15", the largest endpoint distance between frames
// at the same times (analysis/arrow_distance.hpp).
void PanelBuilder::add(const scene::CompareLayer& layer) {
  const std::vector<double> times = sequence_times(layer.samples, std::nullopt);
  const std::vector<Arrow> own = frames(times);
  std::vector<Arrow> other;
  try {
    const motion::SceneMotion motion = motion::with_method(scene_, panel_, layer.method);
    for (const double t : times) other.push_back(motion.arrow_at(t));
  } catch (const motion::NoMotion& error) {
    fail(layer_ + "/method", error.reason());
  }
  for (std::size_t i = 0; i < other.size(); ++i) {
    LineStyle line = layer.line;
    line.opacity *= fade(i, other.size());
    push(static_cast<int>(i), Polyline{{other[i].p, other[i].q()}, false, line});
  }
  const double distance = analysis::pattern_distance(own, other);
  if (!std::isfinite(distance)) fail(layer_, "the distance between the two patterns is not finite");
  const Color text{0.1, 0.1, 0.1, 1.0};
  if (selection() == nullptr) {
    add_lines({{text, fmt::format("max |{} \u2212 {}| = {:.3g}", scene::method_id(panel_.keys), layer.method_name,
                                  distance)}},
              layer.at, layer.corner, layer.size, text);
  }
}

// Its cost (render/layer_cost.hpp).
void LayerCost::operator()(const scene::CompareLayer& l) { frames(l.samples, "a compared pattern", kShapeUnits + 1); }

}  // namespace pita::render::detail
