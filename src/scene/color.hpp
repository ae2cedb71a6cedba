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

}  // namespace pita::scene
