// Edits of a JSON text that keep everything else of it: the key order, the
// spacing, the line breaks and the spelling of every number not edited
// (`pita serve --edit` writes a dragged keyframe back into its scene file).
#pragma once

#include <cstddef>
#include <optional>
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

// What takes an edit back: the value at `pointer` becomes `value` again, or
// the member at `pointer` is removed (nullopt: the edit added it).
struct Undo {
  std::string pointer;
  std::optional<std::string> value;
};

// `text` with the value at `pointer` set to `value` (JSON text): replaced
// when it is there, else added as the last member of its object, spaced as
// that object's last member is (its line break and indent, or its space,
// and the spacing around its ':'); objects missing on the way are added
// too, on one line ({"camera": {"azimuth": 30}}). Every other byte stays.
// `undo` (when given) receives what takes it back: remove_member of what
// was added gives the text back byte for byte. Throws std::invalid_argument
// when the text is not JSON, or the value would go into an array or a value
// that is not an object.
std::string set_value(std::string_view text, std::string_view pointer, std::string_view value, Undo* undo = nullptr);

// `text` without the member at `pointer`, its comma and the spacing before
// it (the bytes set_value adds). Throws std::invalid_argument when there is none.
std::string remove_member(std::string_view text, std::string_view pointer);

}  // namespace pita::serve
