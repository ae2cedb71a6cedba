// "handle" in an arrow scene (Sec. 7.1): the shapes in their own frame and the
// handle arrow over them.
#include <utility>

#include "render/carried_shapes.hpp"
#include "render/layer_cost.hpp"
#include "render/panel_builder.hpp"

namespace pita::render::detail {

void PanelBuilder::add(const scene::HandleLayer& layer) {
  if (layer.shapes) {
    scene::ShapesLayer style;
    for (Shape& shape : carried_shapes(scene::figure_of<scene::KeyframeKeys>(panel_).shapes, Affine2::identity(), style,
                                       scene_.canvas.y_up)) {
      push(-1, std::move(shape));
    }
  }
  push(-1, ArrowShape{handle().p, handle().q(), LineStyle{layer.color, layer.width, 1.0, {}}});
}

// Its cost (render/layer_cost.hpp).
void LayerCost::operator()(const scene::HandleLayer&) {
  add(layer_, "the handle and its shapes", kShapeUnits + shapes_units());
}

}  // namespace pita::render::detail
