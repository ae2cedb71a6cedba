// The script of index.html built into pita (src/sweep/index_script.hpp): the
// file src/sweep/index_page.js as it is, with nothing in it that would end or
// bend the <script> element holding it.
#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "sweep/index_script.hpp"

namespace pita::sweep {
namespace {

TEST(IndexScript, IsTheFileOfTheSourceTree) {
  std::ifstream in(std::string(PITA_SOURCE_DIR) + "/src/sweep/index_page.js", std::ios::binary);
  ASSERT_TRUE(in) << "src/sweep/index_page.js";
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(index_script(), text.str());
  EXPECT_TRUE(index_script().starts_with("\"use strict\";\n"));
  EXPECT_TRUE(index_script().ends_with("\n"));
}

TEST(IndexScript, HoldsNothingThatEndsItsScriptElement) {
  std::string lower(index_script());
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  EXPECT_EQ(lower.find("</script"), std::string::npos);
  EXPECT_EQ(lower.find("<!--"), std::string::npos);
}

}  // namespace
}  // namespace pita::sweep
