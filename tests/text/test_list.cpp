// The one splitter of lists (src/text/list.hpp): every item between the
// separators, empty ones included, untrimmed, in order.
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "text/list.hpp"

namespace pita::text {
namespace {

std::vector<std::string> items(std::string_view text, char separator = ',') {
  std::vector<std::string> out;
  for_each_item(
      text, [&](std::string_view item) { out.emplace_back(item); }, separator);
  return out;
}

TEST(ForEachItem, GivesTheItemsBetweenSeparators) {
  EXPECT_EQ(items("svg,png,pdf"), (std::vector<std::string>{"svg", "png", "pdf"}));
  EXPECT_EQ(items("svg"), (std::vector<std::string>{"svg"}));
  EXPECT_EQ(items(" P1 , P6"), (std::vector<std::string>{" P1 ", " P6"}));
  EXPECT_EQ(items("0/4", '/'), (std::vector<std::string>{"0", "4"}));
}

TEST(ForEachItem, GivesEmptyItemsToo) {
  EXPECT_EQ(items(""), (std::vector<std::string>{""}));
  EXPECT_EQ(items(","), (std::vector<std::string>{"", ""}));
  EXPECT_EQ(items("a,,b,"), (std::vector<std::string>{"a", "", "b", ""}));
}

TEST(ForEachItem, StopsWhenTheVisitorThrows) {
  int seen = 0;
  EXPECT_THROW(for_each_item("1,2,3,4",
                             [&](std::string_view) {
                               if (++seen == 2) throw std::length_error("at most 1");
                             }),
               std::length_error);
  EXPECT_EQ(seen, 2);
}

}  // namespace
}  // namespace pita::text
