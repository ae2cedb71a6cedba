// The digest of what a figure draws (src/render/figure_digest.cpp): the same
// for the same figure whatever its titles, different when a shape, a colour,
// a legend or the view changes.
#include <gtest/gtest.h>

#include "render/figure.hpp"
#include "render/figure_digest.hpp"
#include "scene/scene.hpp"

namespace pita::render {
namespace {

std::uint64_t digest_of(const std::string& json) {
  const scene::Scene scene = scene::parse_scene(json, "test.json");
  return figure_digest(build_figure(scene));
}

std::string scene_text(const std::string& title, double w, const std::string& color, const std::string& width = "400") {
  return R"({"title": ")" + title + R"(", "method": "P6", "samples": 9,
    "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0.4}, {"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": )" +
         std::to_string(w) + R"(}, {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}],
    "canvas": {"width": )" +
         width + R"(, "height": 300},
    "layers": [{"type": "pattern", "color": ")" +
         color + R"(", "label": "P6"}, {"type": "legend"}]})";
}

TEST(FigureDigest, TitlesAsideTheSameFigureHasTheSameDigest) {
  const std::uint64_t base = digest_of(scene_text("one", 2.0, "red"));
  EXPECT_EQ(digest_of(scene_text("one", 2.0, "red")), base);
  EXPECT_EQ(digest_of(scene_text("another title", 2.0, "red")), base);
  EXPECT_NE(digest_of(scene_text("one", 2.1, "red")), base);         // a frame moves
  EXPECT_NE(digest_of(scene_text("one", 2.0, "blue")), base);        // a colour
  EXPECT_NE(digest_of(scene_text("one", 2.0, "red", "500")), base);  // the canvas, so the view
}

}  // namespace
}  // namespace pita::render
