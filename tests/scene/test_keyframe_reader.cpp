// Keyframes, moving keyframes and arrows read by the scene's JSON reader
// (src/scene/keyframe_reader.cpp): both forms of a keyframe, whole turns, the
// method's keyframe count and the knots' order. Each error test asserts the
// pointer and the whole reason.
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene/json_reader.hpp"
#include "scene/scene.hpp"
#include "scene_test_support.hpp"
#include "support/keys.hpp"

namespace pita::scene {
namespace {

using test::p6_with;
using test::p6_with_middle;

using detail::Json;
using detail::JsonReader;
using test::error_of;
using test::failure;
using test::kReader;

TEST(JsonReader, KeyframesComeInTheMethodsCountWithIncreasingKnots) {
  const Json three = Json::parse(R"([{"t": 0, "p": [0, 0], "m": 1, "w": 0},
      {"t": 0.5, "p": [1, 1], "q": [1, 3]}, {"t": 1, "p": [2, 0], "m": 2, "w": -1}])");
  const std::vector<Keyframe> keyframes = kReader.keyframes(three, "/keyframes", Method::P6);
  ASSERT_EQ(keyframes.size(), 3u);
  EXPECT_EQ(keyframes[1].t, 0.5);
  EXPECT_EQ(keyframes[1].arrow.m, 2.0);
  EXPECT_EQ(keyframes[1].arrow.w, kPi / 2.0);
  EXPECT_EQ(keyframes[2].arrow.w, -1.0);
  EXPECT_EQ(kReader.keyframes(three, "/keyframes", Method::SMA).size(), 3u);  // a spiral chain
  EXPECT_EQ(failure([&] { kReader.keyframes(Json::array({three[0]}), "/keyframes", Method::SMA); }),
            "/keyframes: method SMA takes at least 2 keyframes (got 1); more are chained (\"chain\")");
  const Json backwards = Json::parse(R"([{"t": 1, "p": [0, 0], "m": 1, "w": 0},
      {"t": 0.5, "p": [1, 1], "m": 1, "w": 0}])");
  EXPECT_EQ(failure([&] { kReader.keyframes(backwards, "/k", Method::SMA); }),
            "/k/1/t: knot 0.5 is less than the previous knot 1; knots must be strictly increasing");
}

TEST(Keyframes, ReadsEndPointFormAsZeroTurnArrow) {
  const Scene scene = parse_scene(p6_with_middle(R"({"t": 0.5, "p": [1, 1], "q": [4, 5]})"), "s.json");
  const Arrow& arrow = arrow_keys(scene).keyframes[1].arrow;
  EXPECT_EQ(arrow.p, make_point(1, 1));
  EXPECT_DOUBLE_EQ(arrow.m, 5.0);
  EXPECT_DOUBLE_EQ(arrow.w, std::atan2(4.0, 3.0));
  EXPECT_NEAR(arrow.q().real(), 4.0, 1e-15);
  EXPECT_NEAR(arrow.q().imag(), 5.0, 1e-15);
}

TEST(Keyframes, EndPointFormWindingIsPrincipal) {
  // Pointing left: w = pi exactly (in (-pi, pi]); pointing down-left: negative.
  const Scene left = parse_scene(p6_with_middle(R"({"t": 0.5, "p": [1, 1], "q": [0, 1]})"), "s.json");
  EXPECT_EQ(arrow_keys(left).keyframes[1].arrow.w, kPi);
  const Scene down = parse_scene(p6_with_middle(R"({"t": 0.5, "p": [1, 1], "q": [0, 0]})"), "s.json");
  EXPECT_DOUBLE_EQ(arrow_keys(down).keyframes[1].arrow.w, -3.0 * kPi / 4.0);
}

TEST(Keyframes, TurnsAddWholeTurnsToEitherForm) {
  const Scene polar = parse_scene(p6_with_middle(R"({"t": 0.5, "p": [1, 1], "m": 2, "w": 0.5, "turns": 2})"), "s.json");
  EXPECT_DOUBLE_EQ(arrow_keys(polar).keyframes[1].arrow.w, 0.5 + 4.0 * kPi);
  EXPECT_EQ(arrow_keys(polar).keyframes[1].arrow.m, 2.0);

  const Scene end = parse_scene(p6_with_middle(R"({"t": 0.5, "p": [1, 1], "q": [1, 2], "turns": -1})"), "s.json");
  EXPECT_DOUBLE_EQ(arrow_keys(end).keyframes[1].arrow.w, kPi / 2.0 - 2.0 * kPi);
  EXPECT_EQ(arrow_keys(end).keyframes[1].arrow.turns(), -1);

  // 3.0 is an integer, as JSON Schema's "integer" says.
  const Scene integral =
      parse_scene(p6_with_middle(R"({"t": 0.5, "p": [1, 1], "m": 2, "w": 0, "turns": 3.0})"), "s.json");
  EXPECT_DOUBLE_EQ(arrow_keys(integral).keyframes[1].arrow.w, 6.0 * kPi);
}

// Moving keyframes {"t", "from", "to"} (PITA Sec. 7.4): "from" is the
// keyframe, "to" its target; a keyframe that does not move is its own target.
TEST(Keyframes, MovingKeyframesReadFromAndTo) {
  const Json track = Json::parse(R"([{"t": 0, "p": [0, 0], "m": 1, "w": 0.5},
      {"t": 0.5, "from": {"p": [1, 1], "m": 2, "w": 1}, "to": {"p": [3, 4], "q": [3, 6], "turns": 1}},
      {"t": 1, "p": [2, 0], "q": [2, -1]}])");
  std::vector<Arrow> targets;
  const std::vector<Keyframe> keyframes = kReader.keyframes(track, "/keyframes", Method::P6, &targets);
  ASSERT_EQ(keyframes.size(), 3u);
  ASSERT_EQ(targets.size(), 3u);
  EXPECT_EQ(keyframes[1].t, 0.5);
  EXPECT_EQ(keyframes[1].arrow.p, make_point(1, 1));
  EXPECT_EQ(keyframes[1].arrow.m, 2.0);
  EXPECT_EQ(keyframes[1].arrow.w, 1.0);
  EXPECT_EQ(targets[1].p, make_point(3, 4));
  EXPECT_EQ(targets[1].m, 2.0);
  EXPECT_DOUBLE_EQ(targets[1].w, kPi / 2.0 + 2.0 * kPi);
  // The keyframes that do not move are their own targets.
  for (const std::size_t i : {std::size_t{0}, std::size_t{2}}) {
    EXPECT_EQ(targets[i].p, keyframes[i].arrow.p) << i;
    EXPECT_EQ(targets[i].m, keyframes[i].arrow.m) << i;
    EXPECT_EQ(targets[i].w, keyframes[i].arrow.w) << i;
  }
  EXPECT_EQ(targets[0].w, 0.5);
  EXPECT_DOUBLE_EQ(targets[2].w, -kPi / 2.0);

  // No keyframe moves: no targets (and any earlier ones are cleared).
  const Json still = Json::parse(R"([{"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [1, 0], "m": 1, "w": 0}])");
  EXPECT_EQ(kReader.keyframes(still, "/keyframes", Method::SMA, &targets).size(), 2u);
  EXPECT_TRUE(targets.empty());
}

TEST(Keyframes, MovingKeyframesAreCheckedLikeKeyframes) {
  const auto refusal = [](const std::string& middle) {
    const Json track = Json::parse(R"([{"t": 0, "p": [0, 0], "m": 1, "w": 0}, )" + middle +
                                   R"(, {"t": 1, "p": [2, 0], "m": 1, "w": 0}])");
    std::vector<Arrow> targets;
    return failure([&] { kReader.keyframes(track, "/keyframes", Method::P6, &targets); });
  };
  const std::string arrow = R"({"p": [1, 1], "m": 1, "w": 0})";
  EXPECT_EQ(refusal(R"({"t": 0.5, "from": )" + arrow + "}"),
            "/keyframes/1/to: missing required field (a moving keyframe needs \"from\" and \"to\" arrows)");
  EXPECT_EQ(refusal(R"({"t": 0.5, "to": )" + arrow + "}"),
            "/keyframes/1/from: missing required field (a moving keyframe needs \"from\" and \"to\" arrows)");
  EXPECT_EQ(refusal(R"({"from": )" + arrow + R"(, "to": )" + arrow + "}"),
            "/keyframes/1/t: missing required field (the knot, a time value)");
  EXPECT_EQ(refusal(R"({"t": 0.5, "p": [1, 1], "from": )" + arrow + R"(, "to": )" + arrow + "}"),
            "/keyframes/1/p: unknown field \"p\"; known fields: t, from, to");
  EXPECT_EQ(refusal(R"({"t": 0.5, "from": [1, 1], "to": )" + arrow + "}"),
            "/keyframes/1/from: an arrow must be an object {\"p\", and \"q\" or \"m\" and \"w\"} (got array [1,1])");
  EXPECT_EQ(refusal(R"({"t": 0.5, "from": )" + arrow + R"(, "to": {"p": [1, 1], "m": 0, "w": 0}})"),
            "/keyframes/1/to/m: magnitude must be > 0 (got 0)");
  EXPECT_EQ(refusal(R"({"t": 0.5, "from": {"t": 0.5, "p": [1, 1], "m": 1, "w": 0}, "to": )" + arrow + "}"),
            "/keyframes/1/from/t: unknown field \"t\"; known fields: p, m, w, q, turns");
  EXPECT_EQ(refusal(R"({"t": 0, "from": )" + arrow + R"(, "to": )" + arrow + "}"),
            "/keyframes/1/t: knot 0 equals the previous knot; knots must be strictly increasing");
}

TEST(JsonReader, ArrowsAreKeyframesWithoutAKnot) {
  const Arrow polar = kReader.arrow(Json::parse(R"({"p": [1, 2], "m": 3, "w": 0.5, "turns": -1})"), "/handle");
  EXPECT_EQ(polar.p, make_point(1, 2));
  EXPECT_EQ(polar.m, 3.0);
  EXPECT_DOUBLE_EQ(polar.w, 0.5 - 2.0 * kPi);
  const Arrow end = kReader.arrow(Json::parse(R"({"p": [0, 0], "q": [0, 2]})"), "/handle");
  EXPECT_EQ(end.m, 2.0);
  EXPECT_EQ(end.w, kPi / 2.0);
  EXPECT_EQ(failure([] { kReader.arrow(Json::parse(R"({"p": [1, 1], "q": [1, 1]})"), "/handle"); }),
            "/handle/q: q equals p: a zero-length arrow has no direction");
  EXPECT_EQ(failure([] { kReader.arrow(Json::parse(R"({"p": [0, 0], "m": 0, "w": 0})"), "/handle"); }),
            "/handle/m: magnitude must be > 0 (got 0)");
  EXPECT_EQ(failure([] { kReader.arrow(Json::parse(R"({"p": [0, 0]})"), "/handle"); }),
            "/handle: missing the arrow: give \"q\", or \"m\" and \"w\"");
  EXPECT_EQ(failure([] { kReader.arrow(Json::parse(R"({"t": 0, "p": [0, 0], "q": [1, 0]})"), "/handle"); }),
            "/handle/t: unknown field \"t\"; known fields: p, m, w, q, turns");
  EXPECT_EQ(failure([] { kReader.arrow(Json::parse("3"), "/handle"); }),
            "/handle: an arrow must be an object {\"p\", and \"q\" or \"m\" and \"w\"} (got 3)");
}

// Just inside the limits of keyframe values is fine (the cases beyond them are
// tests/data/bad/keyframes-m-subnormal.json, keyframes-w-too-large.json, ...).
TEST(Keyframes, ValuesJustInsideTheLimitsAreAccepted) {
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "m": 1e-100, "w": 1e6})")), "(no error)");
}

}  // namespace
}  // namespace pita::scene
