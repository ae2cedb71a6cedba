// The geometry of a panel of a pose scene, in the plane or in space: every
// pose layer drawn by its kind's drawer (render/layers/pose_layers.hpp)
// through the panel's poses, motion and view (render/pose_panel.hpp).
#pragma once

#include <cstddef>

#include "core/affine2.hpp"
#include "core/affine3.hpp"
#include "render/drawing.hpp"
#include "render/panel_drawing.hpp"
#include "scene/scene.hpp"

namespace pita::render {

// Panel `index` of the stage, whose keys are poses of the plane (Pose =
// Affine2) or of space (Affine3). Throws RenderError.
template <class Pose>
Drawing pose_panel_drawing(const motion::Stage& stage, std::size_t index, const FrameSelection* selection = nullptr,
                           StaticLayers* cache = nullptr);

extern template Drawing pose_panel_drawing<Affine2>(const motion::Stage&, std::size_t, const FrameSelection*,
                                                    StaticLayers*);
extern template Drawing pose_panel_drawing<Affine3>(const motion::Stage&, std::size_t, const FrameSelection*,
                                                    StaticLayers*);

// One panel with a stage of its own: poses of the plane, of space.
Drawing pose_panel_drawing(const scene::Scene& scene, const scene::Panel& panel,
                           const FrameSelection* selection = nullptr);
Drawing space_panel_drawing(const scene::Scene& scene, const scene::Panel& panel,
                            const FrameSelection* selection = nullptr);

}  // namespace pita::render
