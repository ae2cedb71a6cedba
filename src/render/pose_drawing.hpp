// The geometry of one panel of a pose scene (SAM paper): the layers of
// scene/figure.hpp's "pose scenes" part, evaluated on the panel's poses and
// method, in world coordinates.
#pragma once

#include "analysis/sam3d_existence.hpp"
#include "render/drawing.hpp"
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

// The "existence" layer alone (Fig. 6 of the SAM paper): exposed for tests.
// Cells are rectangles [a0, a1] x [h s0, h s1] with h = kExistenceHeight.
inline constexpr double kExistenceHeight = 3.141592653589793;  // drawn height of s in [0, 1]
Drawing existence_drawing(const scene::ExistenceLayer& layer, const std::string& pointer);

// The "sam3d-existence" layer (the SAM paper's Sec. 5.2 experiment as a
// plot): x = theta in [0, pi], y = scene::kSafeCurveScale p. The first
// computes the curve (seconds: analysis/sam3d_existence.hpp), the second
// draws a given one (for tests).
Drawing sam3d_existence_drawing(const scene::Sam3dExistenceLayer& layer, const std::string& pointer);
Drawing sam3d_existence_drawing(const scene::Sam3dExistenceLayer& layer, const analysis::SafeCurve& curve,
                                const std::string& pointer);

}  // namespace pita::render
