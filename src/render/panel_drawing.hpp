// The geometry of one panel: every layer of the scene evaluated on the
// panel's keyframes and method (scene/figure.hpp says what each layer draws).
#pragma once

#include <stdexcept>
#include <string>

#include "render/drawing.hpp"
#include "scene/scene.hpp"

namespace pita::render {

// A figure that cannot be drawn: the motion does not exist, or a frame is not
// finite. what() is "FILE: POINTER: reason", as scene errors are.
class RenderError : public std::runtime_error {
 public:
  RenderError(const std::string& file, const std::string& pointer, const std::string& reason);
};

// The shapes of every layer of `scene` for `panel`, in drawing order. Throws
// RenderError.
Drawing panel_drawing(const scene::Scene& scene, const scene::Panel& panel);

// The times a pattern-like layer samples: `samples` (else the panel's) evenly
// over `range` (else [a, c], the first and last knots).
std::vector<double> layer_times(const scene::Panel& panel, const std::optional<int>& samples,
                                const std::optional<scene::TimeRange>& range);

}  // namespace pita::render
