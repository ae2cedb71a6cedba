#include "scene/timing_reader.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "scene/did_you_mean.hpp"

namespace pita::scene::detail {

namespace {

constexpr std::array<std::string_view, 3> kTimingFields = {"ease", "arc_length", "per"};
constexpr std::array<std::string_view, 2> kPerNames = {"motion", "span"};
constexpr std::array<WarpSpan, 2> kPers = {WarpSpan::motion, WarpSpan::span};
constexpr std::array<std::string_view, 2> kSineFields = {"k1", "k2"};
constexpr std::array<std::string_view, 2> kParabolicFields = {"t1", "t2"};
constexpr std::string_view kCubicBezier = "cubic-bezier";

// Every name a string ease may have, for "did you mean".
std::vector<std::string_view> ease_names() {
  std::vector<std::string_view> names;
  for (const NamedEase& named : named_eases()) names.push_back(named.name);
  names.push_back(kCubicBezier);
  return names;
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
  return text;
}

// "cubic-bezier(x1, y1, x2, y2)" (CSS syntax, any spacing).
Ease read_cubic_bezier(const JsonReader& reader, const std::string& text, const std::string& pointer) {
  const std::string usage = "must be \"cubic-bezier(x1, y1, x2, y2)\" with four numbers, x1 and x2 in [0, 1]";
  const std::string_view whole = trim(text);
  const std::size_t open = whole.find('(');
  if (open == std::string_view::npos || whole.back() != ')' || trim(whole.substr(0, open)) != kCubicBezier) {
    reader.fail(pointer, fmt::format("{} (got \"{}\")", usage, text));
  }
  std::string_view inside = whole.substr(open + 1, whole.size() - open - 2);
  std::vector<double> numbers;
  while (true) {
    const std::size_t comma = inside.find(',');
    std::string_view item = trim(inside.substr(0, comma));
    if (!item.empty() && item.front() == '+') item.remove_prefix(1);
    double x = 0.0;
    const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), x);
    if (item.empty() || error != std::errc{} || end != item.data() + item.size() || !std::isfinite(x)) {
      reader.fail(pointer,
                  fmt::format("{}: \"{}\" is not a finite number (got \"{}\")", usage, std::string(item), text));
    }
    numbers.push_back(x);
    if (comma == std::string_view::npos) break;
    inside.remove_prefix(comma + 1);
  }
  if (numbers.size() != 4) {
    reader.fail(pointer, fmt::format("{} (got {} numbers in \"{}\")", usage, numbers.size(), text));
  }
  try {
    return cubic_bezier_ease(numbers[0], numbers[1], numbers[2], numbers[3]);
  } catch (const std::invalid_argument& error) {
    reader.fail(pointer, fmt::format("{} (in \"{}\")", error.what(), text));
  }
}

// {"sine": {"k1": .., "k2": ..}} or {"parabolic": {"t1": .., "t2": ..}}.
Ease read_ease_family(const JsonReader& reader, const Json& value, const std::string& pointer) {
  if (value.size() != 1) {
    reader.fail(pointer,
                fmt::format("an ease object has one member, \"sine\" or \"parabolic\" (got {})", value_text(value)));
  }
  const std::string key = value.begin().key();
  const Json& parameters = value.begin().value();
  const std::string at = member_pointer(pointer, key);
  const bool sine = key == "sine";
  if (!sine && key != "parabolic") {
    constexpr std::array<std::string_view, 2> families = {"sine", "parabolic"};
    const std::vector<std::string> close = closest_names(key, families);
    reader.fail(at, fmt::format("unknown ease family \"{}\"{}", key,
                                close.empty() ? "; the families with parameters are \"sine\" and \"parabolic\""
                                              : did_you_mean(close)));
  }
  const auto& fields = sine ? kSineFields : kParabolicFields;
  reader.object(
      parameters, at,
      sine ? "the sine ease's parameters {\"k1\", \"k2\"}" : "the parabolic ease's parameters {\"t1\", \"t2\"}");
  reader.check_fields(parameters, at, fields);
  std::array<double, 2> numbers{};
  for (std::size_t i = 0; i < 2; ++i) {
    const Json* number = JsonReader::member(parameters, std::string(fields[i]));
    const std::string field_at = member_pointer(at, fields[i]);
    if (number == nullptr) {
      reader.fail(field_at, "missing required field (a number in [0, 1])");
    }
    numbers[i] = reader.number(*number, field_at, Interval{0.0, 1.0});
  }
  try {
    return sine ? sine_cap_ease(numbers[0], numbers[1]) : parabolic_ease(numbers[0], numbers[1]);
  } catch (const std::invalid_argument& error) {
    reader.fail(member_pointer(at, fields[1]), error.what());
  }
}

}  // namespace

Ease read_ease(const JsonReader& reader, const Json& value, const std::string& pointer) {
  if (value.is_object()) return read_ease_family(reader, value, pointer);
  if (!value.is_string()) {
    reader.fail(pointer, fmt::format("must be an ease: a name such as \"ease-in-out\", "
                                     "\"cubic-bezier(x1, y1, x2, y2)\", {{\"sine\": {{\"k1\": .., \"k2\": ..}}}} "
                                     "or {{\"parabolic\": {{\"t1\": .., \"t2\": ..}}}} (got {})",
                                     value_text(value)));
  }
  const std::string text = value.get<std::string>();
  if (const std::optional<Ease> named = find_named_ease(trim(text))) return *named;
  if (text.find('(') != std::string::npos) return read_cubic_bezier(reader, text, pointer);
  const std::vector<std::string_view> names = ease_names();
  const std::vector<std::string> close = closest_names(text, names);
  reader.fail(pointer, fmt::format("unknown ease \"{}\"{}", text,
                                   close.empty()
                                       ? "; eases: " + joined(names) + ", and {\"sine\": {...}}, {\"parabolic\": {...}}"
                                       : did_you_mean(close)));
}

Timing read_timing(const JsonReader& reader, const Json& value, const std::string& pointer) {
  reader.object(value, pointer, "the timing {\"ease\", \"arc_length\", \"per\"}");
  reader.check_fields(value, pointer, kTimingFields);
  Timing timing;
  timing.pointer = pointer;
  if (const Json* ease = JsonReader::member(value, "ease")) {
    timing.ease = read_ease(reader, *ease, member_pointer(pointer, "ease"));
  }
  if (const Json* point = JsonReader::member(value, "arc_length")) {
    timing.arc_length = reader.choice(*point, member_pointer(pointer, "arc_length"), kPointNames, kPoints);
  }
  if (const Json* per = JsonReader::member(value, "per")) {
    timing.per = reader.choice(*per, member_pointer(pointer, "per"), kPerNames, kPers);
  }
  return timing;
}

}  // namespace pita::scene::detail
