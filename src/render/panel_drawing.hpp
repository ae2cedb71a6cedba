// The geometry of one panel: every layer of the scene evaluated on the
// panel's keyframes and method (scene/figure.hpp says what each layer draws).
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "render/drawing.hpp"
#include "scene/located_error.hpp"
#include "scene/scene.hpp"

namespace pita::motion {
class Stage;  // motion/stage.hpp
}

namespace pita::render {

// A figure that cannot be drawn: the motion does not exist, or a frame is not
// finite. A located error (scene/located_error.hpp): what() is
// "FILE: POINTER: reason", as scene errors are.
class RenderError : public scene::LocatedError {
 public:
  RenderError(std::string file, std::string pointer, std::string reason)
      : LocatedError(scene::LocatedKind::render, std::move(file), std::move(pointer), std::move(reason)) {}
};

// One frame of an animation ("what": "motion", docs/reference/animate.md "Animation"): the
// layers that draw a sequence of frames ("pattern", "shapes") draw the frame
// at scene time `t` and, fading behind it, the frames at the `trail` times
// (oldest first); their items are marked `moving`. Every other layer is drawn
// as in the static figure.
struct FrameSelection {
  double t = 0.0;
  std::vector<double> trail;
};

// The opacity factor of entry i of trail + {t} (count entries, the last is t
// itself at 1): (i + 1) / count.
double trail_fade(std::size_t i, std::size_t count);

// The times a "shapes" layer draws: an animation frame's trail and time, else
// `all` (the layer's own samples).
std::vector<double> selected_times(const FrameSelection* selection, std::vector<double> all);

// "lightness": "area" (SAM Fig. 9, docs/paper-notes.md N48): the white mixed
// into each frame, from none at the smallest measure (area in 2D, volume in
// 3D) to 0.8 at the largest; all none when they are equal.
std::vector<double> lightness_whites(const std::vector<double>& measures);

// The colour mixed with white by `white` in [0, 1] (alpha kept).
Color lightened(Color color, double white);

class StaticLayers;  // render/static_layers.hpp

// The shapes of every layer of the stage's scene for its panel `index`, in
// drawing order, with the motion the stage built. With a selection and a
// cache, the layers that read nothing of the frame are copied from the cache
// once it holds them. Throws RenderError.
Drawing panel_drawing(const motion::Stage& stage, std::size_t index, const FrameSelection* selection = nullptr,
                      StaticLayers* cache = nullptr);
// The same for `panel` alone (a stage of its own).
Drawing panel_drawing(const scene::Scene& scene, const scene::Panel& panel, const FrameSelection* selection = nullptr);

// The times a pattern-like layer samples: `samples` (else the panel's) evenly
// over `range` (else [a, c], the first and last knots).
std::vector<double> layer_times(const scene::Panel& panel, const std::optional<int>& samples,
                                const std::optional<scene::TimeRange>& range);

}  // namespace pita::render
