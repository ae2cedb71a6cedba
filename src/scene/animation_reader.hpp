// Reading "animation" (docs/reference/animate.md "Animation"): how `pita animate` and
// `pita render --at` play a scene. Internal to src/scene/.
#pragma once

#include <string>

#include "scene/figure.hpp"
#include "scene/json_reader.hpp"

namespace pita::scene::detail {

// {"duration", "fps", "frames", "loop", "what", "trail", "overlay"}, every
// field optional, in a scene whose layers are `LayerType` (scene/layer_family.hpp).
// `moving`: whether any keyframe of the scene moves ("what" then defaults to
// "pattern", and "pattern" needs it). A pose scene has no keyframes (nothing
// moves; the messages say so).
template <class LayerType>
Animation read_animation(const JsonReader& reader, const Json& value, const std::string& pointer, bool moving);

// The default animation of a scene without "animation".
Animation default_animation(bool moving);

}  // namespace pita::scene::detail
