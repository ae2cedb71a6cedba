// The family of a scene's layers names its kind of figure scene, where both
// kinds read the same thing with different rules: `Layer` in arrow scenes
// (keyframes or points), `PoseLayer` in pose scenes (poses of the plane or of
// space). The readers of what both kinds of scene have (the "measures",
// "plot" and "shapes" layers, "claims", "animation"; scene/measure_name.hpp)
// are templates over the family, as scene::layers_of<LayerType> is, and ask
// LayerFamily<LayerType> rather than take a flag. A third family fails to
// compile until it has its row here.
#pragma once

#include "scene/layers.hpp"

namespace pita::scene {

template <class LayerType>
struct LayerFamily;

template <>
struct LayerFamily<Layer> {
  // Poses move shapes with an area ("lightness": "area", a plot "of": "area");
  // keyframes may move (an animation of the "pattern", "overlay").
  static constexpr bool moves_poses = false;
};

template <>
struct LayerFamily<PoseLayer> {
  static constexpr bool moves_poses = true;
};

}  // namespace pita::scene
