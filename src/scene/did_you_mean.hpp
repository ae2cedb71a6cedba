// "Did you mean" suggestions for misspelt names (habit copied from ninja's
// subtool table): the known names closest to a misspelt one.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace pita::scene {

// The largest edit distance at which a known name is still suggested.
inline constexpr std::size_t kMaxSuggestionDistance = 2;

// Levenshtein distance (insertions, deletions, substitutions), ignoring ASCII
// case: "Keyframes" and "keyframes" are at distance 0.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The known names closest to `name`, in the order of `known`: those at the
// smallest distance d, provided d <= kMaxSuggestionDistance and d is smaller
// than the length of `name` (so that "x" does not suggest every one-letter
// field). Empty when nothing is close.
std::vector<std::string> closest_names(std::string_view name, std::span<const std::string_view> known);

// `a`, `a or b`, `a, b or c`: for messages; each name in double quotes when
// `quoted`.
std::string alternatives(std::span<const std::string> names, bool quoted = true);

// `; did you mean "a" or "b"?`, or "" when there is no suggestion.
std::string did_you_mean(std::span<const std::string> suggestions, bool quoted = true);

}  // namespace pita::scene
