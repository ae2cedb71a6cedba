// "label" in a pose scene: a text at a point of the figure.
#include "render/layers/pose_layers.hpp"

namespace pita::render {

void draw_pose_layer(PosePanel<Affine2>& panel, const scene::LabelLayer& layer) {
  panel.push(-1, Label{layer.text, layer.at, layer.size, layer.color});
}

}  // namespace pita::render
