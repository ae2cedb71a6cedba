// Which motions read a method option, and the refusal of an option that none
// of those it is given to reads (it would change nothing): the scene's and a
// panel's "options" (scene/arrow_scene_reader.cpp), a layer's
// (render/panel_drawing.cpp), Python's keywords and `pita sweep --vary`
// through them.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "core/pitas/method_options.hpp"
#include "scene/motion_keys.hpp"

namespace pita::scene {

// Whether the keys' method reads `option` (core/pitas/registry.hpp
// reads_option): chained when the track runs through more keyframes or
// points than the method takes, or a "chain" is given. False for poses.
bool keys_read_option(const MotionKeys& keys, MethodOption option);

// "P6 La-LP does not read "anchor", so it would change nothing here; P2
// reads it" (one method), or "none of the methods it applies to (P6 La-LP,
// P8 Lo-Pe) reads ..." (several).
std::string unread_option_reason(std::span<const Method> methods, std::string_view key, MethodOption option);

}  // namespace pita::scene
