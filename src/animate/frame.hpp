// One frame of an animation as a figure (docs/reference/animate.md "Animation"), and the view
// every frame shares: frame k of `pita animate` is exactly the figure that
// `pita render --at t_k` draws.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "animate/timeline.hpp"
#include "motion/stage.hpp"
#include "render/figure.hpp"
#include "render/static_layers.hpp"
#include "scene/scene.hpp"

namespace pita::animate {

// The frames the layout draws besides the static figure (animation_layout).
inline constexpr int kLayoutFrames = 33;

// The placements of every frame: the layout of the drawings that cover the
// whole animation (the static figure, and frames at 33 times spread over the
// timeline; for "pattern", the figure at 33 values of tau), so that the view
// does not jump from frame to frame. A canvas "view" is used as given.
// Only each cover frame's bounds are kept, and a "motion" timeline builds its
// motions once (not once per cover frame), or uses `stage`, the scene's
// motions built by the caller for the frames too; the cover frames draw the
// layers that read nothing of the frame once, into `layers` when given (the
// frames' own, frame_figure), else into a cache of their own.
std::vector<render::PanelPlacement> animation_layout(const scene::Scene& scene, const Timeline& timeline,
                                                     const motion::Stage* stage = nullptr,
                                                     render::StaticLayers* layers = nullptr);

// The figure at time t (a scene time for "motion", tau for "pattern") with the
// shared placements. "motion": the layers that draw frames ("pattern",
// "shapes") draw D(t) (or A(t)) and the timeline's trail; the rest is the
// static figure. "pattern": the whole figure through the keyframes at tau,
// every item but the labels moving. Throws RenderError. `stage`, for a
// "motion" timeline: the scene's motions, built once by the caller for all
// its frames (a const Stage is shared safely between threads); nullptr
// builds them for this frame. `layers`: shared by the frames of one stage,
// the layers that read nothing of the frame, drawn once
// (render/static_layers.hpp); nullptr draws every layer.
render::Figure frame_figure(const scene::Scene& scene, const Timeline& timeline, double t,
                            const std::vector<render::PanelPlacement>& placements, const motion::Stage* stage = nullptr,
                            render::StaticLayers* layers = nullptr);

// What frames.json records of frame k: {"frame": k + 1, "file", "t" (and
// "tau" = ease(t) for "pattern"), and the first panel's state: "D": {"p", "m",
// "w", "q"} (arrow scenes), "A": [[a, b, tx], [c, d, ty]] (pose scenes), "p"
// (timed points) or "keyframes": [...] at tau ("pattern"); with several panels
// also "panels": [{"pointer", "title", and the same state}, ...]}. `stage`:
// as for frame_figure.
nlohmann::ordered_json frame_record(const scene::Scene& scene, const Timeline& timeline, int k, const std::string& file,
                                    const motion::Stage* stage = nullptr);

}  // namespace pita::animate
