// Golden numbers (golden/number_compare.hpp) and SVG geometry
// (golden/svg_compare.hpp): what must match, what must not, and what the
// messages name.
#include <gtest/gtest.h>

#include "golden/figure_data.hpp"
#include "golden/number_compare.hpp"
#include "golden/svg_compare.hpp"
#include "render/figure.hpp"
#include "scene/scene.hpp"

namespace pita::golden {
namespace {

const char* kScene = R"({"method": "P6", "keyframes": [
  {"t": 0, "p": [0, 0], "m": 1, "w": 0.4}, {"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": 2.0},
  {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}],
  "layers": [{"type": "pattern"}, {"type": "discrepancy"}, {"type": "keyframes"}],
  "panels": ["P3", "P6"]})";

Json data_of(const std::string& text) {
  const scene::Scene s = scene::parse_scene(text, "s.json");
  return figure_data("s", s, render::build_figure(s));
}

// The scene with B.p.x written as `x` (instead of 3).
std::string with_moved_keyframe(const std::string& x) {
  std::string text = kScene;
  const std::string from = R"("p": [3, 1.5])";
  text.replace(text.find(from), from.size(), "\"p\": [" + x + ", 1.5]");
  return text;
}

TEST(FigureData, RecordsEveryShapeWithItsLayerAndFrame) {
  const Json data = data_of(kScene);
  ASSERT_EQ(data.at("panels").size(), 2u);
  const Json& items = data.at("panels")[1].at("items");
  // 17 frames (the default for figures), 16 circles (from the second frame),
  // 3 keyframes x (spiral + arrow).
  EXPECT_EQ(items.size(), 17u + 16u + 6u);
  EXPECT_EQ(items[0].at("layer"), "/layers/0");
  EXPECT_EQ(items[0].at("index"), 0);
  EXPECT_TRUE(items[0].contains("polyline"));
  EXPECT_TRUE(items[17].contains("circle"));
  EXPECT_EQ(items[17].at("index"), 1);
  // The text form reads back to the same numbers, exactly.
  EXPECT_EQ(Json::parse(figure_data_text(data)), data);
}

TEST(NumberCompare, IdenticalDataMatches) {
  const NumberComparison c = compare_numbers(data_of(kScene), data_of(kScene), 1e-9);
  EXPECT_TRUE(c.matches);
  EXPECT_EQ(c.differing, 0u);
  EXPECT_GT(c.compared, 100u);
}

TEST(NumberCompare, MovedKeyframeFailsAndNamesLayerAndFrame) {
  const NumberComparison c = compare_numbers(data_of(kScene), data_of(with_moved_keyframe("3.01")), 1e-9);
  EXPECT_FALSE(c.matches);
  EXPECT_TRUE(c.structure.empty()) << c.structure;
  EXPECT_GT(c.relative, 1e-4);
  EXPECT_FALSE(c.layer.empty());
  const std::string text = describe(c, 1e-9);
  EXPECT_NE(text.find("layer /layers/"), std::string::npos) << text;
  EXPECT_NE(text.find("frame"), std::string::npos) << text;
  EXPECT_NE(text.find(c.pointer), std::string::npos) << text;
}

TEST(NumberCompare, ChangeBelowToleranceMatches) {
  // 1e-12 of a ~7-unit figure is far below 1e-9 of its extent.
  const NumberComparison c = compare_numbers(data_of(kScene), data_of(with_moved_keyframe("3.000000000001")), 1e-9);
  EXPECT_TRUE(c.matches) << describe(c, 1e-9);
  EXPECT_GT(c.relative, 0.0);  // but it did see the change
}

TEST(NumberCompare, StructuralChangeIsNamed) {
  std::string more = kScene;
  more.replace(more.find(R"("panels": ["P3", "P6"])"), 22, R"("panels": ["P3", "P6", "P1"])");
  const NumberComparison c = compare_numbers(data_of(kScene), data_of(more), 1e-9);
  EXPECT_FALSE(c.matches);
  EXPECT_EQ(c.structure, "/panels: 3 panels instead of 2");
}

TEST(SvgCompare, ReadsGeometryNotIdsOrGlyphs) {
  const std::string svg = R"(<svg width="100px" version="1.1"><defs><symbol id="glyph0-1"><path d="M 1 2 L 3 4"/></symbol></defs>
<g id="surface12"><path style="stroke-width:0.8;" d="M 10.5 20 L -3e2 .5 "/><use xlink:href="#glyph0-1" x="7" y="8"/></g></svg>)";
  const std::vector<double> numbers = svg_numbers(svg);
  EXPECT_EQ(numbers, (std::vector<double>{100, 0.8, 10.5, 20, -300, 0.5, 7, 8}));
}

TEST(SvgCompare, FormattingChangesMatchAndMovesDoNot) {
  const std::string a = R"(<svg><path d="M 0.5 1 L 2 3"/></svg>)";
  const std::string b = R"(<svg><path d="M .5000 1.0 L 2 3.0000001"/></svg>)";
  const std::string moved = R"(<svg><path d="M 0.5 1 L 2 3.5"/></svg>)";
  const std::string extra = R"(<svg><path d="M 0.5 1 L 2 3 L 4 5"/></svg>)";
  EXPECT_TRUE(compare_svg(a, b, 1e-3).matches);
  const SvgComparison c = compare_svg(a, moved, 1e-3);
  EXPECT_FALSE(c.matches);
  EXPECT_EQ(c.worst, 3u);
  EXPECT_DOUBLE_EQ(c.difference, 0.5);
  EXPECT_FALSE(compare_svg(a, extra, 1e-3).matches);
  EXPECT_NE(describe(compare_svg(a, extra, 1e-3), 1e-3).find("6 numbers where the golden has 4"),
            std::string::npos);
}

}  // namespace
}  // namespace pita::golden
