// The pita command itself (src/cli/main.cpp): help, version, and usage errors
// mapped to exit code 2 (CLI11's own codes would be 100 and above).
#include <string>

#include <gtest/gtest.h>

#include "run_pita.hpp"

namespace pita::test {
namespace {

class Main : public ::testing::Test {
 protected:
  RunResult run(const std::vector<std::string>& args) const { return run_pita(args, dir.path()); }
  ScratchDir dir;
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST_F(Main, HelpExitsZero) {
  const RunResult result = run({"--help"});
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_EQ(result.err, "");
  EXPECT_TRUE(contains(result.out, "Usage: pita [OPTIONS]")) << result.out;
  EXPECT_TRUE(contains(result.out, "eval")) << result.out;
  EXPECT_TRUE(contains(result.out, "pita eval scenes/fig01-eight-pitas.json")) << result.out;
}

TEST_F(Main, EvalHelpDescribesTheSceneFormat) {
  const RunResult result = run({"eval", "--help"});
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_EQ(result.err, "");
  for (const std::string part :
       {"Usage: pita eval [OPTIONS] [SCENE]", "--samples", "--batch FILE", "--t", "--method", "--format",
        "Scene format", "\"keyframes\"", "turns", "P6    La-LP", "SMA   SMA", "Examples:", "Exit codes"}) {
    EXPECT_TRUE(contains(result.out, part)) << "no \"" << part << "\" in\n" << result.out;
  }
}

TEST_F(Main, TheHelpExampleSceneIsValid) {
  // The scene printed by 'pita eval --help', between its braces.
  const std::string help = run({"eval", "--help"}).out;
  const std::size_t start = help.find("  {\n");
  const std::size_t end = help.find("\n  }\n", start);
  ASSERT_NE(start, std::string::npos);
  ASSERT_NE(end, std::string::npos);
  dir.write("example.json", help.substr(start, end + 4 - start));
  const RunResult result = run({"eval", "example.json"});
  EXPECT_EQ(result.exit_code, 0) << result.err;
}

TEST_F(Main, Version) {
  const RunResult result = run({"--version"});
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_EQ(result.out.rfind("pita ", 0), 0u) << result.out;
  EXPECT_EQ(result.err, "");
}

// Issue 38: pango (and GLib with it) is loaded with dlopen when the first
// text is laid out (src/render/pango_library.hpp), not when pita starts. The
// dynamic loader's own log (LD_DEBUG=files) says which libraries a process
// loaded and how.
TEST_F(Main, PangoIsLoadedOnlyForText) {
  const std::vector<std::string> log_loads = {"LD_DEBUG=files"};
  const auto loads_pango = [&](const std::vector<std::string>& args) {
    Started started = start_pita(args, dir.path(), log_loads);
    const RunResult result = finish_pita(started);
    EXPECT_EQ(result.exit_code, 0) << result.err.substr(result.err.size() > 2000 ? result.err.size() - 2000 : 0);
    EXPECT_TRUE(contains(result.err, "libcairo.so.2")) << "LD_DEBUG logged nothing";
    return contains(result.err, "libpango");
  };
  dir.write("plain.json", kFigureOneScene);
  dir.write("titled.json", R"({"title": "Fig. 1", )" + kFigureOneFields + "}");
  EXPECT_FALSE(loads_pango({"--version"}));
  EXPECT_FALSE(loads_pango({"eval", "plain.json"}));
  Started titled = start_pita({"render", "titled.json", "-o", "titled.svg"}, dir.path(), log_loads);
  const RunResult result = finish_pita(titled);
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_TRUE(contains(result.err, "file=libpangocairo-1.0.so.0 [0];  dynamically loaded by")) << result.err;
}

TEST_F(Main, UnknownOptionExitsTwo) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"--frobnicate"}, std::vector<std::string>{"eval", "x.json", "--frobnicate"}}) {
    const RunResult result = run(args);
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_EQ(result.out, "");
    EXPECT_EQ(result.err.rfind("pita: ", 0), 0u) << result.err;
    EXPECT_TRUE(contains(result.err, "--frobnicate")) << result.err;
  }
}

TEST_F(Main, NoSubcommandExitsTwo) {
  const RunResult result = run({});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err,
            "pita: missing subcommand, for example: pita eval scenes/fig01-eight-pitas.json\n"
            "Run 'pita --help' for usage.\n");
}

TEST_F(Main, UnknownSubcommandSuggests) {
  const RunResult result = run({"evl", "scene.json"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err, "pita: unknown subcommand \"evl\"; did you mean \"eval\"?\nRun 'pita --help' for usage.\n");
  const RunResult far = run({"frobnicate"});
  EXPECT_EQ(far.exit_code, 2);
  EXPECT_EQ(far.err, "pita: unknown subcommand \"frobnicate\"\nRun 'pita --help' for usage.\n");
}

}  // namespace
}  // namespace pita::test
