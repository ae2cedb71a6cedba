// Points and arrows as pita writes them in JSON, the form a scene file gives
// a keyframe's arrow in (docs/reference/scene-format.md): a point [x, y], an
// arrow {"p": [x, y], "m": m, "w": w}. The one writer of an arrow for the
// Python module's scenes, the audit report and the animation frames; a
// writer that adds members (a keyframe's "t" before them, a frame's tip "q"
// after) adds them around these.
#pragma once

#include <nlohmann/json.hpp>

#include "core/arrow.hpp"

namespace pita::scene {

nlohmann::ordered_json point_json(Point p);
nlohmann::ordered_json arrow_json(const Arrow& a);

}  // namespace pita::scene
