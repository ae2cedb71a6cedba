// pita serve's tokens (src/serve/token.cpp): random ones of 128 bits, given
// ones checked, and kept ones private to the user and stable per folder.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "serve/token.hpp"
#include "support/scratch_dir.hpp"

namespace pita::serve {
namespace {

namespace fs = std::filesystem;

TEST(Token, RandomTokensAre32HexDigitsAndDiffer) {
  std::set<std::string> seen;
  for (int i = 0; i < 20; ++i) {
    const std::string token = random_token();
    EXPECT_EQ(token.size(), 32U);
    EXPECT_EQ(token.find_first_not_of("0123456789abcdef"), std::string::npos) << token;
    EXPECT_FALSE(token_problem(token)) << token;
    seen.insert(token);
  }
  EXPECT_EQ(seen.size(), 20U);
}

TEST(Token, AGivenTokenMustStandInAnAddress) {
  EXPECT_FALSE(token_problem("abcdefghijklmnop"));
  EXPECT_FALSE(token_problem("A-b_c-0123456789"));
  EXPECT_NE(token_problem("short").value_or("").find("16 to 128 characters (got 5)"), std::string::npos);
  EXPECT_TRUE(token_problem(std::string(129, 'a')));
  EXPECT_TRUE(token_problem("abcdefghijklmnop&x=1"));
  EXPECT_TRUE(token_problem("abcdefghijklmnop op"));
}

int mode_of(const fs::path& path) {
  struct stat st {};
  ::lstat(path.c_str(), &st);
  return static_cast<int>(st.st_mode & 0777);
}

TEST(Token, AKeptTokenIsTheSameForAFolderAndPrivate) {
  const test::ScratchDir state;
  const char* before = std::getenv("XDG_STATE_HOME");
  const std::string saved = before != nullptr ? before : "";
  ::setenv("XDG_STATE_HOME", state.path().c_str(), 1);
  const test::ScratchDir a, b;
  const std::string first = kept_token(a.path(), false);
  EXPECT_EQ(kept_token(a.path(), false), first);
  EXPECT_EQ(kept_token(a.path() / "." / "", false), first);  // the same folder, spelt otherwise
  EXPECT_NE(kept_token(b.path(), false), first);
  const fs::path folder = state.path() / "pita" / "serve-tokens";
  EXPECT_EQ(mode_of(folder), 0700);
  for (const auto& file : fs::directory_iterator(folder)) EXPECT_EQ(mode_of(file.path()), 0600) << file.path();
  // --new-token: another, kept from then on.
  const std::string renewed = kept_token(a.path(), true);
  EXPECT_NE(renewed, first);
  EXPECT_EQ(kept_token(a.path(), false), renewed);
  // A kept file that others may read is not trusted: a new token replaces it.
  for (const auto& file : fs::directory_iterator(folder))
    fs::permissions(file.path(), fs::perms::others_read, fs::perm_options::add);
  const std::string after_exposure = kept_token(a.path(), false);
  EXPECT_NE(after_exposure, renewed);
  if (before != nullptr) {
    ::setenv("XDG_STATE_HOME", saved.c_str(), 1);
  } else {
    ::unsetenv("XDG_STATE_HOME");
  }
}

}  // namespace
}  // namespace pita::serve
