// The keys of an arrow scene, read by JsonReader (scene/json_reader.hpp):
// keyframes in their two forms (an arrow p, m, w or its end points p, q, with
// whole turns), moving keyframes, arrows, and the checks of their coordinates
// and knots.
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "core/limits.hpp"
#include "scene/json_reader.hpp"
#include "scene/scene.hpp"

namespace pita::scene::detail {

namespace {

constexpr std::array<std::string_view, 6> kKeyframeFields = {"t", "p", "m", "w", "q", "turns"};
constexpr std::array<std::string_view, 3> kMovingKeyframeFields = {"t", "from", "to"};
constexpr std::array<std::string_view, 5> kArrowFields = {"p", "m", "w", "q", "turns"};

}  // namespace

std::vector<Keyframe> JsonReader::keyframes(const Json& value, const std::string& pointer, Method method,
                                            std::vector<Arrow>* targets, KnotOrder order) const {
  if (!value.is_array()) {
    fail(pointer, "must be an array of keyframes (got " + value_text(value) + ")");
  }
  if (value.size() < static_cast<std::size_t>(info(method).keyframe_count)) {
    fail(pointer, keyframe_count_reason(method, value.size()));
  }
  if (value.size() > static_cast<std::size_t>(kMaxKeyframes)) {
    fail(pointer, fmt::format("at most {} keyframes (got {})", kMaxKeyframes, value.size()));
  }
  std::vector<Keyframe> result;
  std::vector<Arrow> to;
  bool moving = false;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string at = element_pointer(pointer, i);
    const Json* from = value[i].is_object() ? member(value[i], "from") : nullptr;
    const Json* target = value[i].is_object() ? member(value[i], "to") : nullptr;
    Keyframe next;
    if (from != nullptr || target != nullptr) {
      // A moving keyframe (Sec. 7.4): {"t", "from": ARROW, "to": ARROW}.
      if (targets == nullptr) fail(at + (from ? "/from" : "/to"), "moving keyframes are not allowed here");
      check_fields(value[i], at, kMovingKeyframeFields);
      if (from == nullptr)
        fail(at + "/from", "missing required field (a moving keyframe needs \"from\" and \"to\" arrows)");
      if (target == nullptr)
        fail(at + "/to", "missing required field (a moving keyframe needs \"from\" and \"to\" arrows)");
      const Json* knot = member(value[i], "t");
      if (knot == nullptr) fail(at + "/t", "missing required field (the knot, a time value)");
      next.t = number(*knot, at + "/t");
      if (std::abs(next.t) > kMaxKeyframeValue) {
        fail(at + "/t", fmt::format("knot must be within +-{:g} (got {})", kMaxKeyframeValue, number_text(next.t)));
      }
      next.arrow = arrow(*from, at + "/from");
      to.push_back(arrow(*target, at + "/to"));
      moving = true;
    } else {
      next = keyframe(value[i], at);
      to.push_back(next.arrow);
    }
    if (order == KnotOrder::increasing) {
      if (i > 0) check_knot_order(result.back().t, next.t, at + "/t");
    } else {
      for (std::size_t j = 0; j < i; ++j) {
        if (result[j].t == next.t) {
          fail(at + "/t", fmt::format("knot {} equals the knot of keyframe {}; with \"knots\": \"as-given\" the "
                                      "knots may come in any order but must be distinct",
                                      number_text(next.t), j));
        }
      }
    }
    result.push_back(next);
  }
  if (order == KnotOrder::as_given && (result.size() != 3 || info(method).keyframe_count != 3)) {
    fail(pointer, fmt::format("with \"knots\": \"as-given\" the method takes the keyframes in the order given, "
                              "one window of three (order-independence, PITA Sec. 4): give exactly three keyframes "
                              "to a three-keyframe method (got {} for {})",
                              result.size(), info(method).id));
  }
  if (targets != nullptr) {
    targets->clear();
    if (moving) *targets = std::move(to);
  }
  return result;
}

Arrow JsonReader::arrow(const Json& value, const std::string& pointer) const {
  if (!value.is_object()) {
    fail(pointer, "an arrow must be an object {\"p\", and \"q\" or \"m\" and \"w\"} (got " + value_text(value) + ")");
  }
  check_fields(value, pointer, kArrowFields);
  Json keyframe_form = value;
  keyframe_form["t"] = 0.0;
  return keyframe(keyframe_form, pointer).arrow;
}

// A keyframe is {"t", "p", and either "q" or "m" and "w"; "turns" optional}.
Keyframe JsonReader::keyframe(const Json& value, const std::string& pointer) const {
  if (!value.is_object()) {
    fail(pointer, "a keyframe must be an object (got " + value_text(value) + ")");
  }
  check_fields(value, pointer, kKeyframeFields);

  const Json* knot = member(value, "t");
  if (knot == nullptr) fail(pointer + "/t", "missing required field (the knot, a time value)");
  Keyframe keyframe;
  keyframe.t = number(*knot, pointer + "/t");
  if (std::abs(keyframe.t) > kMaxKeyframeValue) {
    fail(pointer + "/t",
         fmt::format("knot must be within +-{:g} (got {})", kMaxKeyframeValue, number_text(keyframe.t)));
  }

  const Json* start = member(value, "p");
  if (start == nullptr) fail(pointer + "/p", "missing required field (the start point [x, y])");
  const Point p = point(*start, pointer + "/p");
  check_coordinates(p, pointer + "/p");

  const Json* end = member(value, "q");
  const Json* magnitude = member(value, "m");
  const Json* winding = member(value, "w");
  if (end != nullptr) {
    if (magnitude != nullptr || winding != nullptr) {
      fail(pointer + "/q", "give either \"q\" or \"m\" and \"w\", not both");
    }
    const Point q = point(*end, pointer + "/q");
    check_coordinates(q, pointer + "/q");
    if (q == p) fail(pointer + "/q", "q equals p: a zero-length arrow has no direction");
    if (!(std::abs(q - p) >= kMinMagnitude)) {
      fail(pointer + "/q", fmt::format("q is within {:g} of p: the arrow is too short for its "
                                       "direction and magnitude to be computed",
                                       kMinMagnitude));
    }
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
    if (m < kMinMagnitude || m > kMaxKeyframeValue) {
      fail(pointer + "/m", fmt::format("magnitude must be between {:g} and {:g} (got {})", kMinMagnitude,
                                       kMaxKeyframeValue, number_text(m)));
    }
    keyframe.arrow = Arrow{p, m, number(*winding, pointer + "/w")};
    if (std::abs(keyframe.arrow.w) > kMaxWinding) {
      fail(pointer + "/w",
           fmt::format("winding must be within +-{:g} radians (about {:.0f} "
                       "turns; beyond, 2 pi k loses the angle's precision) "
                       "(got {})",
                       kMaxWinding, kMaxWinding / (2 * std::numbers::pi), number_text(keyframe.arrow.w)));
    }
  }

  if (const Json* turns = member(value, "turns")) {
    const double k = integer(*turns, pointer + "/turns");
    keyframe.arrow = with_turns(keyframe.arrow, k);
    if (!(std::abs(keyframe.arrow.w) <= kMaxWinding)) {
      fail(pointer + "/turns", fmt::format("too many turns: the winding must stay within +-{:g} radians (got {} "
                                           "turns)",
                                           kMaxWinding, number_text(k)));
    }
  }
  return keyframe;
}

void JsonReader::check_coordinates(Point x, const std::string& pointer) const {
  for (int i = 0; i < 2; ++i) {
    const double v = i == 0 ? x.real() : x.imag();
    if (std::abs(v) > kMaxKeyframeValue) {
      fail(pointer + "/" + std::to_string(i),
           fmt::format("coordinate must be within +-{:g} (got {})", kMaxKeyframeValue, number_text(v)));
    }
  }
}

// Knots must be strictly increasing (the registry requires a < b < c).
void JsonReader::check_knot_order(double previous, double knot, const std::string& pointer) const {
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

}  // namespace pita::scene::detail
