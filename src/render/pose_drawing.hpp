// The geometry of one panel of a pose scene (SAM paper): the layers of
// scene/figure.hpp's "pose scenes" part, evaluated on the panel's poses and
// method, in world coordinates.
#pragma once

#include "render/drawing.hpp"
#include "render/layers/existence.hpp"
#include "render/layers/sam3d_existence.hpp"
#include "render/panel_drawing.hpp"
#include "scene/scene.hpp"

namespace pita::render {

// The shapes of every pose layer of `scene` for `panel`, in drawing order.
// Throws RenderError.
// With a selection (an animation frame), the "shapes" layers draw the shapes
// at the selection's time and trail only.
Drawing pose_panel_drawing(const scene::Scene& scene, const scene::Panel& panel,
                           const FrameSelection* selection = nullptr);
// The same for the stage's panel `index`, with the motion the stage built.
Drawing pose_panel_drawing(const motion::Stage& stage, std::size_t index, const FrameSelection* selection = nullptr);

}  // namespace pita::render
