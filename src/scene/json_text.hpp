// Parsing a scene's JSON text (internal to src/scene/).
#pragma once

#include <string>
#include <string_view>

#include "scene/json_reader.hpp"

namespace pita::scene::detail {

// The document, or SceneError at the file's line and column (malformed JSON,
// a NUL byte, a number too large for a double) or at the JSON Pointer of a
// member given twice.
Json parse_json(std::string_view text, const std::string& file);

}  // namespace pita::scene::detail
