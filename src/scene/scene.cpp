#include "scene/scene.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <span>
#include <sstream>
#include <utility>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/arrow.hpp"
#include "scene/did_you_mean.hpp"

namespace pita::scene {

namespace {

// Objects keep their members in document order, so that the first problem
// reported is the first one in the file.
using Json = nlohmann::ordered_json;

// The fields each object of a scene may have. A figures issue will add canvas,
// layers and panels; until then anything else is an error.
constexpr std::array<std::string_view, 6> kSceneFields = {
    "$schema", "description", "method", "keyframes", "samples", "options"};
constexpr std::array<std::string_view, 6> kKeyframeFields = {"t", "p", "m", "w", "q", "turns"};
constexpr std::array<std::string_view, 3> kOptionFields = {"anchor", "path_mean",
                                                           "magnitude_mean"};

constexpr std::array<std::string_view, 2> kAnchorNames = {"start", "midpoint"};
constexpr std::array<Anchor, 2> kAnchors = {Anchor::start, Anchor::midpoint};
constexpr std::array<std::string_view, 3> kMeanNames = {"arithmetic", "geometric", "harmonic"};
constexpr std::array<MeanKind, 3> kMeans = {MeanKind::arithmetic, MeanKind::geometric,
                                            MeanKind::harmonic};

// ---------------------------------------------------------------- messages

// JSON Pointer (RFC 6901) of a member: "~" is written "~0" and "/" is "~1".
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

// A number as messages show it: the shortest form that reads back exactly
// ("-2", "0.5", "1e+300", "inf").
std::string number_text(double x) { return fmt::format("{}", x); }

// A JSON value as messages show it after "got": "3", "null", "string \"abc\"",
// "array [1,2,3]"; long values are cut short.
std::string value_text(const Json& value) {
  constexpr std::size_t kMaxShown = 40;
  if (value.is_number()) return number_text(value.get<double>());
  // ensure_ascii keeps the text valid UTF-8 however it is cut.
  std::string text = value.dump(-1, ' ', true, Json::error_handler_t::replace);
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

// The registry ranks its suggestions best first; a few are enough.
constexpr std::size_t kMaxMethodSuggestions = 3;

std::string unknown_method_reason(std::string_view name) {
  std::string reason = fmt::format("unknown method \"{}\"", name);
  std::vector<std::string> suggestions = suggest_methods(name);
  if (suggestions.size() > kMaxMethodSuggestions) suggestions.resize(kMaxMethodSuggestions);
  if (!suggestions.empty()) return reason + did_you_mean(suggestions, /*quoted=*/false);
  std::string known;
  for (const MethodInfo& method : all_methods()) {
    if (!known.empty()) known += ", ";
    known += method.id;
  }
  return reason + "; known methods: " + known;
}

std::string keyframe_count_reason(Method method, std::size_t count) {
  const MethodInfo& about = info(method);
  std::string name(about.id);
  if (!about.mnemonic.empty() && about.mnemonic != about.id) {
    name += fmt::format(" ({})", about.mnemonic);
  }
  return fmt::format("method {} takes exactly {} keyframes (got {})", name, about.keyframe_count,
                     count);
}

// ------------------------------------------------------------ JSON parsing

// 1-based line and column of the byte at `index` (columns count bytes, as
// nlohmann's own messages do).
std::pair<int, int> line_and_column(std::string_view text, std::size_t index) {
  index = std::min(index, text.size());
  const std::string_view before = text.substr(0, index);
  const auto line = 1 + std::count(before.begin(), before.end(), '\n');
  const std::size_t line_start = before.rfind('\n') == std::string_view::npos
                                     ? 0
                                     : before.rfind('\n') + 1;
  return {static_cast<int>(line), static_cast<int>(index - line_start + 1)};
}

// nlohmann's message without its "[json.exception.parse_error.101] parse error
// at line 3, column 14: " prefix (we print our own position).
std::string parse_error_reason(const std::string& message) {
  const std::size_t start = message.find("parse error");
  if (start == std::string::npos) return message;
  const std::size_t colon = message.find(": ", start);
  if (colon == std::string::npos) return message;
  return message.substr(colon + 2);
}

// A number too large for a double (1e999) is refused by nlohmann with an
// out_of_range exception that carries no position. This event-only second
// pass finds where: the parser reports the position just after the number.
class NumberOverflowLocator : public nlohmann::json_sax<Json> {
 public:
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t position, const std::string& last_token,
                   const Json::exception&) override {
    end = position;
    token = last_token;
    return false;
  }

  std::size_t end = 0;  // bytes read, up to and including the number
  std::string token;    // the number as written
};

Json parse_json(std::string_view text, const std::string& file) {
  try {
    return Json::parse(text);
  } catch (const Json::parse_error& error) {
    // error.byte counts the bytes read, the offending one included.
    const auto [line, column] = line_and_column(text, error.byte == 0 ? 0 : error.byte - 1);
    throw SceneError(file, line, column, "malformed JSON: " + parse_error_reason(error.what()));
  } catch (const Json::out_of_range&) {
    NumberOverflowLocator locator;
    Json::sax_parse(text, &locator);
    const std::size_t start =
        locator.end >= locator.token.size() ? locator.end - locator.token.size() : 0;
    const auto [line, column] = line_and_column(text, start);
    throw SceneError(file, line, column,
                     fmt::format("number {} is out of range (too large for a double)",
                                 locator.token));
  }
}

// ----------------------------------------------------------- scene reading

class SceneReader {
 public:
  explicit SceneReader(std::string file) : file_(std::move(file)) {}

  Scene read(const Json& document) const {
    if (!document.is_object()) {
      fail("", "a scene must be a JSON object (got " + value_text(document) + ")");
    }
    check_fields(document, "", kSceneFields);

    Scene scene;
    scene.path = file_;
    if (const Json* schema = member(document, "$schema")) string(*schema, "/$schema");
    if (const Json* description = member(document, "description")) {
      scene.description = string(*description, "/description");
    }

    const Json* method = member(document, "method");
    if (method == nullptr) fail("/method", "missing required field (a method such as \"P6\")");
    const std::string method_name = string(*method, "/method");
    const std::optional<Method> found = find_method(method_name);
    if (!found) fail("/method", unknown_method_reason(method_name));
    scene.method = *found;
    scene.method_name = std::string(info(*found).id);

    if (const Json* options = member(document, "options")) {
      scene.options = read_options(*options, "/options");
    }

    const Json* keyframes = member(document, "keyframes");
    if (keyframes == nullptr) fail("/keyframes", "missing required field (an array of keyframes)");
    if (!keyframes->is_array()) {
      fail("/keyframes", "must be an array of keyframes (got " + value_text(*keyframes) + ")");
    }
    if (keyframes->size() != static_cast<std::size_t>(info(scene.method).keyframe_count)) {
      fail("/keyframes", keyframe_count_reason(scene.method, keyframes->size()));
    }
    for (std::size_t i = 0; i < keyframes->size(); ++i) {
      const std::string pointer = element_pointer("/keyframes", i);
      const Keyframe keyframe = read_keyframe((*keyframes)[i], pointer);
      if (i > 0) check_knot_order(scene.keyframes.back().t, keyframe.t, pointer + "/t");
      scene.keyframes.push_back(keyframe);
    }

    if (const Json* samples = member(document, "samples")) {
      const double count = integer(*samples, "/samples");
      if (count < kMinSamples || count > kMaxSamples) {
        fail("/samples", fmt::format("must be an integer between {} and {} (got {})", kMinSamples,
                                     kMaxSamples, number_text(count)));
      }
      scene.samples = static_cast<int>(count);
    }
    return scene;
  }

 private:
  [[noreturn]] void fail(const std::string& pointer, std::string reason) const {
    throw SceneError(file_, pointer, std::move(reason));
  }

  static const Json* member(const Json& object, const std::string& key) {
    const auto found = object.find(key);
    return found == object.end() ? nullptr : &*found;
  }

  void check_fields(const Json& object, const std::string& pointer,
                    std::span<const std::string_view> known) const {
    for (const auto& [key, value] : object.items()) {
      if (std::find(known.begin(), known.end(), key) != known.end()) continue;
      const std::vector<std::string> suggestions = closest_names(key, known);
      std::string reason = fmt::format("unknown field \"{}\"", key);
      reason += suggestions.empty() ? "; known fields: " + joined(known) : did_you_mean(suggestions);
      fail(member_pointer(pointer, key), reason);
    }
  }

  std::string string(const Json& value, const std::string& pointer) const {
    if (!value.is_string()) fail(pointer, "must be a string (got " + value_text(value) + ")");
    return value.get<std::string>();
  }

  // Every number of a scene must be finite. nlohmann 3.11 already refuses
  // numbers that overflow (see parse_json); other versions read them as inf.
  double number(const Json& value, const std::string& pointer) const {
    if (!value.is_number()) fail(pointer, "must be a number (got " + value_text(value) + ")");
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(pointer, "must be a finite number (got " + number_text(x) + ")");
    return x;
  }

  // A number with no fractional part (as JSON Schema's "integer": 3 and 3.0).
  double integer(const Json& value, const std::string& pointer) const {
    const bool ok = value.is_number() && std::isfinite(value.get<double>()) &&
                    value.get<double>() == std::trunc(value.get<double>());
    if (!ok) fail(pointer, "must be an integer (got " + value_text(value) + ")");
    return value.get<double>();
  }

  Point point(const Json& value, const std::string& pointer) const {
    if (!value.is_array() || value.size() != 2) {
      fail(pointer, "must be an array of two numbers [x, y] (got " + value_text(value) + ")");
    }
    return make_point(number(value[0], element_pointer(pointer, 0)),
                      number(value[1], element_pointer(pointer, 1)));
  }

  template <typename T, std::size_t N>
  T choice(const Json& value, const std::string& pointer,
           const std::array<std::string_view, N>& names, const std::array<T, N>& values) const {
    if (value.is_string()) {
      const auto found = std::find(names.begin(), names.end(), value.get<std::string>());
      if (found != names.end()) return values[static_cast<std::size_t>(found - names.begin())];
    }
    fail(pointer, "must be " + quoted_choices(names) + " (got " + value_text(value) + ")");
  }

  MethodOptions read_options(const Json& value, const std::string& pointer) const {
    if (!value.is_object()) fail(pointer, "must be an object (got " + value_text(value) + ")");
    check_fields(value, pointer, kOptionFields);
    MethodOptions options;
    if (const Json* anchor = member(value, "anchor")) {
      options.anchor = choice(*anchor, pointer + "/anchor", kAnchorNames, kAnchors);
    }
    if (const Json* mean = member(value, "path_mean")) {
      options.path_mean = choice(*mean, pointer + "/path_mean", kMeanNames, kMeans);
    }
    if (const Json* mean = member(value, "magnitude_mean")) {
      options.magnitude_mean = choice(*mean, pointer + "/magnitude_mean", kMeanNames, kMeans);
    }
    return options;
  }

  // A keyframe is {"t", "p", and either "q" or "m" and "w"; "turns" optional}.
  Keyframe read_keyframe(const Json& value, const std::string& pointer) const {
    if (!value.is_object()) {
      fail(pointer, "a keyframe must be an object (got " + value_text(value) + ")");
    }
    check_fields(value, pointer, kKeyframeFields);

    const Json* knot = member(value, "t");
    if (knot == nullptr) fail(pointer + "/t", "missing required field (the knot, a time value)");
    Keyframe keyframe;
    keyframe.t = number(*knot, pointer + "/t");

    const Json* start = member(value, "p");
    if (start == nullptr) fail(pointer + "/p", "missing required field (the start point [x, y])");
    const Point p = point(*start, pointer + "/p");

    const Json* end = member(value, "q");
    const Json* magnitude = member(value, "m");
    const Json* winding = member(value, "w");
    if (end != nullptr) {
      if (magnitude != nullptr || winding != nullptr) {
        fail(pointer + "/q", "give either \"q\" or \"m\" and \"w\", not both");
      }
      const Point q = point(*end, pointer + "/q");
      if (q == p) fail(pointer + "/q", "q equals p: a zero-length arrow has no direction");
      keyframe.arrow = zero_turn_arrow(p, q);
      if (!is_finite(keyframe.arrow)) {
        fail(pointer + "/q", "the arrow from p to q is too long (its magnitude overflows)");
      }
    } else {
      if (magnitude == nullptr && winding == nullptr) {
        fail(pointer, "missing the arrow: give \"q\", or \"m\" and \"w\"");
      }
      if (magnitude == nullptr) {
        fail(pointer + "/m", "missing required field (\"w\" needs the magnitude \"m\")");
      }
      if (winding == nullptr) {
        fail(pointer + "/w", "missing required field (\"m\" needs the winding \"w\")");
      }
      const double m = number(*magnitude, pointer + "/m");
      if (!(m > 0.0)) fail(pointer + "/m", "magnitude must be > 0 (got " + number_text(m) + ")");
      keyframe.arrow = Arrow{p, m, number(*winding, pointer + "/w")};
    }

    if (const Json* turns = member(value, "turns")) {
      const double k = integer(*turns, pointer + "/turns");
      keyframe.arrow = with_turns(keyframe.arrow, k);
      if (!std::isfinite(keyframe.arrow.w)) {
        fail(pointer + "/turns",
             "too many turns: the winding overflows (got " + number_text(k) + ")");
      }
    }
    return keyframe;
  }

  // Knots must be strictly increasing (the registry requires a < b < c).
  void check_knot_order(double previous, double knot, const std::string& pointer) const {
    if (knot == previous) {
      fail(pointer, fmt::format("knot {} equals the previous knot; knots must be strictly "
                                "increasing",
                                number_text(knot)));
    }
    if (knot < previous) {
      fail(pointer, fmt::format("knot {} is less than the previous knot {}; knots must be "
                                "strictly increasing",
                                number_text(knot), number_text(previous)));
    }
  }

  std::string file_;
};

std::string located(const std::string& file, const std::string& pointer,
                    const std::string& reason) {
  return pointer.empty() ? file + ": " + reason : file + ": " + pointer + ": " + reason;
}

}  // namespace

SceneError::SceneError(std::string file, std::string pointer, std::string reason)
    : std::runtime_error(located(file, pointer, reason)),
      file_(std::move(file)),
      pointer_(std::move(pointer)),
      reason_(std::move(reason)) {}

SceneError::SceneError(std::string file, int line, int column, std::string reason)
    : std::runtime_error(fmt::format("{}:{}:{}: {}", file, line, column, reason)),
      file_(std::move(file)),
      reason_(std::move(reason)),
      line_(line),
      column_(column) {}

Scene load_scene(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) {
    throw SceneError(name, "", "cannot read the scene file: it is a directory");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw SceneError(name, "", fmt::format("cannot open the scene file ({})", std::strerror(errno)));
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw SceneError(name, "", "cannot read the scene file");
  return parse_scene(text.str(), name);
}

Scene parse_scene(std::string_view text, std::string source_name) {
  const Json document = parse_json(text, source_name);
  return SceneReader(std::move(source_name)).read(document);
}

Method resolve_method(std::string_view name) {
  if (const std::optional<Method> method = find_method(name)) return *method;
  throw std::invalid_argument(unknown_method_reason(name));
}

Scene with_method(Scene scene, Method method) {
  const MethodInfo& about = info(method);
  if (scene.keyframes.size() != static_cast<std::size_t>(about.keyframe_count)) {
    throw SceneError(scene.path, "/keyframes", keyframe_count_reason(method, scene.keyframes.size()));
  }
  scene.method = method;
  scene.method_name = std::string(about.id);
  return scene;
}

}  // namespace pita::scene
