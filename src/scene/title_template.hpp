// Titles that name fields of their scene: "A house carried by {/method}"
// shows the scene's method ("{/keyframes/1/t}" the second knot), so that a
// sweep's variants, or any scene, say what they draw
// (docs/reference/scene-format.md "Titles that name fields").
#pragma once

#include <string>

#include "scene/json_reader.hpp"

namespace pita::scene::detail {

// `title` (at `pointer`) with each "{/json/pointer}" replaced by the value
// at that pointer of `document`: a string as it is, a number in its
// shortest exact form, true, false or null. Fails at `pointer` for a pointer
// that names no field, or an object or array.
std::string expand_title(const JsonReader& reader, const Json& document, const std::string& title,
                         const std::string& pointer);

}  // namespace pita::scene::detail
