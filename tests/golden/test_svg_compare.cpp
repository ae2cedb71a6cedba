// Comparing SVG figures by their geometry (src/golden/svg_compare.cpp): the
// numbers of attribute values outside <defs>, compared with a tolerance in
// pixels, and what the message says.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "golden/svg_compare.hpp"

namespace pita::golden {
namespace {

TEST(SvgCompare, ReadsGeometryNotIdsOrGlyphs) {
  const std::string svg =
      R"(<svg width="100px" version="1.1"><defs><symbol id="glyph0-1"><path d="M 1 2 L 3 4"/></symbol></defs>
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
  EXPECT_NE(describe(compare_svg(a, extra, 1e-3), 1e-3).find("6 numbers where the golden has 4"), std::string::npos);
}

TEST(SvgCompare, SkipsNamesIdsNamespacesAndText) {
  const std::string svg =
      R"svg(<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" version="1.1" id="s2">
<g transform="matrix(1,0,0,1,5.5,-6)" fill="rgb(20%,40%,60%)"><text x='+3' y="1e1">123</text></g></svg>)svg";
  EXPECT_EQ(svg_numbers(svg), (std::vector<double>{1, 0, 0, 1, 5.5, -6, 20, 40, 60, 3, 10}));
  // An unterminated <defs> hides the rest.
  EXPECT_EQ(svg_numbers(R"(<svg width="3"><defs><path d="M 1 2"/>)"), (std::vector<double>{3}));
}

// Two of six numbers differ beyond 1e-3: 0.01 and, the worst, 5 at index 5.
TEST(SvgCompare, CountsTheDifferencesAndNamesTheWorst) {
  const std::string golden = R"(<svg><path d="M 0 0 L 10 10 L 20 20"/></svg>)";
  const std::string actual = R"(<svg><path d="M 0 0.01 L 10 10 L 20 25"/></svg>)";
  const SvgComparison c = compare_svg(golden, actual, 1e-3);
  EXPECT_FALSE(c.matches);
  EXPECT_EQ(c.expected_count, 6u);
  EXPECT_EQ(c.actual_count, 6u);
  EXPECT_EQ(c.differing, 2u);
  EXPECT_EQ(c.worst, 5u);
  EXPECT_EQ(c.expected, 20.0);
  EXPECT_EQ(c.actual, 25.0);
  EXPECT_EQ(describe(c, 1e-3),
            "2 of 6 SVG numbers differ by more than 0.001 px; the worst, number 5, is 25 instead of 20");
  // With a tolerance of 10 pixels they match, and the worst is still known.
  const SvgComparison loose = compare_svg(golden, actual, 10.0);
  EXPECT_TRUE(loose.matches);
  EXPECT_EQ(loose.differing, 0u);
  EXPECT_EQ(loose.worst, 5u);
}

// "nan" is not read as a number: the count differs, and the message says so.
TEST(SvgCompare, ValuesThatAreNotNumbersAreNotRead) {
  const SvgComparison c = compare_svg(R"(<svg width="1"/>)", R"(<svg width="nan"/>)", 1e-3);
  EXPECT_FALSE(c.matches);
  EXPECT_EQ(c.actual_count, 0u);
  EXPECT_EQ(describe(c, 1e-3), "the SVG draws 0 numbers where the golden has 1 (its paths changed)");
  EXPECT_TRUE(compare_svg("<svg/>", "<svg/>", 0.0).matches);
}

}  // namespace
}  // namespace pita::golden
