// "label": a text at a point of the figure, in both kinds of scene.
#include "render/layer_cost.hpp"
#include "render/layers/pose_layers.hpp"
#include "render/panel_builder.hpp"

namespace pita::render {

void draw_pose_layer(PosePanel<Affine2>& panel, const scene::LabelLayer& layer) {
  panel.push(-1, Label{layer.text, layer.at, layer.size, layer.color, layer.avoid_data});
}

// In an arrow scene.
namespace detail {

void PanelBuilder::add(const scene::LabelLayer& layer) {
  push(-1, Label{layer.text, layer.at, layer.size, layer.color, layer.avoid_data});
}

}  // namespace detail

// Its cost (render/layer_cost.hpp).
namespace detail {

void LayerCost::operator()(const scene::LabelLayer& l) {
  add(layer_, "a label", kShapeUnits + static_cast<double>(l.text.size()));
}

}  // namespace detail

}  // namespace pita::render
