// Reading "timing" (src/scene/timing_reader.cpp): every ease form, the
// arc-length point, per, and inheritance by panels. Refusals are data files
// (tests/data/bad/timing-*.json).
#include <string>

#include <gtest/gtest.h>

#include "core/ease.hpp"
#include "scene/scene.hpp"

namespace pita::scene {
namespace {

Scene with_timing(const std::string& timing, const std::string& more = "") {
  return parse_scene(R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
      {"t": 0.5, "p": [1, 1], "m": 1, "w": 0}, {"t": 1, "p": [2, 0], "m": 1, "w": 0}], "timing": )" +
                         timing + more + "}",
                     "s.json");
}

TEST(TimingReader, NoTimingIsTheIdentity) {
  const Scene scene = parse_scene(R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
      {"t": 0.5, "p": [1, 1], "m": 1, "w": 0}, {"t": 1, "p": [2, 0], "m": 1, "w": 0}]})",
                                  "s.json");
  EXPECT_TRUE(scene.timing.is_identity());
  EXPECT_EQ(scene.timing.pointer, "");
  EXPECT_TRUE(scene.panels[0].timing.is_identity());
}

TEST(TimingReader, NamedEases) {
  for (const NamedEase& named : named_eases()) {
    const Scene scene = with_timing(R"({"ease": ")" + std::string(named.name) + "\"}");
    EXPECT_EQ(scene.timing.ease, named.ease) << named.name;
    EXPECT_EQ(scene.timing.pointer, "/timing");
    EXPECT_FALSE(scene.timing.arc_length.has_value());
    EXPECT_EQ(scene.timing.per, WarpSpan::motion);
  }
}

TEST(TimingReader, CubicBezierStringWithAnySpacing) {
  EXPECT_EQ(with_timing(R"js({"ease": "cubic-bezier(0.1, -0.5, 0.9, 1.5)"})js").timing.ease,
            cubic_bezier_ease(0.1, -0.5, 0.9, 1.5));
  EXPECT_EQ(with_timing(R"js({"ease": "  cubic-bezier (0.1,0.2 ,0.3,  0.4 ) "})js").timing.ease,
            cubic_bezier_ease(0.1, 0.2, 0.3, 0.4));
  EXPECT_EQ(with_timing(R"js({"ease": "cubic-bezier(+1, 1e-1, 0, 1)"})js").timing.ease,
            cubic_bezier_ease(1.0, 0.1, 0.0, 1.0));
}

TEST(TimingReader, ParameterisedFamilies) {
  EXPECT_EQ(with_timing(R"({"ease": {"sine": {"k1": 0.25, "k2": 0.75}}})").timing.ease, sine_cap_ease(0.25, 0.75));
  EXPECT_EQ(with_timing(R"({"ease": {"parabolic": {"t1": 0, "t2": 1}}})").timing.ease, parabolic_ease(0.0, 1.0));
  EXPECT_EQ(with_timing(R"({"ease": {"parabolic": {"t1": 0.4, "t2": 0.4}}})").timing.ease, parabolic_ease(0.4, 0.4));
}

TEST(TimingReader, ArcLengthPointAndPer) {
  const Scene scene = with_timing(R"({"arc_length": "mid", "per": "span"})");
  EXPECT_EQ(scene.timing.arc_length, TrackedPoint::middle);
  EXPECT_EQ(scene.timing.per, WarpSpan::span);
  EXPECT_EQ(scene.timing.ease.kind, EaseKind::linear);
  EXPECT_FALSE(scene.timing.is_identity());
  EXPECT_EQ(with_timing(R"({"arc_length": "p"})").timing.arc_length, TrackedPoint::start);
  EXPECT_EQ(with_timing(R"({"arc_length": "q"})").timing.arc_length, TrackedPoint::end);
  EXPECT_TRUE(with_timing(R"({"per": "span"})").timing.is_identity());  // nothing to warp
}

TEST(TimingReader, PanelsInheritTheScenesTimingUnlessTheyGiveTheirOwn) {
  const Scene scene = with_timing(
      R"({"ease": "sine"})", R"(, "panels": ["P1", {"method": "P3", "timing": {"ease": "ease-out"}}, {"title": "x"}])");
  ASSERT_EQ(scene.panels.size(), 3u);
  EXPECT_EQ(scene.panels[0].timing.ease, *find_named_ease("sine"));
  EXPECT_EQ(scene.panels[1].timing.ease, *find_named_ease("ease-out"));
  EXPECT_EQ(scene.panels[1].timing.pointer, "/panels/1/timing");
  EXPECT_EQ(scene.panels[2].timing.ease, *find_named_ease("sine"));
  EXPECT_EQ(scene.panels[2].timing.pointer, "/timing");
}

TEST(TimingReader, PoseScenesTakeTheSameTiming) {
  const Scene scene = parse_scene(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "matrix": [[1, 0, 3], [0, 1, 0]]}], "timing": {"ease": "ease-in", "arc_length": "q"}})",
                                  "s.json");
  EXPECT_EQ(scene.timing.ease, *find_named_ease("ease-in"));
  EXPECT_EQ(scene.timing.arc_length, TrackedPoint::end);
  EXPECT_EQ(scene.panels[0].timing.ease, *find_named_ease("ease-in"));
}

TEST(TimingReader, NamesAreLowerCaseAsInCss) {
  EXPECT_THROW(with_timing(R"({"ease": "Ease-In"})"), SceneError);
  EXPECT_THROW(with_timing(R"js({"ease": "CUBIC-BEZIER(0, 0, 1, 1)"})js"), SceneError);
}

}  // namespace
}  // namespace pita::scene
