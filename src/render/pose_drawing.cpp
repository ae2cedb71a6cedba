#include "render/pose_drawing.hpp"

#include <string>
#include <variant>
#include <vector>

#include "motion/stage.hpp"
#include "render/layers/pose_layers.hpp"
#include "render/pose_panel.hpp"
#include "render/static_layers.hpp"

namespace pita::render {

template <class Pose>
Drawing pose_panel_drawing(const motion::Stage& stage, std::size_t index, const FrameSelection* selection,
                           StaticLayers* cache) {
  if (selection == nullptr) cache = nullptr;  // the figure itself: drawn whole
  PosePanel<Pose> panel(stage, index, selection, cache);
  const scene::Panel& own = panel.panel();
  // The panel's own layers, else the scene's.
  const scene::LayersOf<scene::PoseLayer> drawn = scene::layers_of<scene::PoseLayer>(panel.scene(), own);
  const std::vector<scene::PoseLayer>& layers = drawn.layers;
  for (std::size_t i = 0; i < layers.size(); ++i) {
    panel.begin_layer(drawn.pointer(i));
    // A layer that casts shadows leaves them outside the drawing (take()
    // paints them): drawn at every frame.
    draw_layer(cache, index, i, panel.drawing(), [&] {
      const std::size_t shadows = panel.shadow_count();
      std::visit(
          [&panel]<class Layer>(const Layer& layer) {
            if constexpr (DrawnIn<Pose, Layer>) {
              draw_pose_layer(panel, layer);
            } else {
              // The reader refuses these in 3D scenes (the in_space column of
              // scene/layer_kinds.hpp); a scene built in code may still hold one.
              panel.fail("this layer type draws pose scenes of the plane only");
            }
          },
          layers[i]);
      return panel.took_frame() || panel.shadow_count() != shadows;
    });
  }
  return panel.take();
}

template Drawing pose_panel_drawing<Affine2>(const motion::Stage&, std::size_t, const FrameSelection*, StaticLayers*);
template Drawing pose_panel_drawing<Affine3>(const motion::Stage&, std::size_t, const FrameSelection*, StaticLayers*);

Drawing pose_panel_drawing(const scene::Scene& scene, const scene::Panel& panel, const FrameSelection* selection) {
  return pose_panel_drawing<Affine2>(motion::Stage(scene, panel), 0, selection);
}

Drawing space_panel_drawing(const scene::Scene& scene, const scene::Panel& panel, const FrameSelection* selection) {
  return pose_panel_drawing<Affine3>(motion::Stage(scene, panel), 0, selection);
}

}  // namespace pita::render
