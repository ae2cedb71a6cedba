#include "scene/did_you_mean.hpp"

#include <algorithm>
#include <numeric>

namespace pita::scene {

namespace {

char lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

}  // namespace

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // One row of the dynamic-programming table at a time.
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];  // table[i-1][j-1]
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];  // table[i-1][j]
      const std::size_t substitution = diagonal + (lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1);
      row[j] = std::min({above + 1, row[j - 1] + 1, substitution});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::vector<std::string> closest_names(std::string_view name, std::span<const std::string_view> known) {
  std::vector<std::size_t> distances;
  distances.reserve(known.size());
  for (std::string_view candidate : known) distances.push_back(edit_distance(name, candidate));
  std::vector<std::string> result;
  if (distances.empty()) return result;
  const std::size_t best = *std::min_element(distances.begin(), distances.end());
  if (best > kMaxSuggestionDistance || (best > 0 && best >= name.size())) return result;
  for (std::size_t i = 0; i < known.size(); ++i) {
    if (distances[i] == best) result.emplace_back(known[i]);
  }
  return result;
}

std::string alternatives(std::span<const std::string> names, bool quoted) {
  const std::string_view quote = quoted ? "\"" : "";
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) text += (i + 1 == names.size()) ? " or " : ", ";
    text += quote;
    text += names[i];
    text += quote;
  }
  return text;
}

std::string did_you_mean(std::span<const std::string> suggestions, bool quoted) {
  if (suggestions.empty()) return {};
  return "; did you mean " + alternatives(suggestions, quoted) + "?";
}

}  // namespace pita::scene
