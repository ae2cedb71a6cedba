// Colours of a scene: "#rgb", "#rrggbb", "#rrggbbaa" (hex digits in any case)
// or one of a few names (docs/reference/render.md "Figures", schema/scene.schema.json).
#pragma once

#include <span>
#include <string_view>

#include "scene/figure.hpp"

namespace pita::scene {

struct NamedColor {
  std::string_view name;  // lower case
  std::string_view hex;   // "#rrggbb", as documented in the schema
};

// The colour names a scene may use, in the order the messages list them.
std::span<const NamedColor> named_colors();

// The colour written `text`. Throws std::invalid_argument with a reason such as
//   unknown color "rde"; did you mean "red"?
//   "#12345" is not a color: "#" must be followed by 3, 6 or 8 hex digits
Color parse_color(std::string_view text);

// The colour of the i-th keyframe (or pose) of a "keyframes" ("poses") layer:
// the layer's own "colors" cycled, or when it gives none (`given` empty) the
// default series: red, green and blue, then orange, purple, teal, brown,
// magenta, olive, and after those hues a golden angle apart. The default
// series never repeats a colour (as "#rrggbb") below kMaxKeyframes, so the
// keyframes of any scene are told apart without a "colors" field.
Color series_color(std::span<const Color> given, std::size_t i);

}  // namespace pita::scene
