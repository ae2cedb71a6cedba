// The animated SVG of `pita animate OUT.svg` (docs/reference/animate.md "Animation"): one file
// that plays in any browser by SMIL alone (no script). What every frame shares
// is drawn once by cairo (the background, titles, the layers that do not
// move, legends), as two nested <svg> documents below and above the frames;
// each frame is a group of what moves, shown during its 1/fps seconds by a
// discrete <animate> of its visibility. Images are embedded once in <defs>
// and placed by <use transform>.
#pragma once

#include <functional>
#include <string>

#include "animate/timeline.hpp"
#include "motion/stage.hpp"
#include "render/static_layers.hpp"
#include "scene/scene.hpp"

namespace pita::animate {

// The animated SVG's text. `progress(k)` is called after frame k (0-based).
// Throws RenderError as the frames do. `stage`, for a "motion" timeline: the
// scene's motions built once by the caller (frame.hpp), so that a motion
// that is costly to build (an arc-length warp of a long track) is built once
// for the layout and every frame; nullptr builds them here, once. `layers`:
// the layers drawn once for every frame (frame_figure), the caller's or,
// when nullptr, a cache of its own.
std::string animated_svg(const scene::Scene& scene, const Timeline& timeline,
                         const std::function<void(int)>& progress = {}, const motion::Stage* stage = nullptr,
                         render::StaticLayers* layers = nullptr);

}  // namespace pita::animate
