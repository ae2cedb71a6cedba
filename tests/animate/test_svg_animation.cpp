// The animated SVG (src/animate/svg_animation.cpp). Its playback in a real
// browser is tested by tests/cli/test_animate.cpp (headless Chromium).
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "animate/svg_animation.hpp"
#include "scene/scene.hpp"
#include "support/source_paths.hpp"

namespace pita::animate {
namespace {

using test::kScenes;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(SvgAnimation, OneGroupPerFrameShownInTurn) {
  const scene::Scene scene = scene::load_scene(kScenes / "fig24-animation-frames.json");
  const Timeline timeline = make_timeline(scene, {std::nullopt, std::nullopt, 10});
  int progressed = 0;
  const std::string svg = animated_svg(scene, timeline, [&](int) { ++progressed; });
  EXPECT_EQ(progressed, 10);
  EXPECT_EQ(count(svg, "<animate attributeName=\"visibility\""), 10u);
  // looping: each frame visible over [k/N, (k+1)/N) of the 1/3 s (10 frames at 30 fps)
  EXPECT_NE(svg.find("values=\"hidden;visible;hidden\" keyTimes=\"0;0.3;0.4\" dur=\"0.333333s\""), std::string::npos);
  EXPECT_NE(svg.find("values=\"visible;hidden\" keyTimes=\"0;0.1\""), std::string::npos);
  EXPECT_NE(svg.find("values=\"hidden;visible\" keyTimes=\"0;0.9\""), std::string::npos);
  EXPECT_EQ(count(svg, "repeatCount=\"indefinite\""), 10u);
  // no script: SMIL only
  EXPECT_EQ(svg.find("<script"), std::string::npos);
  // the two static layers (below and above the frames) are nested cairo documents with distinct ids
  EXPECT_EQ(count(svg, "<svg"), 3u);
  EXPECT_GT(count(svg, "id=\"pita-below-"), 0u);  // the title's glyphs
  EXPECT_EQ(svg.find("id=\"glyph"), std::string::npos);
}

TEST(SvgAnimation, NotLoopingFreezesOnTheLastFrame) {
  const scene::Scene scene = scene::load_scene(kScenes / "fig27-animated-pattern.json");
  const Timeline timeline = make_timeline(scene, {std::nullopt, std::nullopt, 4});
  const std::string svg = animated_svg(scene, timeline);
  EXPECT_EQ(count(svg, "fill=\"freeze\""), 4u);
  EXPECT_EQ(count(svg, "repeatCount"), 0u);
}

TEST(SvgAnimation, ImagesAreEmbeddedOnceAndPlacedByUse) {
  const scene::Scene scene = scene::load_scene(kScenes / "fig23-image-motion.json");
  const Timeline timeline = make_timeline(scene);
  const std::string svg = animated_svg(scene, timeline);
  EXPECT_EQ(count(svg, "<image id=\"pita-image-"), 1u);
  // four panels, each frame one picture and a trail of three: at most 4 x 4 uses per frame
  EXPECT_GE(count(svg, "xlink:href=\"#pita-image-0\""), 120u * 4u);
  // compact: 120 frames of Fig. 23 well under 2 MB
  EXPECT_LT(svg.size(), 2u << 20);
}

}  // namespace
}  // namespace pita::animate
