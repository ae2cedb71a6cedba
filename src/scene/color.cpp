#include "scene/color.hpp"

#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "scene/did_you_mean.hpp"

namespace pita::scene {

namespace {

// Darker than the CSS primaries where those are hard to see on white.
constexpr std::array<NamedColor, 13> kNamedColors = {{
    {"black", "#000000"},
    {"white", "#ffffff"},
    {"red", "#d00000"},
    {"green", "#00a000"},
    {"blue", "#0000d0"},
    {"gray", "#808080"},
    {"grey", "#808080"},
    {"orange", "#ff8c00"},
    {"purple", "#800080"},
    {"brown", "#8b4513"},
    {"magenta", "#d000d0"},
    {"cyan", "#00b0c0"},
    {"yellow", "#f0c800"},
}};

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// "#rgb", "#rrggbb" or "#rrggbbaa"; nullopt when `text` is none of them.
std::optional<Color> parse_hex(std::string_view text) {
  if (text.empty() || text[0] != '#') return std::nullopt;
  const std::string_view digits = text.substr(1);
  if (digits.size() != 3 && digits.size() != 6 && digits.size() != 8) return std::nullopt;
  std::vector<int> values;
  for (char c : digits) {
    const int value = hex_digit(c);
    if (value < 0) return std::nullopt;
    values.push_back(value);
  }
  std::array<double, 4> channels = {0.0, 0.0, 0.0, 1.0};
  if (values.size() == 3) {
    for (std::size_t i = 0; i < 3; ++i) channels[i] = (values[i] * 17) / 255.0;
  } else {
    for (std::size_t i = 0; i < values.size() / 2; ++i) {
      channels[i] = (values[2 * i] * 16 + values[2 * i + 1]) / 255.0;
    }
  }
  return Color{channels[0], channels[1], channels[2], channels[3]};
}

// The default series (series_color): the keyframes layer's red, green and
// blue of old first, then hues apart from them and from each other.
constexpr std::array<Color, 9> kSeries = {{
    {0.85, 0.0, 0.0, 1.0},
    {0.0, 0.6, 0.0, 1.0},
    {0.0, 0.0, 0.85, 1.0},
    {0.9, 0.5, 0.0, 1.0},
    {0.5, 0.0, 0.65, 1.0},
    {0.0, 0.55, 0.55, 1.0},
    {0.55, 0.3, 0.05, 1.0},
    {0.85, 0.0, 0.55, 1.0},
    {0.45, 0.5, 0.0, 1.0},
}};

// Hue h (turns), saturation s, value v to RGB (the HSV hexcone).
Color from_hsv(double h, double s, double v) {
  const double sector = 6.0 * (h - std::floor(h));
  const int k = static_cast<int>(sector) % 6;
  const double f = sector - std::floor(sector);
  const double p = v * (1.0 - s), q = v * (1.0 - s * f), t = v * (1.0 - s * (1.0 - f));
  switch (k) {
    case 0:
      return {v, t, p, 1.0};
    case 1:
      return {q, v, p, 1.0};
    case 2:
      return {p, v, t, 1.0};
    case 3:
      return {p, q, v, 1.0};
    case 4:
      return {t, p, v, 1.0};
    default:
      return {v, p, q, 1.0};
  }
}

}  // namespace

std::span<const NamedColor> named_colors() { return kNamedColors; }

Color series_color(std::span<const Color> given, std::size_t i) {
  if (!given.empty()) return given[i % given.size()];
  if (i < kSeries.size()) return kSeries[i];
  // Hues a golden angle apart (never the same hue twice), dark enough to read
  // on white; the value steps through four levels so that hues that round
  // to one "#rrggbb" at one level differ at the next.
  const std::size_t n = i - kSeries.size();
  const double golden = 0.3819660112501051;  // 1 - 1/phi, in turns
  const double hue = 0.07 + golden * static_cast<double>(n);
  const double value = 0.5 + 0.08 * static_cast<double>(n % 4);
  return from_hsv(hue, 0.85, value);
}

Color parse_color(std::string_view text) {
  if (!text.empty() && text[0] == '#') {
    if (const std::optional<Color> color = parse_hex(text)) return *color;
    throw std::invalid_argument(
        fmt::format("\"{}\" is not a color: \"#\" must be followed by 3, 6 or 8 hex digits (\"#rgb\", "
                    "\"#rrggbb\" or \"#rrggbbaa\")",
                    text));
  }
  std::vector<std::string_view> names;
  for (const NamedColor& named : kNamedColors) {
    if (named.name == text) return *parse_hex(named.hex);
    names.push_back(named.name);
  }
  const std::vector<std::string> suggestions = closest_names(text, names);
  std::string reason = fmt::format("unknown color \"{}\"", text);
  if (!suggestions.empty()) throw std::invalid_argument(reason + did_you_mean(suggestions));
  std::string known;
  for (std::string_view name : names) known += (known.empty() ? "" : ", ") + std::string(name);
  throw std::invalid_argument(reason + "; a color is \"#rgb\", \"#rrggbb\", \"#rrggbbaa\" or one of " + known);
}

}  // namespace pita::scene
