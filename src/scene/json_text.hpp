// Reading the JSON text of a scene (and of a golden data file): the file
// with a size limit, the text with a nesting limit checked before any DOM is
// built, and the checks the DOM cannot make afterwards. Shared by src/scene/
// and src/golden/; every failure is a SceneError naming the file and a line
// and column (or the JSON Pointer of a member given twice).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace pita::scene {

// The bytes of `path`, at most `max_bytes` of them: a larger file (or an
// endless one, /dev/zero) is refused after reading max_bytes + 1, never read
// whole. `what` names the file in messages ("scene file", "golden data file").
// Throws SceneError.
std::string read_input_file(const std::filesystem::path& path, std::size_t max_bytes, std::string_view what);

// The document, or SceneError at the file's line and column (malformed JSON,
// a NUL byte, nesting deeper than kMaxJsonDepth, a number too large for a
// double) or at the JSON Pointer of a member given twice.
nlohmann::ordered_json parse_json(std::string_view text, const std::string& file);

}  // namespace pita::scene
