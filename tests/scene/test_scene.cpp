// Scene parsing and validation (src/scene/scene.cpp). Every error test asserts
// the whole message: file, JSON Pointer and reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <unistd.h>

#include "scene/scene.hpp"
#include "scene_test_support.hpp"

namespace pita::scene {
namespace {

constexpr double kPi = std::numbers::pi;

using test::error_of;

// A P6 scene whose middle keyframe is `middle` (JSON text).
std::string p6_with_middle(const std::string& middle) {
  return R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0}, )" + middle +
         R"(, {"t": 1, "p": [2, 0], "m": 1, "w": 0}]})";
}

// A valid P6 scene with `extra` members added at the top level (",\"samples\": 3").
std::string p6_with(const std::string& extra) {
  return R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
    {"t": 0.5, "p": [1, 1], "m": 1, "w": 0}, {"t": 1, "p": [2, 0], "m": 1, "w": 0}])" +
         extra + "}";
}

// ------------------------------------------------------------ good scenes

TEST(Scene, ReadsMagnitudeWindingForm) {
  const Scene scene = parse_scene(R"({
    "$schema": "../schema/scene.schema.json",
    "description": "three arrows",
    "method": "P6",
    "keyframes": [
      {"t": 0,   "p": [0, 0],   "m": 1,   "w": 0.4},
      {"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": 2.0},
      {"t": 1,   "p": [6, 0],   "m": 1.2, "w": -3.5}
    ]
  })",
                                  "s.json");
  EXPECT_EQ(scene.path, "s.json");
  EXPECT_EQ(scene.description, "three arrows");
  EXPECT_EQ(scene.method_name, "P6");
  EXPECT_EQ(scene.method, Method::P6);
  EXPECT_FALSE(scene.samples.has_value());
  ASSERT_EQ(scene.keyframes.size(), 3u);
  EXPECT_EQ(scene.keyframes[1].t, 0.5);
  EXPECT_EQ(scene.keyframes[1].arrow.p, make_point(3, 1.5));
  EXPECT_EQ(scene.keyframes[1].arrow.m, 0.6);
  EXPECT_EQ(scene.keyframes[1].arrow.w, 2.0);
  EXPECT_EQ(scene.keyframes[2].arrow.w, -3.5);  // windings are never reduced
}

TEST(Scene, DefaultsApplied) {
  const Scene scene = parse_scene(p6_with(""), "s.json");
  EXPECT_EQ(scene.description, "");
  EXPECT_FALSE(scene.samples.has_value());
  EXPECT_EQ(scene.options.anchor, Anchor::start);
  EXPECT_EQ(scene.options.path_mean, MeanKind::geometric);
  EXPECT_EQ(scene.options.magnitude_mean, MeanKind::geometric);
}

TEST(Scene, ReadsEndPointFormAsZeroTurnArrow) {
  const Scene scene = parse_scene(p6_with_middle(R"({"t": 0.5, "p": [1, 1], "q": [4, 5]})"), "s.json");
  const Arrow& arrow = scene.keyframes[1].arrow;
  EXPECT_EQ(arrow.p, make_point(1, 1));
  EXPECT_DOUBLE_EQ(arrow.m, 5.0);
  EXPECT_DOUBLE_EQ(arrow.w, std::atan2(4.0, 3.0));
  EXPECT_NEAR(arrow.q().real(), 4.0, 1e-15);
  EXPECT_NEAR(arrow.q().imag(), 5.0, 1e-15);
}

TEST(Scene, EndPointFormWindingIsPrincipal) {
  // Pointing left: w = pi exactly (in (-pi, pi]); pointing down-left: negative.
  const Scene left = parse_scene(p6_with_middle(R"({"t": 0.5, "p": [1, 1], "q": [0, 1]})"), "s.json");
  EXPECT_EQ(left.keyframes[1].arrow.w, kPi);
  const Scene down = parse_scene(p6_with_middle(R"({"t": 0.5, "p": [1, 1], "q": [0, 0]})"), "s.json");
  EXPECT_DOUBLE_EQ(down.keyframes[1].arrow.w, -3.0 * kPi / 4.0);
}

TEST(Scene, TurnsAddWholeTurnsToEitherForm) {
  const Scene polar =
      parse_scene(p6_with_middle(R"({"t": 0.5, "p": [1, 1], "m": 2, "w": 0.5, "turns": 2})"), "s.json");
  EXPECT_DOUBLE_EQ(polar.keyframes[1].arrow.w, 0.5 + 4.0 * kPi);
  EXPECT_EQ(polar.keyframes[1].arrow.m, 2.0);

  const Scene end = parse_scene(p6_with_middle(R"({"t": 0.5, "p": [1, 1], "q": [1, 2], "turns": -1})"), "s.json");
  EXPECT_DOUBLE_EQ(end.keyframes[1].arrow.w, kPi / 2.0 - 2.0 * kPi);
  EXPECT_EQ(end.keyframes[1].arrow.turns(), -1);

  // 3.0 is an integer, as JSON Schema's "integer" says.
  const Scene integral =
      parse_scene(p6_with_middle(R"({"t": 0.5, "p": [1, 1], "m": 2, "w": 0, "turns": 3.0})"), "s.json");
  EXPECT_DOUBLE_EQ(integral.keyframes[1].arrow.w, 6.0 * kPi);
}

TEST(Scene, ReadsSamplesAndOptions) {
  const Scene scene = parse_scene(
      p6_with(R"(, "samples": 1000000, "options": {"anchor": "midpoint", "path_mean": "arithmetic",
                  "magnitude_mean": "harmonic"})"),
      "s.json");
  EXPECT_EQ(scene.samples, 1000000);
  EXPECT_EQ(scene.options.anchor, Anchor::midpoint);
  EXPECT_EQ(scene.options.path_mean, MeanKind::arithmetic);
  EXPECT_EQ(scene.options.magnitude_mean, MeanKind::harmonic);
  EXPECT_EQ(parse_scene(p6_with(R"(, "samples": 2)"), "s.json").samples, 2);
}

TEST(Scene, MethodNamesAreResolvedToCanonicalIds) {
  const std::string keyframes =
      R"("keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 0.5, "p": [1, 1], "m": 1, "w": 0},
                       {"t": 1, "p": [2, 0], "m": 1, "w": 0}]})";
  const Scene mnemonic = parse_scene(R"({"method": "la-lp", )" + keyframes, "s.json");
  EXPECT_EQ(mnemonic.method, Method::P6);
  EXPECT_EQ(mnemonic.method_name, "P6");
  const Scene number = parse_scene(R"({"method": "5s", )" + keyframes, "s.json");
  EXPECT_EQ(number.method_name, "P5S");
}

TEST(Scene, SmaTakesTwoKeyframes) {
  const Scene scene = parse_scene(R"({"method": "SMA", "keyframes": [
    {"t": 0, "p": [0, 0], "m": 2, "w": 0.3}, {"t": 1, "p": [4, 1], "m": 0.5, "w": 4.3}]})",
                                  "s.json");
  EXPECT_EQ(scene.method, Method::SMA);
  EXPECT_EQ(scene.keyframes.size(), 2u);
}

// ------------------------------------------------------------ malformed JSON

TEST(SceneError, MalformedJsonGivesLineAndColumn) {
  EXPECT_EQ(error_of("{\n  \"method\": \"P6\",\n  \"keyframes\": [1, 2,]\n}"),
            "s.json:3:22: malformed JSON: syntax error while parsing value - unexpected ']'; "
            "expected '[', '{', or a literal");
  EXPECT_EQ(error_of(""),
            "s.json:1:1: malformed JSON: syntax error while parsing value - unexpected end of "
            "input; expected '[', '{', or a literal");
  EXPECT_EQ(error_of("{\"method\": \"P6\"} x"),
            "s.json:1:18: malformed JSON: syntax error while parsing value - invalid literal; last "
            "read: '\"P6\"} x'; expected end of input");
}

TEST(SceneError, ErrorCarriesItsParts) {
  try {
    parse_scene("{\n\n  ]", "s.json");
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.file(), "s.json");
    EXPECT_EQ(error.line(), 3);
    EXPECT_EQ(error.column(), 3);
    EXPECT_EQ(error.pointer(), "");
  }
  try {
    parse_scene(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "m": -2, "w": 1})"), "s.json");
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.pointer(), "/keyframes/1/m");
    EXPECT_EQ(error.reason(), "magnitude must be > 0 (got -2)");
    EXPECT_EQ(error.line(), 0);
  }
}

TEST(SceneError, NumberTooLargeForDoubleGivesLineAndColumn) {
  // nlohmann 3.11 refuses 1e999 at parse time; the error points at the number.
  EXPECT_EQ(error_of("{\"method\": \"P6\",\n \"samples\": 1e999}"),
            "s.json:2:13: number 1e999 is out of range (too large for a double)");
  EXPECT_EQ(error_of("[-1e999]"), "s.json:1:2: number -1e999 is out of range (too large for a double)");
}

// ------------------------------------------------------------ structure and types

TEST(SceneError, SceneMustBeAnObject) {
  EXPECT_EQ(error_of("[1, 2]"), "s.json: a scene must be a JSON object (got array [1,2])");
  EXPECT_EQ(error_of("\"P6\""), "s.json: a scene must be a JSON object (got string \"P6\")");
  // Long values are cut short.
  EXPECT_EQ(error_of("[\"" + std::string(60, 'a') + "\"]"),
            "s.json: a scene must be a JSON object (got array [\"" + std::string(35, 'a') + "...)");
}

TEST(SceneError, MissingFields) {
  EXPECT_EQ(error_of(R"({"keyframes": []})"),
            "s.json: /method: missing required field (a method such as \"P6\")");
  EXPECT_EQ(error_of(R"({"method": "P6"})"),
            "s.json: /keyframes: missing required field (an array of keyframes)");
  EXPECT_EQ(error_of(p6_with_middle(R"({"p": [1, 0], "m": 1, "w": 0})")),
            "s.json: /keyframes/1/t: missing required field (the knot, a time value)");
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "m": 1, "w": 0})")),
            "s.json: /keyframes/1/p: missing required field (the start point [x, y])");
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0]})")),
            "s.json: /keyframes/1: missing the arrow: give \"q\", or \"m\" and \"w\"");
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "m": 1})")),
            "s.json: /keyframes/1/w: missing required field (\"m\" needs the winding \"w\")");
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "w": 1})")),
            "s.json: /keyframes/1/m: missing required field (\"w\" needs the magnitude \"m\")");
}

TEST(SceneError, WrongTypes) {
  EXPECT_EQ(error_of(R"({"method": 6, "keyframes": []})"), "s.json: /method: must be a string (got 6)");
  EXPECT_EQ(error_of(R"({"$schema": null, "method": "P6", "keyframes": []})"),
            "s.json: /$schema: must be a string (got null)");
  EXPECT_EQ(error_of(R"({"description": true, "method": "P6", "keyframes": []})"),
            "s.json: /description: must be a string (got true)");
  EXPECT_EQ(error_of(R"({"method": "P6", "keyframes": {"t": 0}})"),
            "s.json: /keyframes: must be an array of keyframes (got object {\"t\":0})");
  EXPECT_EQ(error_of(p6_with_middle("[0.5, 1, 0]")),
            "s.json: /keyframes/1: a keyframe must be an object (got array [0.5,1,0])");
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": "0.5", "p": [1, 0], "m": 1, "w": 0})")),
            "s.json: /keyframes/1/t: must be a number (got string \"0.5\")");
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "m": "abc", "w": 0})")),
            "s.json: /keyframes/1/m: must be a number (got string \"abc\")");
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "m": 1, "w": [0]})")),
            "s.json: /keyframes/1/w: must be a number (got array [0])");
  EXPECT_EQ(error_of(p6_with(R"(, "options": "midpoint")")),
            "s.json: /options: must be an object (got string \"midpoint\")");
}

TEST(SceneError, PointsMustBeTwoNumbers) {
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1], "m": 1, "w": 0})")),
            "s.json: /keyframes/1/p: must be an array of two numbers [x, y] (got array [1])");
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 2, 3], "m": 1, "w": 0})")),
            "s.json: /keyframes/1/p: must be an array of two numbers [x, y] (got array [1,2,3])");
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": {"x": 1}, "m": 1, "w": 0})")),
            "s.json: /keyframes/1/p: must be an array of two numbers [x, y] (got object {\"x\":1})");
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, "a"], "m": 1, "w": 0})")),
            "s.json: /keyframes/1/p/1: must be a number (got string \"a\")");
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "q": [null, 0]})")),
            "s.json: /keyframes/1/q/0: must be a number (got null)");
}

// ------------------------------------------------------------ values

TEST(SceneError, MagnitudeMustBePositive) {
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "m": -2, "w": 1})")),
            "s.json: /keyframes/1/m: magnitude must be > 0 (got -2)");
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "m": 0, "w": 1})")),
            "s.json: /keyframes/1/m: magnitude must be > 0 (got 0)");
}

TEST(SceneError, EitherEndPointOrMagnitudeAndWinding) {
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "m": 1, "q": [2, 2]})")),
            "s.json: /keyframes/1/q: give either \"q\" or \"m\" and \"w\", not both");
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "q": [2, 2], "w": 1})")),
            "s.json: /keyframes/1/q: give either \"q\" or \"m\" and \"w\", not both");
}

TEST(SceneError, ZeroLengthArrow) {
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "q": [1, 0]})")),
            "s.json: /keyframes/1/q: q equals p: a zero-length arrow has no direction");
}

TEST(SceneError, ArrowTooLong) {
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [-1e308, 0], "q": [1e308, 0]})")),
            "s.json: /keyframes/1/p/0: coordinate must be within +-1e+100 (got -1e+308)");
}

TEST(SceneError, TurnsMustBeAnInteger) {
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "m": 1, "w": 1, "turns": 1.5})")),
            "s.json: /keyframes/1/turns: must be an integer (got 1.5)");
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "q": [1, 1], "turns": "1"})")),
            "s.json: /keyframes/1/turns: must be an integer (got string \"1\")");
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "q": [1, 1], "turns": 1e308})")),
            "s.json: /keyframes/1/turns: too many turns: the winding must stay within +-1e+06 radians (got 1e+308 turns)");
}

TEST(SceneError, KnotsMustBeStrictlyIncreasing) {
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0, "p": [1, 0], "m": 1, "w": 1})")),
            "s.json: /keyframes/1/t: knot 0 equals the previous knot; knots must be strictly "
            "increasing");
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 1.5, "p": [1, 0], "m": 1, "w": 1})")),
            "s.json: /keyframes/2/t: knot 1 is less than the previous knot 1.5; knots must be "
            "strictly increasing");
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": -0.5, "p": [1, 0], "m": 1, "w": 1})")),
            "s.json: /keyframes/1/t: knot -0.5 is less than the previous knot 0; knots must be "
            "strictly increasing");
}

TEST(SceneError, UnknownMethod) {
  EXPECT_EQ(error_of(R"({"method": "La-LQ", "keyframes": []})"),
            "s.json: /method: unknown method \"La-LQ\"; did you mean P6 (La-LP), P3 (Pa-LP) or LS-LP?");
  EXPECT_EQ(error_of(R"({"method": "xyzzy", "keyframes": []})"),
            "s.json: /method: unknown method \"xyzzy\"; known methods: P1, P2, P3, P4, P5, P5S, P6, "
            "P7, P8, P9, P10, SMA, Pa-Po, LS-Ca, LS-LP");
}

TEST(SceneError, WrongNumberOfKeyframes) {
  EXPECT_EQ(error_of(R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0}]})"),
            "s.json: /keyframes: method P6 (La-LP) takes exactly 3 keyframes (got 1)");
  EXPECT_EQ(error_of(R"({"method": "SMA", "keyframes": []})"),
            "s.json: /keyframes: method SMA takes exactly 2 keyframes (got 0)");
  EXPECT_EQ(error_of(R"({"method": "sma", "keyframes": [1, 2, 3]})"),
            "s.json: /keyframes: method SMA takes exactly 2 keyframes (got 3)");
}

TEST(SceneError, SamplesOutOfRange) {
  EXPECT_EQ(error_of(p6_with(R"(, "samples": 1)")),
            "s.json: /samples: must be an integer between 2 and 1000000 (got 1)");
  EXPECT_EQ(error_of(p6_with(R"(, "samples": 1000001)")),
            "s.json: /samples: must be an integer between 2 and 1000000 (got 1000001)");
  EXPECT_EQ(error_of(p6_with(R"(, "samples": -5)")),
            "s.json: /samples: must be an integer between 2 and 1000000 (got -5)");
  EXPECT_EQ(error_of(p6_with(R"(, "samples": 2.5)")), "s.json: /samples: must be an integer (got 2.5)");
  EXPECT_EQ(error_of(p6_with(R"(, "samples": "9")")),
            "s.json: /samples: must be an integer (got string \"9\")");
}

TEST(SceneError, OptionValues) {
  EXPECT_EQ(error_of(p6_with(R"(, "options": {"anchor": "end"})")),
            "s.json: /options/anchor: must be \"start\" or \"midpoint\" (got string \"end\")");
  EXPECT_EQ(error_of(p6_with(R"(, "options": {"path_mean": "geometic"})")),
            "s.json: /options/path_mean: must be \"arithmetic\", \"geometric\" or \"harmonic\" (got "
            "string \"geometic\")");
  EXPECT_EQ(error_of(p6_with(R"(, "options": {"magnitude_mean": 1})")),
            "s.json: /options/magnitude_mean: must be \"arithmetic\", \"geometric\" or \"harmonic\" "
            "(got 1)");
}

TEST(SceneError, UnknownFieldsSuggestCloseNames) {
  EXPECT_EQ(error_of(p6_with(R"(, "smaples": 3)")),
            "s.json: /smaples: unknown field \"smaples\"; did you mean \"samples\"?");
  EXPECT_EQ(error_of(R"({"method": "P6", "Keyframe": []})"),
            "s.json: /Keyframe: unknown field \"Keyframe\"; did you mean \"keyframes\"?");
  EXPECT_EQ(error_of(p6_with(R"(, "canvs": {})")),
            "s.json: /canvs: unknown field \"canvs\"; did you mean \"canvas\"?");
  EXPECT_EQ(error_of(p6_with(R"(, "figure": {})")),
            "s.json: /figure: unknown field \"figure\"; known fields: $schema, description, method, "
            "keyframes, samples, options, title, canvas, layers, panels, golden");
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "mm": 1, "w": 0})")),
            "s.json: /keyframes/1/mm: unknown field \"mm\"; did you mean \"m\"?");
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "m": 1, "w": 0, "x": 1})")),
            "s.json: /keyframes/1/x: unknown field \"x\"; known fields: t, p, m, w, q, turns");
  EXPECT_EQ(error_of(p6_with(R"(, "options": {"anchr": "start"})")),
            "s.json: /options/anchr: unknown field \"anchr\"; did you mean \"anchor\"?");
}

TEST(SceneError, PointerEscapesSlashAndTilde) {
  EXPECT_EQ(error_of(R"({"a/b~c": 1})"),
            "s.json: /a~1b~0c: unknown field \"a/b~c\"; known fields: $schema, description, method, "
            "keyframes, samples, options, title, canvas, layers, panels, golden");
}

// ------------------------------------------------------------ methods and files

TEST(Scene, ResolveMethod) {
  EXPECT_EQ(resolve_method("P8"), Method::P8);
  EXPECT_EQ(resolve_method("lo-pe"), Method::P8);
  try {
    resolve_method("P66");
    FAIL() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()).rfind("unknown method \"P66\"; did you mean P6 (La-LP)", 0), 0u)
        << error.what();
  }
}

TEST(Scene, WithMethodReplacesTheMethodWhenTheCountFits) {
  const Scene scene = with_method(parse_scene(p6_with(""), "s.json"), Method::P8);
  EXPECT_EQ(scene.method, Method::P8);
  EXPECT_EQ(scene.method_name, "P8");
  try {
    with_method(parse_scene(p6_with(""), "s.json"), Method::SMA);
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_STREQ(error.what(), "s.json: /keyframes: method SMA takes exactly 2 keyframes (got 3)");
  }
}

TEST(Scene, LoadSceneReportsUnreadableFiles) {
  try {
    load_scene("no/such/scene.json");
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_STREQ(error.what(),
                 "no/such/scene.json: cannot open the scene file (No such file or directory)");
  }
  try {
    load_scene(std::filesystem::temp_directory_path());
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.reason(), "cannot read the scene file: it is a directory");
  }
}

TEST(Scene, LoadSceneNamesTheFileAsGiven) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("pita-test-scene-" + std::to_string(::getpid()) + ".json");
  std::ofstream(path) << R"({"method": "P6", "keyframes": []})";
  try {
    load_scene(path);
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_EQ(std::string(error.what()),
              path.string() + ": /keyframes: method P6 (La-LP) takes exactly 3 keyframes (got 0)");
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace pita::scene

namespace pita::scene {
namespace {

// Found by feeding malformed scenes to `pita eval` (a corpus of 461 cases).
TEST(SceneRobustness, DuplicateKeysAreRefusedWithTheirPointer) {
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "m": 1, "w": 0, "m": 2})")),
            "s.json: /keyframes/1/m: field \"m\" is given twice in the same object");
  EXPECT_EQ(error_of(R"({"method": "P6", "method": "SMA", "keyframes": []})"),
            "s.json: /method: field \"method\" is given twice in the same object");
}

TEST(SceneRobustness, NulByteIsRefusedNotTreatedAsTheEnd) {
  const std::string text = std::string(R"({"method": "P6"})") + '\0' + "junk";
  EXPECT_EQ(error_of(text).rfind("s.json:1:17: the file contains a NUL byte", 0), 0u) << error_of(text);
}

TEST(SceneRobustness, DeepNestingIsReportedShortly) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_EQ(error_of(R"({"method": )" + deep + "}"),
            "s.json: /method: must be a string (got array [[[[...]]]])");
}

TEST(SceneRobustness, KeyframeValuesHaveLimits) {
  EXPECT_NE(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "m": 5e-324, "w": 0})"))
                .find("/keyframes/1/m: magnitude must be between 1e-100 and 1e+100"),
            std::string::npos);
  EXPECT_NE(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "m": 1, "w": 1e14})"))
                .find("/keyframes/1/w: winding must be within +-1e+06 radians"),
            std::string::npos);
  EXPECT_NE(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "m": 1, "w": 0, "turns": 1e18})"))
                .find("/keyframes/1/turns: too many turns"),
            std::string::npos);
  EXPECT_NE(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 1e200], "m": 1, "w": 0})"))
                .find("/keyframes/1/p/1: coordinate must be within +-1e+100"),
            std::string::npos);
  EXPECT_NE(error_of(p6_with_middle(R"({"t": 0.5, "p": [0, 0], "q": [5e-324, 0]})"))
                .find("/keyframes/1/q: q is within 1e-100 of p"),
            std::string::npos);
  // Just inside the limits is fine.
  EXPECT_EQ(error_of(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "m": 1e-100, "w": 1e6})")), "(no error)");
}

}  // namespace
}  // namespace pita::scene
