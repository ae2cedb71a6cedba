// analysis/claims.cpp: each test kind holds and fails where it must, on
// values known in closed form (the steady morph: m(t) = 2^t, w(t) = 1.2 t),
// and a claim the panel cannot measure is a SceneError at its pointer.
#include <cmath>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "analysis/claims.hpp"
#include "analysis/comparison.hpp"
#include "analysis/measure.hpp"
#include "scene/scene.hpp"

namespace pita::analysis {
namespace {

// Two panels: the SMA (steady: scale step ln 2 / 4 over 5 frames, no pop)
// and P1 through a midpoint that flips the vector (turn step pi).
scene::Scene with_claims(const std::string& claims) {
  return scene::parse_scene(fmt::format(R"({{"method": "SMA", "samples": 5, "keyframes": [
      {{"t": 0, "p": [0, 0], "m": 1, "w": 0}}, {{"t": 1, "p": [3, 1], "m": 2, "w": 1.2}}],
      "panels": ["SMA", {{"method": "P1", "keyframes": [
        {{"t": 0, "p": [0, 0], "q": [0, 2]}}, {{"t": 0.5, "p": [1, 0], "q": [1, -2]}},
        {{"t": 1, "p": [2, 0], "q": [2, 2]}}]}}],
      "claims": [{}]}})",
                                        claims),
                            "test.json");
}

ClaimOutcome only(const std::string& claim) {
  const scene::Scene scene = with_claims(claim);
  const std::vector<ClaimOutcome> outcomes = check_claims(motion::Stage(scene));
  EXPECT_EQ(outcomes.size(), 1u);
  return outcomes.at(0);
}

const double kStep = std::log(2.0) / 4.0;

TEST(Claims, BelowAndAboveANumber) {
  EXPECT_TRUE(
      only(fmt::format(R"({{"says": "s", "panel": 0, "measure": "scale-step", "below": {}}})", kStep + 1e-9)).held);
  EXPECT_FALSE(
      only(fmt::format(R"({{"says": "s", "panel": 0, "measure": "scale-step", "below": {}}})", kStep - 1e-9)).held);
  EXPECT_TRUE(only(R"({"says": "s", "panel": 0, "measure": "turn-step", "above": 0.29})").held);
  EXPECT_FALSE(only(R"({"says": "s", "panel": 0, "measure": "turn-step", "above": 0.31})").held);
}

TEST(Claims, AgainstAnotherPanelsMeasureScaledAndShifted) {
  // P1's turn step is pi, the SMA's 0.3: pi > 10 x 0.3 holds, pi > 11 x 0.3 does not.
  EXPECT_TRUE(only(R"({"says": "s", "panel": 1, "measure": "turn-step", "above": {"panel": 0, "times": 10}})").held);
  const ClaimOutcome failed =
      only(R"({"says": "P1 flips", "panel": 1, "measure": "turn-step", "above": {"panel": 0, "times": 11}})");
  EXPECT_FALSE(failed.held);
  EXPECT_EQ(failed.pointer, "/claims/0");
  EXPECT_EQ(failed.says, "P1 flips");
  EXPECT_NE(failed.measured.find("turn-step of panel 1 (P1 Pa-Ca) = 3.142, not above 3.3 (11 x turn-step of panel 0"),
            std::string::npos)
      << failed.measured;
  // "plus" and another measure of the same panel: ln 2 / 4 + 0.1 > 0.26 ... the SMA's scale step.
  EXPECT_TRUE(
      only(R"({"says": "s", "panel": 0, "measure": "turn-step", "above": {"measure": "scale-step", "plus": 0.1}})")
          .held);
  EXPECT_FALSE(
      only(R"({"says": "s", "panel": 0, "measure": "turn-step", "above": {"measure": "scale-step", "plus": 0.2}})")
          .held);
}

TEST(Claims, NearWithinAndAbsolute) {
  EXPECT_TRUE(only(R"({"says": "s", "panel": 0, "measure": "turn-step", "near": 0.3, "within": 1e-12})").held);
  EXPECT_FALSE(only(R"({"says": "s", "panel": 0, "measure": "turn-step", "near": 0.3001, "within": 1e-6})").held);
  // The signed angle from the SMA's D(1/2) to P1's: their vectors are
  // 2^(1/2) e^(0.6 i) and -2 i, an angle of -pi/2 - 0.6.
  EXPECT_TRUE(
      only(
          R"({"says": "s", "panel": 0, "measure": "angle:/panels/1@0.5", "near": -2.1707963267948966, "within": 1e-9})")
          .held);
  EXPECT_TRUE(
      only(R"({"says": "s", "panel": 0, "measure": "angle:/panels/1@0.5", "absolute": true, "above": 2.17})").held);
  EXPECT_FALSE(only(R"({"says": "s", "panel": 0, "measure": "angle:/panels/1@0.5", "above": 0})").held);
}

TEST(Claims, NearAnotherPanelsMeasure) {
  // P1's turn step is pi: pi / 10 is within 0.02 of the SMA's 0.3 ... and not within 0.01.
  EXPECT_TRUE(
      only(R"({"says": "s", "panel": 1, "measure": "turn-step", "near": {"panel": 0, "times": 10.471975511965978},
                       "within": 1e-9})")
          .held);
  EXPECT_TRUE(
      only(R"({"says": "s", "panel": 0, "measure": "turn-step", "near": {"panel": 1, "times": 0.1}, "within": 0.02})")
          .held);
  const ClaimOutcome far =
      only(R"({"says": "s", "panel": 0, "measure": "turn-step", "near": {"panel": 1, "times": 0.1}, "within": 0.01})");
  EXPECT_FALSE(far.held);
  EXPECT_NE(far.measured.find("not within 0.01 of 0.3142 (0.1 x turn-step of panel 1 (P1 Pa-Ca))"), std::string::npos)
      << far.measured;
}

TEST(Claims, IsForPops) {
  // The SMA does not pop (Sec. 4.7: it is smooth in its keyframes).
  EXPECT_TRUE(only(R"({"says": "s", "panel": 0, "measure": "pop", "is": false})").held);
  EXPECT_FALSE(only(R"({"says": "s", "panel": 0, "measure": "pop", "is": true})").held);
}

TEST(Claims, AMeasureThePanelLacksIsASceneErrorAtItsPointer) {
  try {
    only(R"({"says": "s", "panel": 0, "measure": "gain:C.q", "above": 0})");  // the SMA has keyframes A and B
    FAIL() << "no error";
  } catch (const scene::SceneError& error) {
    EXPECT_EQ(error.pointer(), "/claims/0/measure");
    EXPECT_NE(error.reason().find("no keyframe has that parameter"), std::string::npos) << error.reason();
  }
}

// A claim asking for a frame where the panel's motion has none (a time far
// outside the knots) is the claim's error, at its measure, not the panel's.
TEST(Claims, AFrameTheMotionLacksIsTheClaimsError) {
  for (const char* measure : {"frame-distance:/panels/0@1e300", "angle:P6@1e300"}) {
    try {
      only(fmt::format(R"({{"says": "s", "panel": 1, "measure": "{}", "above": 0}})", measure));
      FAIL() << "no error for " << measure;
    } catch (const scene::SceneError& error) {
      EXPECT_EQ(error.pointer(), "/claims/0/measure") << measure;
      EXPECT_NE(error.reason().find(fmt::format("\"{}\" cannot be measured: ", measure)), std::string::npos)
          << error.reason();
      EXPECT_NE(error.reason().find("t = 1e+300"), std::string::npos) << error.reason();
    }
  }
}

// "property:NAME": what pita audit measures on the panel's keyframes. P1 is
// affine-invariant (Sec. 4.10: defined by affine-invariant operators) and
// not winding-aware (it reads no winding: its reaction to a turn is 0).
TEST(Claims, PropertiesOfSection4OnThePanelsKeyframes) {
  EXPECT_TRUE(only(R"({"says": "s", "panel": 1, "measure": "property:affine-invariant", "below": 1e-9})").held);
  EXPECT_TRUE(only(R"({"says": "s", "panel": 1, "measure": "property:winding-aware", "below": 1e-12})").held);
  EXPECT_FALSE(only(R"({"says": "s", "panel": 1, "measure": "property:winding-aware", "above": 0.5})").held);
  try {
    only(R"({"says": "s", "panel": 1, "measure": "property:afine-invariant", "below": 1})");
    FAIL() << "no error";
  } catch (const scene::SceneError& error) {
    EXPECT_EQ(error.pointer(), "/claims/0/measure");
    EXPECT_NE(error.reason().find("unknown property \"afine-invariant\"; did you mean \"affine-invariant\"?"),
              std::string::npos)
        << error.reason();
  }
  try {
    only(R"({"says": "s", "panel": 0, "measure": "property:symmetric", "below": 1})");  // the SMA: two keyframes
    FAIL() << "no error";
  } catch (const scene::SceneError& error) {
    EXPECT_NE(error.reason().find("measured on three keyframes"), std::string::npos) << error.reason();
  }
}

// In a pose scene "property:NAME" is what pita audit poses measures on the
// panel's three poses: P6 symmetric and invariant to a change of handle, P5
// changing with it (docs/paper-notes.md N81); names are those of the pose
// properties; two poses are not measured.
TEST(Claims, PropertiesOfPitaAuditPosesOnThePanelsPoses) {
  const auto outcome = [](const std::string& claim) {
    const scene::Scene scene = scene::parse_scene(fmt::format(R"({{"method": "P6", "poses": [
        {{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}}, {{"t": 1, "matrix": [[0.8, -0.9, 3], [0.7, 1.1, 1]]}},
        {{"t": 2, "matrix": [[-0.6, -1.2, 5], [1.3, -0.2, 3]]}}],
        "panels": ["P6", "P5", {{"method": "SAM", "poses": [{{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}},
          {{"t": 1, "matrix": [[1, 0, 2], [0, 1, 0]]}}]}}],
        "claims": [{}]}})",
                                                              claim),
                                                  "poses.json");
    const std::vector<ClaimOutcome> outcomes = check_claims(motion::Stage(scene));
    EXPECT_EQ(outcomes.size(), 1u);
    return outcomes.at(0);
  };
  EXPECT_TRUE(outcome(R"({"says": "s", "panel": 0, "measure": "property:symmetric", "below": 1e-9})").held);
  EXPECT_TRUE(
      outcome(R"({"says": "s", "panel": 0, "measure": "property:right-affine-invariant", "below": 1e-9})").held);
  EXPECT_FALSE(
      outcome(R"({"says": "s", "panel": 0, "measure": "property:right-affine-invariant", "above": 1e-3})").held);
  try {
    outcome(R"({"says": "s", "panel": 0, "measure": "property:winding-aware", "below": 1})");
    FAIL() << "no error";
  } catch (const scene::SceneError& error) {
    EXPECT_EQ(error.pointer(), "/claims/0/measure");
    EXPECT_NE(error.reason().find("unknown property \"winding-aware\""), std::string::npos) << error.reason();
    EXPECT_NE(error.reason().find("left-affine-invariant"), std::string::npos) << error.reason();
  }
  try {
    outcome(R"({"says": "s", "panel": 2, "measure": "property:symmetric", "below": 1})");  // the SAM: two poses
    FAIL() << "no error";
  } catch (const scene::SceneError& error) {
    EXPECT_NE(error.reason().find("measured on three poses"), std::string::npos) << error.reason();
  }
}

// "discrepancy:P" and "discrepancy-t:P": the largest E of one predictor of
// Sec. 6.1 and its time. The steady SMA is its neighbours' steady average
// at every frame (E = 0 for "average"), though each frame differs from the
// one before; on P1 each name is that predictor's row of `pita measure`.
TEST(Claims, DiscrepancyOfOnePredictorAndWhen) {
  EXPECT_TRUE(only(R"({"says": "s", "panel": 0, "measure": "discrepancy:average", "below": 1e-9})").held);
  EXPECT_TRUE(only(R"({"says": "s", "panel": 0, "measure": "discrepancy:previous", "above": 1e-3})").held);
  const scene::Scene scene = with_claims(R"({"says": "s", "panel": 1, "measure": "pop", "is": false})");
  const MotionMeasures p1 = measure_panel(motion::Stage(scene), 1);
  const ArrowMeasures& arrows = std::get<ArrowMeasures>(p1.measured);
  int predictors = 0;
  for (const DiscrepancyStats& d : arrows.discrepancy) {
    if (d.frames == 0) continue;
    ++predictors;
    EXPECT_TRUE(only(fmt::format(R"({{"says": "s", "panel": 1, "measure": "discrepancy:{}", "near": {:.17g}}})",
                                 d.predictor, d.max))
                    .held)
        << d.predictor;
    EXPECT_TRUE(only(fmt::format(R"({{"says": "s", "panel": 1, "measure": "discrepancy-t:{}", "near": {:.17g}}})",
                                 d.predictor, d.t_of_max))
                    .held)
        << d.predictor;
  }
  EXPECT_EQ(predictors, 3);
  // The predictors differ here, so that a claim reading the wrong one would fail.
  EXPECT_NE(arrows.discrepancy[0].max, arrows.discrepancy[1].max);
}

// "frame-distance:M" (another method through the panel's keyframes),
// "knot-distance" and "guess-distance:G" / "guess-discrepancy:G" (a guess of
// the panel's "guesses" layer; tests/analysis/test_comparison.cpp has their
// closed forms). Panel 1's P1 passes its flipped midpoint, its vector
// vanishing at t = (1 - 1/sqrt 2)/2, where P3's log-polar vector, turning
// instead, is 2 long: the frames part by 2 (1.9999 at the 201 times).
TEST(Claims, AnotherMethodTheKnotsAndAGuess) {
  EXPECT_TRUE(only(R"({"says": "s", "panel": 1, "measure": "frame-distance:P1", "below": 1e-15})").held);
  EXPECT_TRUE(only(R"({"says": "s", "panel": 1, "measure": "frame-distance:P3", "near": 2, "within": 1e-3})").held);
  EXPECT_TRUE(only(R"({"says": "s", "panel": 1, "measure": "knot-distance", "below": 1e-12})").held);
  EXPECT_TRUE(only(R"({"says": "s", "panel": 0, "measure": "knot-distance", "below": 1e-12})").held);
  const auto guessed = [](const std::string& claim) {
    return check_claims(motion::Stage(scene::parse_scene(fmt::format(R"({{"method": "SMA", "keyframes": [
        {{"t": 0, "p": [0, 0], "m": 1, "w": 0}}, {{"t": 1, "p": [3, 1], "m": 2, "w": 1.2}}],
        "layers": [{{"type": "pattern"}}, {{"type": "guesses", "guesses": [
          {{"t": 0, "p": [0.5, 0], "q": [1.5, 0], "name": "L"}}, {{"t": 1, "p": [3, 1.25], "m": 2, "w": 1.2, "name": "R"}}]}}],
        "claims": [{}]}})",
                                                                     claim),
                                                         "test.json")));
  };
  EXPECT_TRUE(guessed(R"({"says": "s", "measure": "guess-distance:L", "near": 0.5, "within": 1e-12})").at(0).held);
  EXPECT_TRUE(guessed(R"({"says": "s", "measure": "guess-distance:R", "near": 0.25, "within": 1e-12})").at(0).held);
  EXPECT_TRUE(guessed(R"({"says": "s", "measure": "guess-discrepancy:L", "above": 0.01})").at(0).held);
  try {
    guessed(R"({"says": "s", "measure": "guess-distance:E", "below": 1})");
    FAIL() << "no error";
  } catch (const scene::SceneError& error) {
    EXPECT_EQ(error.pointer(), "/claims/0/measure");
    EXPECT_NE(error.reason().find("its guesses are named L, R"), std::string::npos) << error.reason();
  }
  try {
    only(R"({"says": "s", "panel": 0, "measure": "guess-distance:L", "below": 1})");
    FAIL() << "no error";
  } catch (const scene::SceneError& error) {
    EXPECT_NE(error.reason().find("the panel has no \"guesses\" layer"), std::string::npos) << error.reason();
  }
}

// "frame-distance:/panels/K/layers/L" and a claim's "layer": the motions
// layers draw, each its own method through the panel's keyframes (N57), are
// as far apart as a panel and the method (tests/analysis/test_comparison.cpp).
TEST(Claims, TheMotionsLayersDraw) {
  const auto layered = [](const std::string& claim) {
    return check_claims(motion::Stage(scene::parse_scene(fmt::format(R"({{"method": "P1", "keyframes": [
        {{"t": 0, "p": [0, 0], "m": 0.6, "w": 0.1}}, {{"t": 0.5, "p": [0, 0], "m": 2.4, "w": 1.6}},
        {{"t": 1, "p": [0, 0], "m": 1.2, "w": 3.3}}],
        "layers": [{{"type": "pattern", "method": "P3"}}, {{"type": "trajectory", "point": "q", "method": "P1"}},
                   {{"type": "keyframes"}}],
        "claims": [{}]}})",
                                                                     claim),
                                                         "test.json")));
  };
  const scene::Scene plain = scene::parse_scene(R"({"method": "P1", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 0.6, "w": 0.1}, {"t": 0.5, "p": [0, 0], "m": 2.4, "w": 1.6},
      {"t": 1, "p": [0, 0], "m": 1.2, "w": 3.3}]})",
                                                "test.json");
  const double expected = method_distance(motion::Stage(plain), 0, Method::P3);
  EXPECT_GT(expected, 0.1);
  const std::string near = fmt::format(R"("near": {:.17g}, "within": 1e-12)", expected);
  EXPECT_TRUE(
      layered(fmt::format(R"({{"says": "s", "layer": 0, "measure": "frame-distance:/panels/0/layers/1", {}}})", near))
          .at(0)
          .held);
  EXPECT_TRUE(
      layered(fmt::format(R"({{"says": "s", "measure": "frame-distance:/panels/0/layers/0", {}}})", near)).at(0).held);
  const ClaimOutcome same =
      layered(R"({"says": "s", "layer": 1, "measure": "frame-distance:/panels/0", "below": 1e-15})").at(0);
  EXPECT_TRUE(same.held);
  EXPECT_NE(same.measured.find("of layer 1 of the scene (P1"), std::string::npos) << same.measured;
  for (const char* bad : {R"({"says": "s", "layer": 2, "measure": "frame-distance:/panels/0", "below": 1})",
                          R"({"says": "s", "measure": "frame-distance:/panels/0/layers/3", "below": 1})"}) {
    try {
      layered(bad);
      ADD_FAILURE() << "no error: " << bad;
    } catch (const scene::SceneError& error) {
      EXPECT_EQ(error.pointer(), "/claims/0/measure");
      EXPECT_TRUE(error.reason().find("draws no motion of its own") != std::string::npos ||
                  error.reason().find("it has no layer 3 (it draws 3 layers)") != std::string::npos)
          << error.reason();
    }
  }
  try {
    layered(R"({"says": "s", "layer": 0, "measure": "turning", "below": 1})");
    ADD_FAILURE() << "no error";
  } catch (const scene::SceneError& error) {
    EXPECT_EQ(error.pointer(), "/claims/0/layer");
  }
}

TEST(Claims, AScenesWithoutClaimsHasNoOutcomes) {
  const scene::Scene scene = scene::parse_scene(R"({"method": "SMA", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [3, 1], "m": 2, "w": 1.2}]})",
                                                "test.json");
  EXPECT_TRUE(check_claims(motion::Stage(scene)).empty());
  EXPECT_EQ(claims_cost(scene), 0.0);
}

}  // namespace
}  // namespace pita::analysis
