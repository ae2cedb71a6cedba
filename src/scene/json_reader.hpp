// The checking JSON reader shared by the parts of the scene reader (scene.cpp:
// the document, keyframes and panels; figure_reader.cpp: canvas and layers, read by
// arrow_layer_reader.cpp and pose_layer_reader.cpp).
// Internal to src/scene/: every check fails with a SceneError that names the
// JSON Pointer of the bad value and says what was expected.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/arrow.hpp"
#include "core/keyframe.hpp"
#include "core/methods.hpp"
#include "core/pitas/method_options.hpp"
#include "core/pitas/registry.hpp"
#include "scene/figure.hpp"
#include "scene/read_options.hpp"

namespace pita::scene::detail {

// Objects keep their members in document order, so that the first problem
// reported is the first one in the file.
using Json = nlohmann::ordered_json;

// ---------------------------------------------------------------- messages

// JSON Pointer (RFC 6901) of a member: "~" is written "~0" and "/" is "~1".
std::string member_pointer(const std::string& parent, std::string_view key);
std::string element_pointer(const std::string& parent, std::size_t index);

// A number as messages show it: the shortest form that reads back exactly
// ("-2", "0.5", "1e+300", "inf").
std::string number_text(double x);

// A JSON value as messages show it after "got": "3", "null", "string \"abc\"",
// "array [1,2,3]"; long values are cut short.
std::string value_text(const Json& value);

std::string joined(std::span<const std::string_view> names);          // a, b, c
std::string quoted_choices(std::span<const std::string_view> names);  // "a", "b" or "c"

// unknown method "P66"; did you mean P6 (La-LP), ... among the methods of the
// scene's kind (`filter`: core/methods.hpp's one wording), or, for a method of
// the other kind, what the scene needs instead.
std::string unknown_scene_method_reason(std::string_view name, MethodFilter filter);
// method SMA takes exactly 2 keyframes (got 3)
std::string keyframe_count_reason(Method method, std::size_t count);

// ---------------------------------------------------------------- reader

// An interval of numbers; each end open (excluded) or closed.
struct Interval {
  double min;
  double max;
  bool min_open = false;
  bool max_open = false;
};

class JsonReader {
 public:
  explicit JsonReader(std::string file, ReadOptions options = {}) : file_(std::move(file)), options_(options) {}

  const std::string& file() const { return file_; }
  const ReadOptions& options() const { return options_; }

  [[noreturn]] void fail(const std::string& pointer, std::string reason) const;

  static const Json* member(const Json& object, const std::string& key);

  // Fails unless `value` is an object; `what` names it ("the canvas").
  void object(const Json& value, const std::string& pointer, std::string_view what) const;

  // Fails at the first member of `object` whose key is not in `known`, with a
  // "did you mean" among `known`.
  void check_fields(const Json& object, const std::string& pointer, std::span<const std::string_view> known) const;

  std::string string(const Json& value, const std::string& pointer) const;
  // A string of 1 .. max_length characters (code points).
  std::string text(const Json& value, const std::string& pointer, std::size_t max_length) const;
  bool boolean(const Json& value, const std::string& pointer) const;
  // Every number of a scene must be finite.
  double number(const Json& value, const std::string& pointer) const;
  double number(const Json& value, const std::string& pointer, const Interval& bounds) const;
  // A number with no fractional part (as JSON Schema's "integer": 3 and 3.0).
  double integer(const Json& value, const std::string& pointer) const;
  int integer(const Json& value, const std::string& pointer, int min, int max) const;
  Point point(const Json& value, const std::string& pointer) const;
  Color color(const Json& value, const std::string& pointer) const;
  Method method(const Json& value, const std::string& pointer) const;

  // One of `names`, mapped to the value at the same index.
  template <typename T, std::size_t N>
  T choice(const Json& value, const std::string& pointer, const std::array<std::string_view, N>& names,
           const std::array<T, N>& values) const {
    if (value.is_string()) {
      const std::string given = value.get<std::string>();
      for (std::size_t i = 0; i < N; ++i) {
        if (names[i] == given) return values[i];
      }
    }
    choice_failed(value, pointer, names);
  }

  // "options": the fields given replace those of `base`.
  MethodOptions options(const Json& value, const std::string& pointer, MethodOptions base) const;

  // "points": kMinPoints..kMaxPoints objects {"t", "p"}, knots strictly
  // increasing, coordinates within kMaxKeyframeValue.
  std::vector<TimedPoint> points(const Json& value, const std::string& pointer) const;

  // "chain": one of core/chains/chain.hpp's names.
  Chain chain(const Json& value, const std::string& pointer) const;
  // Refuses (at `pointer`, the "chain" field or the keyframes) a chain that
  // cannot extend `method` over `count` keyframes: "blend" on the SMA,
  // "neville" beyond limits::kMaxNevilleKeyframes.
  void check_chain(Method method, std::optional<Chain> chain, std::size_t count, const std::string& pointer) const;

  // "keyframes": at least as many as `method` takes (a track of more is
  // chained), at most kMaxKeyframes, knots strictly increasing; with
  // KnotOrder::as_given exactly three for a three-keyframe method, knots
  // distinct in any order (docs/paper-notes.md N41).
  // Moving keyframes {"t", "from", "to"} (PITA Sec. 7.4) read `from` as the
  // keyframe; when any moves, `targets` receives every keyframe's `to` (a
  // keyframe that does not move is its own target), else stays empty.
  std::vector<Keyframe> keyframes(const Json& value, const std::string& pointer, Method method,
                                  std::vector<Arrow>* targets = nullptr, KnotOrder order = KnotOrder::increasing) const;
  // An arrow: {"p", and "q" or "m" and "w"; "turns" optional}.
  Arrow arrow(const Json& value, const std::string& pointer) const;

 private:
  [[noreturn]] void choice_failed(const Json& value, const std::string& pointer,
                                  std::span<const std::string_view> names) const;
  Keyframe keyframe(const Json& value, const std::string& pointer) const;
  void check_knot_order(double previous, double knot, const std::string& pointer) const;
  // Both coordinates within +-kMaxKeyframeValue.
  void check_coordinates(Point x, const std::string& pointer) const;

  std::string file_;
  ReadOptions options_;
};

}  // namespace pita::scene::detail
