// Reading "animation" (docs/reference/animate.md "Animation"): how `pita animate` and
// `pita render --at` play a scene. Internal to src/scene/.
#pragma once

#include <string>

#include "scene/figure.hpp"
#include "scene/json_reader.hpp"

namespace pita::scene::detail {

// {"duration", "fps", "frames", "loop", "what", "trail", "overlay"}, every
// field optional. `moving`: whether any keyframe of the scene moves ("what"
// then defaults to "pattern", and "pattern" needs it). `poses`: a pose scene
// (nothing moves; the messages say so).
Animation read_animation(const JsonReader& reader, const Json& value, const std::string& pointer, bool moving,
                         bool poses = false);

// The default animation of a scene without "animation".
Animation default_animation(bool moving);

}  // namespace pita::scene::detail
