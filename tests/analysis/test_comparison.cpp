// The comparisons of analysis/comparison.cpp against closed forms: Fig. 5's
// angles between vector motions (Lagrange weights by hand), Fig. 11's
// handle shift (0 for handle-invariant methods, the Pa-LP shift by hand), the
// distances between frames (of two panels, of two methods, at the knots) and
// between a frame and a drawn guess.
#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "analysis/comparison.hpp"
#include "core/discrepancy.hpp"
#include "scene/scene.hpp"

namespace pita::analysis {
namespace {

// Quadratic Lagrange weights of knots 0, 1/2, 1 at t (PITA Eq. 9).
std::array<double, 3> lagrange(double t) {
  return {(t - 0.5) * (t - 1.0) / 0.5, t * (t - 1.0) / -0.25, t * (t - 0.5) / 0.5};
}

// Three keyframes at the common origin (Fig. 5), even knots.
constexpr std::array<double, 3> kM = {0.6, 2.4, 1.2};
constexpr std::array<double, 3> kW = {0.1, 1.6, 3.3};

scene::Scene common_origin(const std::string& method) {
  return scene::parse_scene(fmt::format(R"({{"method": "{}", "keyframes": [
      {{"t": 0, "p": [0, 0], "m": {}, "w": {}}}, {{"t": 0.5, "p": [0, 0], "m": {}, "w": {}}},
      {{"t": 1, "p": [0, 0], "m": {}, "w": {}}}]}})",
                                        method, kM[0], kW[0], kM[1], kW[1], kM[2], kW[2]),
                            "test.json");
}

TEST(Comparison, PolarAndLogPolarVectorsAreParallel) {
  // -Po and -LP blend the winding w by the same Lagrange weights (Sec. 3.1):
  // D(t).w has the same direction at every t, only the magnitude differs.
  const scene::Scene scene = common_origin("P3");
  for (const double t : {0.1, 0.25, 0.75, 0.9}) {
    EXPECT_NEAR(vector_angle(motion::Stage(scene), 0, Method::PaPo, t), 0.0, 1e-12) << t;
  }
  // Extrapolated to t = 1.3 the Lagrange blend of the magnitudes is
  // 0.48 * 0.6 - 1.56 * 2.4 + 2.08 * 1.2 = -0.96 < 0: -Po's vector points
  // backwards, still on the same line (angle pi); -LP's magnitude stays > 0.
  EXPECT_NEAR(std::abs(vector_angle(motion::Stage(scene), 0, Method::PaPo, 1.3)), kPi, 1e-12);
}

TEST(Comparison, AngleIsUndefinedWhereAFrameVectorVanishes) {
  // P1 (Pa-Ca) blends the vectors 1, -1, 1 by the Lagrange weights: the
  // blend 1 - 2 * 4t(1 - t) vanishes at t = (1 - 1/sqrt 2)/2, where no angle
  // exists. A little later P1's vector points backwards (angle pi) and P3's
  // winding is the Lagrange blend pi * 4t(1 - t) of 0, pi, 0.
  const scene::Scene scene = scene::parse_scene(R"({"method": "P1", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 0.5, "p": [0, 0], "m": 1, "w": 3.141592653589793},
      {"t": 1, "p": [0, 0], "m": 1, "w": 0}]})",
                                                "test.json");
  const double zero = (1.0 - 1.0 / std::numbers::sqrt2) / 2.0;
  EXPECT_TRUE(std::isnan(vector_angle(motion::Stage(scene), 0, Method::P3, zero)));
  const double later = zero + 0.05;
  EXPECT_NEAR(vector_angle(motion::Stage(scene), 0, Method::P3, later),
              std::remainder(kPi * 4.0 * later * (1.0 - later) - kPi, 2.0 * kPi), 1e-12);
  EXPECT_NEAR(vector_angle(motion::Stage(scene), 0, Method::P3, 0.0), 0.0, 1e-12);
}

TEST(Comparison, CartesianAgainstLogPolarMatchesTheLagrangeBlends) {
  const scene::Scene scene = common_origin("P3");
  const double t = 0.25;
  const std::array<double, 3> L = lagrange(t);
  std::complex<double> cartesian = 0.0;
  double winding = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    cartesian += L[i] * std::polar(kM[i], kW[i]);  // -Ca: zero-turn vectors (all in (-pi, pi] here)
    winding += L[i] * kW[i];                       // -LP: the winding
  }
  const double expected = std::remainder(std::arg(cartesian) - winding, 2.0 * kPi);
  const double measured = vector_angle(motion::Stage(scene), 0, Method::P1, t);
  EXPECT_NEAR(measured, expected, 1e-12);
  EXPECT_GT(std::abs(measured), 0.1);  // the configuration separates them
}

// Fig. 11's configuration: an F-shaped polygon, the red handle = keyframe A
// on its stem (the scene's handle), and the orange handle E' on its top bar
// with the keyframes A', B', C' that mark the same key-shapes:
// K' = S_K(E') with S_K the similarity taking A onto K, winding w_K + angle(E') - angle(A).
struct Key {
  double t;
  std::complex<double> p;
  double m, w;
};
constexpr std::array<double, 3> kT = {0.0, 0.5, 1.0};
const std::array<Key, 3> kRed = {Key{0.0, {0.15, 0.1}, 1.1, kPi / 2}, Key{0.5, {3.6, 2.4}, 0.7, -0.4},
                                 Key{1.0, {6.8, -0.4}, 1.4, 2.6}};
const std::complex<double> kEp{0.3, 1.3}, kEq{0.9, 1.3};

std::array<Key, 3> orange() {
  std::array<Key, 3> keys{};
  const std::complex<double> a = std::polar(kRed[0].m, kRed[0].w);
  for (std::size_t i = 0; i < 3; ++i) {
    const std::complex<double> r = std::polar(kRed[i].m, kRed[i].w) / a;
    const std::complex<double> p = kRed[i].p + r * (kEp - kRed[0].p);
    const std::complex<double> q = kRed[i].p + r * (kEq - kRed[0].p);
    keys[i] = Key{kT[i], p, std::abs(q - p), kRed[i].w + std::arg((kEq - kEp) / a)};
  }
  return keys;
}

std::string keys_json(const std::array<Key, 3>& keys) {
  std::string out;
  for (const Key& k : keys) {
    out += fmt::format(R"({}{{"t": {}, "p": [{:.17g}, {:.17g}], "m": {:.17g}, "w": {:.17g}}})", out.empty() ? "" : ", ",
                       k.t, k.p.real(), k.p.imag(), k.m, k.w);
  }
  return "[" + out + "]";
}

const char* const kF = R"([[0, 0], [0, 1.35], [0.9, 1.35], [0.9, 1.08], [0.27, 1.08], [0.27, 0.765],
                           [0.72, 0.765], [0.72, 0.495], [0.27, 0.495], [0.27, 0]])";

double shift(const std::string& method) {
  const std::string text = fmt::format(
      R"({{"method": "{}", "keyframes": {}, "shapes": [{{"polygon": {}}}],
          "panels": [{{"method": "{}", "keyframes": {}, "handle": {{"p": [{}, {}], "q": [{}, {}]}}}}]}})",
      method, keys_json(kRed), kF, method, keys_json(orange()), kEp.real(), kEp.imag(), kEq.real(), kEq.imag());
  const scene::Scene scene = scene::parse_scene(text, "test.json");
  return handle_shift(motion::Stage(scene), 0);
}

TEST(Comparison, HandleInvariantMethodsDoNotShift) {
  // Fig. 10 / Sec. 4.5: P1 and P6 are handle-invariant (P1 is affine in the
  // keyframes' points; P6's steady morphs commute with the similarity).
  EXPECT_LT(shift("P1"), 1e-12);
  EXPECT_LT(shift("P6"), 1e-12);
}

TEST(Comparison, P2P3P5AreNotHandleInvariant) {
  // "All chosen PITAs are handle-invariant, except for P235 (Fig. 11)."
  for (const char* method : {"P2", "P3", "P5"}) EXPECT_GT(shift(method), 1e-2) << method;
}

TEST(Comparison, PaLpShiftByHand) {
  // P3 (Pa-LP): p(t) Lagrange of the points, w(t) exp of Lagrange of (log m, w).
  // The shapes' point x goes to D.p + D.w / E.w (x - E.p) for each handle;
  // over the same 129 times and the F's ten corners this is the measure
  // itself, computed without pita's motions, and Fig. 11's printed 1.19.
  const auto frame = [](const std::array<Key, 3>& keys, double t) {
    const std::array<double, 3> L = lagrange(t);
    std::complex<double> p = 0.0;
    double log_m = 0.0, w = 0.0;
    for (std::size_t i = 0; i < 3; ++i) {
      p += L[i] * keys[i].p;
      log_m += L[i] * std::log(keys[i].m);
      w += L[i] * keys[i].w;
    }
    return std::pair{p, std::polar(std::exp(log_m), w)};
  };
  const std::array<std::complex<double>, 10> corners{{{0, 0},
                                                      {0, 1.35},
                                                      {0.9, 1.35},
                                                      {0.9, 1.08},
                                                      {0.27, 1.08},
                                                      {0.27, 0.765},
                                                      {0.72, 0.765},
                                                      {0.72, 0.495},
                                                      {0.27, 0.495},
                                                      {0.27, 0}}};
  const std::complex<double> e0 = std::polar(kRed[0].m, kRed[0].w), e1 = kEq - kEp;
  double by_hand = 0.0;
  for (int i = 0; i < kHandleShiftSamples; ++i) {
    const double t = kT[0] + (kT[2] - kT[0]) * i / (kHandleShiftSamples - 1);
    const auto [p0, v0] = frame(kRed, t);
    const auto [p1, v1] = frame(orange(), t);
    for (const std::complex<double> x : corners) {
      const std::complex<double> a = p0 + v0 / e0 * (x - kRed[0].p);
      const std::complex<double> b = p1 + v1 / e1 * (x - kEp);
      by_hand = std::max(by_hand, std::abs(a - b));
    }
  }
  EXPECT_NEAR(shift("P3"), by_hand, 1e-12);
  EXPECT_NEAR(by_hand, 1.19, 0.005);  // as scenes/fig11-handle-invariance.json prints it (3 digits)
}

TEST(Comparison, PanelAngleOfTwoPanels) {
  // Fig. 19's D(1/4): weights 3/8, 3/4, -1/8 of the vectors (0, 2.4),
  // (+-0.15, -0.8), (0, 2.4) give (+-0.1125, 0): opposite directions.
  const std::string panel = R"({{"method": "P1", "keyframes": [
      {{"t": 0, "p": [0, 0], "q": [0, 2.4]}}, {{"t": 0.5, "p": [3, 1], "q": [{}, 0.2]}},
      {{"t": 1, "p": [6, 0], "q": [6, 2.4]}}]}})";
  const scene::Scene scene =
      scene::parse_scene(fmt::format(R"({{"method": "P1", "keyframes": [
      {{"t": 0, "p": [0, 0], "q": [0, 2.4]}}, {{"t": 0.5, "p": [3, 1], "q": [3.15, 0.2]}},
      {{"t": 1, "p": [6, 0], "q": [6, 2.4]}}], "panels": [{}, {}]}})",
                                     fmt::format(fmt::runtime(panel), 3.15), fmt::format(fmt::runtime(panel), 2.85)),
                         "test.json");
  const motion::Stage stage(scene);
  EXPECT_NEAR(std::abs(panel_angle(stage, 1, 0, 0.25)), std::numbers::pi, 1e-9);
  EXPECT_NEAR(panel_angle(stage, 1, 0, 0.0), 0.0, 1e-12);  // the keyframes agree at A
  // At t = 1/2 the vectors are B's: (0.15, -0.8) and (-0.15, -0.8).
  EXPECT_NEAR(panel_angle(stage, 0, 1, 0.5),
              std::arg(std::complex<double>(-0.15, -0.8) / std::complex<double>(0.15, -0.8)), 1e-12);
}

TEST(Comparison, FrameDistanceOfTranslatedKeyframesIsTheTranslation) {
  // Every PITA commutes with translations (similarity invariance, Sec. 4.3):
  // keyframes moved by (0.5, 0) move every frame by (0.5, 0).
  const std::string keys =
      R"([{{"t": 0, "p": [{0}, 0], "m": 1, "w": 0.2}}, {{"t": 1, "p": [{1}, 2], "m": 0.6, "w": 1.9}},
      {{"t": 2, "p": [{2}, 0], "m": 1.3, "w": 3.1}}])";
  const scene::Scene scene = scene::parse_scene(
      fmt::format(R"({{"method": "P6", "keyframes": {}, "panels": [{{"method": "P6", "keyframes": {}}}, "P6"]}})",
                  fmt::format(fmt::runtime(keys), 0, 3, 6), fmt::format(fmt::runtime(keys), 0.5, 3.5, 6.5)),
      "test.json");
  const motion::Stage stage(scene);
  EXPECT_NEAR(frame_distance(stage, 0, 1), 0.5, 1e-12);
  EXPECT_NEAR(frame_distance(stage, 1, 0), 0.5, 1e-12);
  EXPECT_EQ(frame_distance(stage, 1, 1), 0.0);
  // At one time, also past the last knot, where P6 extrapolates (Fig. 28).
  EXPECT_NEAR(frame_distance(stage, 0, 1, 1.0), 0.5, 1e-12);
  EXPECT_NEAR(frame_distance(stage, 0, 1, 3.0), 0.5, 1e-12);
}

// At one time: two SMA slides of one arrow, (0, 0) -> (1, 0) and (0, 0) ->
// (2, 0) over [0, 1], are t and 2t along x, extrapolated too: t apart.
TEST(Comparison, FrameDistanceAtOneTime) {
  const scene::Scene scene = scene::parse_scene(R"({"method": "SMA", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [1, 0], "m": 1, "w": 0}],
      "panels": ["SMA", {"method": "SMA", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [2, 0], "m": 1, "w": 0}]}]})",
                                                "test.json");
  const motion::Stage stage(scene);
  EXPECT_NEAR(frame_distance(stage, 0, 1), 1.0, 1e-12);  // at t = 1, the largest over [0, 1]
  EXPECT_NEAR(frame_distance(stage, 0, 1, 0.25), 0.25, 1e-12);
  EXPECT_NEAR(frame_distance(stage, 1, 0, 1.5), 1.5, 1e-12);
  EXPECT_EQ(frame_distance(stage, 0, 1, 0.0), 0.0);
}

// carried-distance: panel K's frames carried by the similarity taking its first
// keyframe onto the panel's. A method that commutes with similarities (P6,
// Sec. 4.3; P5 with translations, about its centroid) gives 0 for keyframes
// moved by one; He-G, about the global origin, does not (Fig. C.31).
TEST(Comparison, CarriedDistanceOfMovedKeyframes) {
  const std::string keys =
      R"([{{"t": 0, "p": [{0}, 0.5], "m": 1, "w": -0.4}}, {{"t": 0.5, "p": [{1}, 2.5], "m": 0.7, "w": 1.6}},
      {{"t": 1, "p": [{2}, 1], "m": 1.2, "w": 2.9}}])";
  const std::string here = fmt::format(fmt::runtime(keys), 1, 2.5, 4.5);
  const std::string there = fmt::format(fmt::runtime(keys), 7, 8.5, 10.5);
  for (const char* method : {"P5", "P6", "P1", "He-G"}) {
    const scene::Scene scene = scene::parse_scene(
        fmt::format(
            R"({{"method": "{0}", "keyframes": {1}, "panels": [{{"method": "{0}"}}, {{"method": "{0}", "keyframes": {2}}}]}})",
            method, here, there),
        "test.json");
    const motion::Stage stage(scene);
    EXPECT_NEAR(frame_distance(stage, 1, 0), 6.0, std::string(method) == "He-G" ? 1.0 : 1e-12) << method;
    if (std::string(method) == "He-G") {
      EXPECT_GT(carried_distance(stage, 1, 0), 0.1) << method;
    } else {
      EXPECT_NEAR(carried_distance(stage, 1, 0), 0.0, 1e-12) << method;
      EXPECT_NEAR(carried_distance(stage, 0, 1), 0.0, 1e-12) << method;
    }
  }
  // P6 commutes with rotations and scalings too: the keyframes turned by a
  // quarter turn and doubled about the origin.
  const scene::Scene turned = scene::parse_scene(R"({"method": "P6", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0.2}, {"t": 1, "p": [3, 2], "m": 0.6, "w": 1.9}, {"t": 2, "p": [6, 0], "m": 1.3, "w": 3.1}],
      "panels": ["P6", {"method": "P6", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 2, "w": 1.7707963267948966}, {"t": 1, "p": [-4, 6], "m": 1.2, "w": 3.4707963267948966},
      {"t": 2, "p": [0, 12], "m": 2.6, "w": 4.670796326794897}]}]})",
                                                 "test.json");
  EXPECT_NEAR(carried_distance(motion::Stage(turned), 1, 0), 0.0, 1e-12);
  // Two translations of one arrow by SMA: (0, 0) -> (1, 0) and (0, 0) -> (2, 0)
  // share their first keyframe (the identity carries), and their frames at t
  // are t and 2t along x: the largest distance is 1, at t = 1.
  const scene::Scene slides = scene::parse_scene(R"({"method": "SMA", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [1, 0], "m": 1, "w": 0}],
      "panels": ["SMA", {"method": "SMA", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [2, 0], "m": 1, "w": 0}]}]})",
                                                 "test.json");
  EXPECT_NEAR(carried_distance(motion::Stage(slides), 1, 0), 1.0, 1e-12);
  EXPECT_NEAR(carried_distance(motion::Stage(slides), 0, 1), 1.0, 1e-12);
}

// Poses: the largest distance between the corners of the reference triangle
// (tetrahedron) carried by the two motions. The pose PITAs commute with a
// left translation (docs/paper-notes.md N73), so poses moved by (0.3, -0.4)
// move every corner of every frame by 0.5.
TEST(Comparison, FrameDistanceOfTranslatedPosesIsTheTranslation) {
  const std::string poses =
      R"([{{"t": 0, "matrix": [[1, 0.2, {0}], [0.1, 0.8, {1}]]}}, {{"t": 0.5, "matrix": [[0.4, -1, {2}], [0.9, 0.5, {3}]]}},
      {{"t": 1, "matrix": [[-0.3, -0.9, {4}], [1.2, -0.2, {5}]]}}])";
  for (const char* method : {"P4", "P5", "P6", "P9"}) {
    const scene::Scene scene = scene::parse_scene(
        fmt::format(R"({{"method": "{}", "poses": {}, "panels": [{{"poses": {}}}, {{}}, "polySAM"]}})", method,
                    fmt::format(fmt::runtime(poses), 0, 0, 3, 2, 6, 0),
                    fmt::format(fmt::runtime(poses), 0.3, -0.4, 3.3, 1.6, 6.3, -0.4)),
        "test.json");
    const motion::Stage stage(scene);
    EXPECT_NEAR(frame_distance(stage, 0, 1), 0.5, 1e-12) << method;
    EXPECT_NEAR(frame_distance(stage, 1, 0), 0.5, 1e-12) << method;
    EXPECT_EQ(frame_distance(stage, 1, 1), 0.0) << method;
    // The polySAM through the same poses passes them too, and differs between.
    EXPECT_GT(frame_distance(stage, 1, 2), 0.01) << method;
  }
  const std::string space =
      R"([{{"t": 0, "matrix": [[1, 0, 0, {0}], [0, 1, 0, 0], [0, 0, 1, 0]]}},
      {{"t": 1, "matrix": [[0, -1, 0, {1}], [1, 0.2, 0, 1], [0, 0, 0.7, 1]]}},
      {{"t": 2, "matrix": [[-0.5, -0.6, 0.3, {2}], [0.6, -0.4, 0, 0], [0, 0.4, 1, 2]]}}])";
  const scene::Scene scene = scene::parse_scene(
      fmt::format(R"({{"dimension": 3, "method": "P6", "poses": {}, "panels": [{{"poses": {}}}, {{}}]}})",
                  fmt::format(fmt::runtime(space), 0, 2, 4), fmt::format(fmt::runtime(space), 0.5, 2.5, 4.5)),
      "test.json");
  const motion::Stage stage(scene);
  EXPECT_NEAR(frame_distance(stage, 0, 1), 0.5, 1e-12);
}

// "frame-distance:M": at the common origin P1 (Pa-Ca) and P3 (Pa-LP) share
// the point p = 0, and their vectors are the Lagrange blend of the keyframe
// vectors and the exponential of the blend of their logs (Sec. 3.1): the
// distance is the largest gap between the two blends over the 201 times.
TEST(Comparison, FrameDistanceToAMethodIsTheLargestGapBetweenItsFrames) {
  const scene::Scene scene = common_origin("P1");
  const motion::Stage stage(scene);
  double expected = 0.0;
  for (int i = 0; i < kFrameDistanceSamples; ++i) {
    const double t = static_cast<double>(i) / (kFrameDistanceSamples - 1);
    const std::array<double, 3> l = lagrange(t);
    std::complex<double> cartesian = 0.0, log = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      cartesian += l[k] * std::polar(kM[k], kW[k]);
      log += l[k] * std::complex<double>(std::log(kM[k]), kW[k]);
    }
    expected = std::max(expected, std::abs(cartesian - std::exp(log)));
  }
  EXPECT_GT(expected, 0.1);
  EXPECT_NEAR(method_distance(stage, 0, Method::P3), expected, 1e-12);
  EXPECT_EQ(method_distance(stage, 0, Method::P1), 0.0);  // the panel's own method
}

// The same through a second panel of method M on the same keyframes: the
// two forms are one distance. P3 and P10 (Pa-EL) agree while every keyframe
// angle is in (-pi, pi) (appendix B, Fig. B.30).
TEST(Comparison, FrameDistanceToAMethodIsThatToAPanelOfIt) {
  const scene::Scene scene = scene::parse_scene(R"({"method": "P3", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 3.09}, {"t": 0.5, "p": [3, 2], "m": 0.8, "w": 1.2},
      {"t": 1, "p": [6, 0], "m": 1.2, "w": -0.6}], "panels": ["P3", "P6", "P10"]})",
                                                "test.json");
  const motion::Stage stage(scene);
  EXPECT_EQ(method_distance(stage, 0, Method::P6), frame_distance(stage, 0, 1));
  EXPECT_GT(method_distance(stage, 0, Method::P6), 0.1);
  EXPECT_LT(method_distance(stage, 0, Method::P10), 1e-12);
  EXPECT_EQ(method_distance(stage, 0, Method::P10), frame_distance(stage, 0, 2));
}

// "knot-distance": P1 through p = 0, 1, 4 at t = 0, 1/2, 1 on the x axis
// (the Lagrange path p(t) = 4 t^2) with one vector interpolates its keyframes;
// timed by the arc length of p, it is at x = 2 at t = 1/2 (half of the path's
// length 4), one unit past B, at A and C at the ends.
TEST(Comparison, KnotDistanceIsZeroUnlessATimingMovesTheKnots) {
  const std::string keys = R"([{"t": 0, "p": [0, 0], "m": 1, "w": 0.5}, {"t": 0.5, "p": [1, 0], "m": 1, "w": 0.5},
      {"t": 1, "p": [4, 0], "m": 1, "w": 0.5}])";
  const scene::Scene scene = scene::parse_scene(
      fmt::format(
          R"({{"method": "P1", "keyframes": {}, "panels": ["P1", {{"method": "P1", "timing": {{"arc_length": "p"}}}}]}})",
          keys),
      "test.json");
  const motion::Stage stage(scene);
  EXPECT_LT(knot_distance(stage, 0), 1e-15);
  EXPECT_NEAR(knot_distance(stage, 1), 1.0, 1e-6);
}

// "guess-distance:G", "guess-discrepancy:G": a guess at t = 0 that is the
// SMA's first keyframe moved by (0.5, 0) is 0.5 from the frame, and its
// discrepancy is PITA Eq. 47's of the two arrows; a guess equal to the frame at
// t = 1 (the second keyframe) is at 0 in both.
TEST(Comparison, GuessGapIsTheDistanceOrTheDiscrepancyToTheFrameAtItsTime) {
  const scene::Scene scene = scene::parse_scene(R"({"method": "SMA", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [3, 1], "m": 2, "w": 1.2}]})",
                                                "test.json");
  const motion::Stage stage(scene);
  const Arrow A{{0.0, 0.0}, 1.0, 0.0};
  const scene::Guess moved{0.0, Arrow{{0.5, 0.0}, 1.0, 0.0}, "G", {}};
  EXPECT_NEAR(guess_gap(stage, 0, moved, false), 0.5, 1e-15);
  EXPECT_EQ(guess_gap(stage, 0, moved, true), pita::discrepancy(moved.arrow, A));
  EXPECT_GT(guess_gap(stage, 0, moved, true), 0.01);
  const scene::Guess exact{1.0, Arrow{{3.0, 1.0}, 2.0, 1.2}, "B", {}};
  EXPECT_LT(guess_gap(stage, 0, exact, false), 1e-14);
  EXPECT_LT(guess_gap(stage, 0, exact, true), 1e-12);
}

// "frame-distance:M" (method_distance): the SAM from I to a quarter turn about
// the origin against the linear blend through the same poses. At t = 1/2 the
// SAM turns the corner (1, 0) of the reference triangle to e^(i pi/4), the
// blend (I + R)/2 to cos(pi/4) e^(i pi/4): 1 - cos(pi/4) apart, the most over
// t (by symmetry; the 201 times include 1/2), and (0, 1) likewise. Against
// itself, 0; between arrows, the same as a panel of that method.
TEST(Comparison, MethodDistanceIsTheDistanceToThatMethodsMotion) {
  const scene::Scene poses = scene::parse_scene(R"({"method": "SAM", "poses": [
      {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[0, -1, 0], [1, 0, 0]]}]})",
                                                "test.json");
  const motion::Stage stage(poses);
  EXPECT_NEAR(method_distance(stage, 0, PoseMethod::linear), 1.0 - std::cos(std::numbers::pi / 4), 1e-12);
  EXPECT_EQ(method_distance(stage, 0, PoseMethod::sam), 0.0);
  const scene::Scene arrows = scene::parse_scene(R"({"method": "P6", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0.2}, {"t": 1, "p": [3, 2], "m": 0.6, "w": 1.9},
      {"t": 2, "p": [6, 0], "m": 1.3, "w": 3.1}], "panels": [{}, "P8"]})",
                                                 "test.json");
  const motion::Stage both(arrows);
  EXPECT_NEAR(method_distance(both, 0, Method::P8), frame_distance(both, 0, 1), 1e-12);
  EXPECT_GT(method_distance(both, 0, Method::P8), 0.01);
}

}  // namespace
}  // namespace pita::analysis
