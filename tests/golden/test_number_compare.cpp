// Golden numbers (src/golden/number_compare.cpp): what must match, what must
// not, and what the messages name.
#include <gtest/gtest.h>

#include "golden/number_compare.hpp"
#include "golden_support.hpp"

namespace pita::golden {
namespace {

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

}  // namespace
}  // namespace pita::golden
