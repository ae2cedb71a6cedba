#include "scene/json_reader.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "core/limits.hpp"
#include "core/overloaded.hpp"
#include "scene/color.hpp"
#include "scene/did_you_mean.hpp"
#include "scene/scene.hpp"

namespace pita::scene::detail {

namespace {

// The keys of "options" and their values: core/pitas/method_options.hpp.
constexpr auto kOptionFields = method_option_names();

// Characters (Unicode code points) of UTF-8 text; nlohmann has checked the encoding.
std::size_t character_count(std::string_view text) {
  return static_cast<std::size_t>(
      std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0U) != 0x80U; }));
}

std::string interval_text(const Interval& bounds) {
  const bool has_min = std::isfinite(bounds.min);
  const bool has_max = std::isfinite(bounds.max);
  if (has_min && has_max && !bounds.min_open && !bounds.max_open) {
    return fmt::format("between {} and {}", number_text(bounds.min), number_text(bounds.max));
  }
  std::string text;
  if (has_min) text += fmt::format("{} {}", bounds.min_open ? ">" : ">=", number_text(bounds.min));
  if (has_max) {
    if (!text.empty()) text += " and ";
    text += fmt::format("{} {}", bounds.max_open ? "<" : "<=", number_text(bounds.max));
  }
  return text;
}

}  // namespace

// ---------------------------------------------------------------- messages

std::string member_pointer(const std::string& parent, std::string_view key) {
  std::string pointer = parent + '/';
  for (char c : key) {
    if (c == '~') {
      pointer += "~0";
    } else if (c == '/') {
      pointer += "~1";
    } else {
      pointer += c;
    }
  }
  return pointer;
}

std::string element_pointer(const std::string& parent, std::size_t index) {
  return parent + '/' + std::to_string(index);
}

std::string number_text(double x) { return fmt::format("{}", x); }

namespace {

// Appends a short preview of `value` to `out`, stopping once `out` is longer
// than `budget` and never descending more than a few levels: a scene may nest
// 100 000 arrays, and the whole value is never needed to say what it is.
void append_preview(const Json& value, std::string& out, std::size_t budget, int depth) {
  constexpr int kMaxDepth = 3;
  if (value.is_array() || value.is_object()) {
    const bool array = value.is_array();
    out += array ? '[' : '{';
    if (!value.empty() && depth >= kMaxDepth) {
      out += "...";
    } else {
      bool first = true;
      for (auto it = value.begin(); it != value.end(); ++it) {
        if (out.size() > budget) break;
        if (!first) out += ',';
        first = false;
        if (!array) out += Json(it.key()).dump(-1, ' ', true, Json::error_handler_t::replace) + ':';
        append_preview(*it, out, budget, depth + 1);
      }
    }
    out += array ? ']' : '}';
    return;
  }
  // Scalars dump without recursion; a long string is cut below.
  out += value.dump(-1, ' ', true, Json::error_handler_t::replace).substr(0, budget + 1);
}

}  // namespace

std::string value_text(const Json& value) {
  constexpr std::size_t kMaxShown = 40;
  if (value.is_number()) return number_text(value.get<double>());
  // ensure_ascii keeps the text valid UTF-8 however it is cut.
  std::string text;
  append_preview(value, text, kMaxShown, 0);
  if (text.size() > kMaxShown) text = text.substr(0, kMaxShown - 3) + "...";
  switch (value.type()) {
    case Json::value_t::string:
      return "string " + text;
    case Json::value_t::array:
      return "array " + text;
    case Json::value_t::object:
      return "object " + text;
    default:
      return text;  // null, true, false
  }
}

std::string joined(std::span<const std::string_view> names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) text += ", ";
    text += names[i];
  }
  return text;
}

std::string quoted_choices(std::span<const std::string_view> names) {
  const std::vector<std::string> copies(names.begin(), names.end());
  return alternatives(copies);
}

std::string unknown_scene_method_reason(std::string_view name, MethodFilter filter) {
  if (const MethodEntry* other = find_method_entry(name)) {
    // A method of the other kind of scene.
    return std::visit(overloaded{[&](PoseMethod) {
                                   return fmt::format(
                                       "method {} interpolates poses, and this scene has keyframes "
                                       "(arrows): give it \"poses\" instead, or an arrow method "
                                       "such as P6",
                                       other->id);
                                 },
                                 [&](Method) {
                                   return fmt::format(
                                       "method {} interpolates arrows, and this is a pose scene: "
                                       "give it \"keyframes\" instead, or a pose method such as SAM",
                                       other->id);
                                 }},
                      other->method);
  }
  return pita::unknown_method_reason(name, filter);
}

std::string keyframe_count_reason(Method method, std::size_t count) {
  const MethodInfo& about = info(method);
  std::string name(about.id);
  if (!about.mnemonic.empty() && about.mnemonic != about.id) {
    name += fmt::format(" ({})", about.mnemonic);
  }
  return fmt::format("method {} takes at least {} keyframes (got {}); more are chained (\"chain\")", name,
                     about.keyframe_count, count);
}

// ---------------------------------------------------------------- reader

void JsonReader::fail(const std::string& pointer, std::string reason) const {
  throw SceneError(file_, pointer, std::move(reason));
}

const Json* JsonReader::member(const Json& object, const std::string& key) {
  const auto found = object.find(key);
  return found == object.end() ? nullptr : &*found;
}

void JsonReader::object(const Json& value, const std::string& pointer, std::string_view what) const {
  if (!value.is_object()) {
    fail(pointer, fmt::format("{} must be an object (got {})", what, value_text(value)));
  }
}

void JsonReader::check_fields(const Json& object, const std::string& pointer,
                              std::span<const std::string_view> known) const {
  for (const auto& [key, value] : object.items()) {
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    const std::vector<std::string> suggestions = closest_names(key, known);
    std::string reason = fmt::format("unknown field \"{}\"", key);
    reason += suggestions.empty() ? "; known fields: " + joined(known) : did_you_mean(suggestions);
    fail(member_pointer(pointer, key), reason);
  }
}

std::string JsonReader::string(const Json& value, const std::string& pointer) const {
  if (!value.is_string()) fail(pointer, "must be a string (got " + value_text(value) + ")");
  return value.get<std::string>();
}

std::string JsonReader::text(const Json& value, const std::string& pointer, std::size_t max_length) const {
  std::string result = string(value, pointer);
  if (result.empty()) fail(pointer, "must not be empty");
  const std::size_t length = character_count(result);
  if (length > max_length) {
    fail(pointer, fmt::format("must be at most {} characters long (got {})", max_length, length));
  }
  return result;
}

bool JsonReader::boolean(const Json& value, const std::string& pointer) const {
  if (!value.is_boolean()) {
    fail(pointer, "must be true or false (got " + value_text(value) + ")");
  }
  return value.get<bool>();
}

// nlohmann 3.11 already refuses numbers that overflow (see parse_json);
// other versions read them as inf.
double JsonReader::number(const Json& value, const std::string& pointer) const {
  if (!value.is_number()) fail(pointer, "must be a number (got " + value_text(value) + ")");
  const double x = value.get<double>();
  if (!std::isfinite(x)) fail(pointer, "must be a finite number (got " + number_text(x) + ")");
  return x;
}

double JsonReader::number(const Json& value, const std::string& pointer, const Interval& bounds) const {
  const double x = number(value, pointer);
  const bool above = bounds.min_open ? x > bounds.min : x >= bounds.min;
  const bool below = bounds.max_open ? x < bounds.max : x <= bounds.max;
  if (!above || !below) {
    fail(pointer, fmt::format("must be {} (got {})", interval_text(bounds), number_text(x)));
  }
  return x;
}

double JsonReader::integer(const Json& value, const std::string& pointer) const {
  const bool ok =
      value.is_number() && std::isfinite(value.get<double>()) && value.get<double>() == std::trunc(value.get<double>());
  if (!ok) fail(pointer, "must be an integer (got " + value_text(value) + ")");
  return value.get<double>();
}

int JsonReader::integer(const Json& value, const std::string& pointer, int min, int max) const {
  const double x = integer(value, pointer);
  if (x < min || x > max) {
    fail(pointer, fmt::format("must be an integer between {} and {} (got {})", min, max, number_text(x)));
  }
  return static_cast<int>(x);
}

Point JsonReader::point(const Json& value, const std::string& pointer) const {
  if (!value.is_array() || value.size() != 2) {
    fail(pointer, "must be an array of two numbers [x, y] (got " + value_text(value) + ")");
  }
  return make_point(number(value[0], element_pointer(pointer, 0)), number(value[1], element_pointer(pointer, 1)));
}

Color JsonReader::color(const Json& value, const std::string& pointer) const {
  if (!value.is_string()) {
    fail(pointer,
         "must be a color: a string \"#rgb\", \"#rrggbb\", \"#rrggbbaa\" or a name such "
         "as \"red\" (got " +
             value_text(value) + ")");
  }
  try {
    return parse_color(value.get<std::string>());
  } catch (const std::invalid_argument& error) {
    fail(pointer, error.what());
  }
}

Method JsonReader::method(const Json& value, const std::string& pointer) const {
  const std::string name = string(value, pointer);
  const Method* found = find_method_of<Method>(name);
  if (found == nullptr) fail(pointer, unknown_scene_method_reason(name, is_method_of<Method>));
  return *found;
}

void JsonReader::choice_failed(const Json& value, const std::string& pointer,
                               std::span<const std::string_view> names) const {
  fail(pointer, "must be " + quoted_choices(names) + " (got " + value_text(value) + ")");
}

std::vector<TimedPoint> JsonReader::points(const Json& value, const std::string& pointer) const {
  if (!value.is_array() || value.size() < static_cast<std::size_t>(kMinPoints) ||
      value.size() > static_cast<std::size_t>(kMaxPoints)) {
    fail(pointer, fmt::format("must be an array of {} to {} timed points {{\"t\": knot, \"p\": [x, y]}} (got {})",
                              kMinPoints, kMaxPoints, value_text(value)));
  }
  std::vector<TimedPoint> result;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string at = element_pointer(pointer, i);
    const Json& item = value[i];
    if (!item.is_object())
      fail(at, "a timed point must be an object {\"t\": knot, \"p\": [x, y]} (got " + value_text(item) + ")");
    static constexpr std::array<std::string_view, 2> kPointFields = {"t", "p"};
    check_fields(item, at, kPointFields);
    const Json* knot = member(item, "t");
    if (knot == nullptr) fail(at + "/t", "missing required field (the knot, a time value)");
    const Json* where = member(item, "p");
    if (where == nullptr) fail(at + "/p", "missing required field (the point [x, y])");
    TimedPoint next{number(*knot, at + "/t"), point(*where, at + "/p")};
    if (std::abs(next.t) > kMaxKeyframeValue) {
      fail(at + "/t", fmt::format("knot must be within +-{:g} (got {})", kMaxKeyframeValue, number_text(next.t)));
    }
    check_coordinates(next.p, at + "/p");
    if (i > 0) check_knot_order(result.back().t, next.t, at + "/t");
    result.push_back(next);
  }
  return result;
}

Chain JsonReader::chain(const Json& value, const std::string& pointer) const {
  if (value.is_string()) {
    if (const ChainInfo* found = find_chain(value.get<std::string>())) return found->chain;
  }
  std::vector<std::string_view> names;
  for (const ChainInfo& about : all_chains()) names.push_back(about.name);
  choice_failed(value, pointer, names);
}

void JsonReader::check_chain(Method method, std::optional<Chain> chain, std::size_t count,
                             const std::string& pointer) const {
  if (!chain) return;
  if (*chain == Chain::blend && info(method).keyframe_count != 3) {
    fail(pointer, fmt::format("chain \"blend\" blends a method through three keyframes, and {} interpolates "
                              "two: use \"spiral\", \"bezier-spiral\" or \"neville\", or method P9 (an SMA "
                              "of SMAs) for the blend of consecutive spirals",
                              info(method).id));
  }
  if (*chain == Chain::neville && count > static_cast<std::size_t>(limits::kMaxNevilleKeyframes)) {
    fail(pointer, fmt::format("chain \"neville\" takes at most {} keyframes (got {}): it is global, so its "
                              "cost per frame grows as n^2; use \"blend\", which is local",
                              limits::kMaxNevilleKeyframes, count));
  }
}

MethodOptions JsonReader::options(const Json& value, const std::string& pointer, MethodOptions base) const {
  if (!value.is_object()) fail(pointer, "must be an object (got " + value_text(value) + ")");
  check_fields(value, pointer, kOptionFields);
  if (const Json* anchor = member(value, "anchor")) {
    base.anchor = choice(*anchor, pointer + "/anchor", kAnchorNames, kAnchors);
  }
  if (const Json* mean = member(value, "path_mean")) {
    base.path_mean = choice(*mean, pointer + "/path_mean", kMeanNames, kMeans);
  }
  if (const Json* mean = member(value, "magnitude_mean")) {
    base.magnitude_mean = choice(*mean, pointer + "/magnitude_mean", kMeanNames, kMeans);
  }
  if (const Json* knots = member(value, "knots")) {
    base.knots = choice(*knots, pointer + "/knots", kKnotOrderNames, kKnotOrders);
  }
  if (const Json* permutation = member(value, "permutation")) {
    base.permutation = choice(*permutation, pointer + "/permutation", kPermutationNames, kPermutations);
  }
  if (const Json* symmetrize = member(value, "symmetrize")) {
    base.symmetrize = boolean(*symmetrize, pointer + "/symmetrize");
  }
  return base;
}

}  // namespace pita::scene::detail
