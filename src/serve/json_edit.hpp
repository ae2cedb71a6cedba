// Edits of a JSON text that keep everything else of it: the key order, the
// spacing, the line breaks and the spelling of every number not edited
// (`pita serve --edit` writes a dragged keyframe back into its scene file).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace pita::serve {

// Where the value at `pointer` (RFC 6901; "" for the whole document) is in
// `text`: the bytes [begin, end). Throws std::invalid_argument when the text
// is not JSON or has no such value.
struct TextSpan {
  std::size_t begin = 0;
  std::size_t end = 0;
};
TextSpan value_span(std::string_view text, std::string_view pointer);

// `text` with the value at `pointer` replaced by `replacement` (JSON text),
// every other byte as it was. Throws as value_span does.
std::string replace_value(std::string_view text, std::string_view pointer, std::string_view replacement);

}  // namespace pita::serve
