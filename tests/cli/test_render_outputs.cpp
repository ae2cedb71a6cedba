// Where `pita render` writes, through the real binary: two scenes that would
// write one file are refused before anything is written, a scene's formats are
// written all or none, and no scene name can put a file outside the output
// directory (docs/reference/render.md "Figures: pita render").
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "run_pita.hpp"

namespace pita::test {
namespace {

namespace fs = std::filesystem;

const std::string& kScene = kFigureOneScene;

// Every file and symlink under `root`, relative to it, symlinks not followed.
std::set<std::string> entries_under(const fs::path& root) {
  std::set<std::string> found;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (!entry.is_directory() || entry.is_symlink()) found.insert(entry.path().lexically_relative(root).string());
  }
  return found;
}

bool is_whole_svg(const std::string& text) {
  return text.rfind("<?xml", 0) == 0 && text.find("</svg>") != std::string::npos &&
         text.find_last_not_of("\n") == text.rfind("</svg>") + 5;
}

// --- Two scenes, one name -------------------------------------------------

TEST(RenderOutputs, TwoScenesOfOneNameAreRefusedBeforeAnythingIsWritten) {
  const ScratchDir dir;
  fs::create_directories(dir.path() / "a");
  fs::create_directories(dir.path() / "b");
  dir.write("a/x.json", kScene);
  dir.write("b/x.json", kScene);
  dir.write("good.json", kScene);
  const RunResult r =
      run_pita({"render", "good.json", "a/x.json", "b/x.json", "-o", "out", "--format", "svg,png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("pita: a/x.json and b/x.json would both write out/x.svg"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));  // not even the good scene, nor the directory
  EXPECT_TRUE(r.out.empty()) << r.out;
}

// A scene file without extension is named like its .json twin.
TEST(RenderOutputs, ASceneWithoutExtensionCollidesWithItsJsonTwin) {
  const ScratchDir dir;
  dir.write("x.json", kScene);
  dir.write("x", kScene);
  const RunResult r = run_pita({"render", "x.json", "x", "-o", "out"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("x.json and x would both write out/x.svg"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(RenderOutputs, OneSceneGivenTwiceIsRefused) {
  const ScratchDir dir;
  dir.write("x.json", kScene);
  const std::string absolute = (dir.path() / "x.json").string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"x.json", "x.json is given twice: it would write out/x.svg twice"},
      {"./x.json", "./x.json is given twice: it would write out/x.svg twice (also as x.json)"},
      {absolute, absolute + " is given twice: it would write out/x.svg twice (also as x.json)"},
  };
  for (const auto& [second, message] : cases) {
    const RunResult r = run_pita({"render", "x.json", second, "-o", "out"}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << second << ": " << r.err;
    EXPECT_NE(r.err.find("pita: " + message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir.path() / "out")) << second;
  }
}

// Distinct names in one directory are fine, and a single output file takes one scene anyway.
TEST(RenderOutputs, DistinctNamesAreWritten) {
  const ScratchDir dir;
  fs::create_directories(dir.path() / "a");
  dir.write("a/x.json", kScene);
  dir.write("x.svg.json", kScene);
  dir.write("y.json", kScene);
  const RunResult r = run_pita({"render", "a/x.json", "x.svg.json", "y.json", "-o", "out"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(entries_under(dir.path() / "out"), (std::set<std::string>{"x.svg", "x.svg.svg", "y.svg"}));
}

// "-o four.jpg": an extension pita does not write is refused (exit 2, with
// what it writes), not made a directory; an existing directory of that name
// is still a directory, and a name without extension is one to create.
TEST(RenderOutputs, AnOutputWithAnExtensionPitaDoesNotWriteIsRefused) {
  const ScratchDir dir;
  dir.write("four.json", kScene);
  for (const char* wrong : {"four.jpg", "four.svgz", "out/four.gif"}) {
    const RunResult r = run_pita({"render", "four.json", "-o", wrong}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << wrong << ": " << r.err;
    EXPECT_NE(r.err.find("pita render writes .svg, .png or .pdf files"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir.path() / wrong)) << wrong;
    EXPECT_TRUE(r.out.empty());
  }
  fs::create_directories(dir.path() / "figures.v2");
  ASSERT_EQ(run_pita({"render", "four.json", "-o", "figures.v2"}, dir.path()).exit_code, 0);
  EXPECT_TRUE(fs::exists(dir.path() / "figures.v2" / "four.svg"));
  ASSERT_EQ(run_pita({"render", "four.json", "-o", "figures"}, dir.path()).exit_code, 0);
  EXPECT_TRUE(fs::exists(dir.path() / "figures" / "four.svg"));
}

// --method M draws the scene as the file with "method": M would be drawn: its
// own motion, the panels without a method of their own, a title's {/method}.
TEST(RenderOutputs, MethodDrawsTheSceneAsIfItsMethodWereM) {
  const ScratchDir dir;
  const std::string fields = kFigureOneFields.substr(kFigureOneFields.find(", \"keyframes\""));
  const auto scene = [&](const std::string& method, const std::string& panels) {
    return "{\"title\": \"by {/method}\", \"method\": \"" + method + "\"" + fields + panels + "}";
  };
  const std::string panels = R"(, "panels": ["P8", {"title": "the scene's"}])";
  dir.write("p6.json", scene("P6", panels));
  dir.write("p2.json", scene("P2", panels));
  ASSERT_EQ(run_pita({"render", "p6.json", "--method", "P2", "-o", "override.svg"}, dir.path()).exit_code, 0);
  ASSERT_EQ(run_pita({"render", "p2.json", "-o", "by-hand.svg"}, dir.path()).exit_code, 0);
  ASSERT_EQ(run_pita({"render", "p6.json", "-o", "own.svg"}, dir.path()).exit_code, 0);
  EXPECT_EQ(read_file(dir.path() / "override.svg"), read_file(dir.path() / "by-hand.svg"));
  EXPECT_NE(read_file(dir.path() / "override.svg"), read_file(dir.path() / "own.svg"));
  // Refused: an unknown name, and a scene whose panels all draw their own method.
  const RunResult unknown = run_pita({"render", "p6.json", "--method", "P66", "-o", "x.svg"}, dir.path());
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("--method: unknown method \"P66\""), std::string::npos) << unknown.err;
  dir.write("own.json", scene("P6", R"(, "panels": ["P8", {"method": "P1"}])"));
  const RunResult none = run_pita({"render", "own.json", "--method", "P2", "-o", "x.svg"}, dir.path());
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("own.json: /method: P2, given in place of the scene's method, would be drawn by no panel: "
                          "each sets its own (/panels/0, /panels/1/method)"),
            std::string::npos)
      << none.err;
  EXPECT_FALSE(fs::exists(dir.path() / "x.svg"));
}

// An output never replaces an input of the same run: the image a scene's
// shapes draw, by its own name or through a link.
TEST(RenderOutputs, AnOutputThatIsAnInputIsRefused) {
  const ScratchDir dir;
  const fs::path scenes = fs::path(PITA_SOURCE_DIR) / "scenes";
  fs::copy(scenes / "fig23-image-motion.json", dir.path() / "fig23.json");
  fs::create_directories(dir.path() / "images");
  fs::copy(scenes / "images" / "picture.png", dir.path() / "images" / "picture.png");
  fs::create_symlink("images/picture.png", dir.path() / "alias.png");
  const std::string picture = read_file(dir.path() / "images" / "picture.png");
  for (const std::string out : {"images/picture.png", "alias.png"}) {
    const RunResult r = run_pita({"render", "fig23.json", "-o", out}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << out << ": " << r.err;
    EXPECT_NE(r.err.find("fig23.json: the output " + out + " is an image its shapes draw, which it would replace"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(read_file(dir.path() / "images" / "picture.png"), picture);
  }
  EXPECT_EQ(run_pita({"render", "fig23.json", "-o", "fig23.png"}, dir.path()).exit_code, 0);
}

// --- A scene's formats: all or none ---------------------------------------

// A directory in the way of x.png: the scene fails with exit 3, its SVG is
// not written either (an older x.svg stays as it was), no temporary remains,
// and the other scene of the run is still written.
TEST(RenderOutputs, AFormatThatCannotBeWrittenTakesTheOthersAlong) {
  const ScratchDir dir;
  dir.write("x.json", kScene);
  dir.write("good.json", kScene);
  fs::create_directories(dir.path() / "out" / "x.png" / "inside");
  dir.write("out/x.svg", "older");
  const RunResult r = run_pita({"render", "x.json", "good.json", "-o", "out", "--format", "svg,png"}, dir.path());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("pita: out/x.png: cannot rename the finished file into place (Is a directory)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(read_file(dir.path() / "out/x.svg"), "older");
  EXPECT_TRUE(is_whole_svg(read_file(dir.path() / "out/good.svg")));
  EXPECT_TRUE(fs::exists(dir.path() / "out/good.png"));
  EXPECT_TRUE(hidden_in(dir.path() / "out").empty());
  EXPECT_EQ(r.out.find("wrote out/x."), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("wrote out/good.png"), std::string::npos) << r.out;
}

// A rename failing during the commit (the shim fails the one onto x.png, after
// x.svg is in place): x.svg is removed again, so that no partial set remains.
TEST(RenderOutputs, ARenameFailingDuringTheCommitRemovesTheRenamedFiles) {
  const ScratchDir dir;
  dir.write("x.json", kScene);
  dir.write("good.json", kScene);
  Started started = start_pita({"render", "x.json", "good.json", "-o", "out", "--format", "svg,png"}, dir.path(),
                               with_rename_hook({"PITA_TEST_FAIL_RENAME_TO=x.png"}));
  const RunResult r = finish_pita(started);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("pita: out/x.png: cannot rename the finished file into place (Input/output error); "
                       "removed out/x.svg, written with it"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(entries_under(dir.path() / "out"), (std::set<std::string>{"good.png", "good.svg"}));
}

// --- Output names never leave the output directory -------------------------

// The name is the scene file's stem: its last path component less the
// extension. Dots, dashes, spaces, backslashes, Unicode, ../ and absolute
// paths all end up as one file name inside OUT.
TEST(RenderOutputs, NoSceneNameLeavesTheOutputDirectory) {
  const ScratchDir root;
  fs::create_directories(root.path() / "work");
  fs::create_directories(root.path() / "elsewhere");
  root.write("up.json", kScene);
  root.write("elsewhere/absolute.json", kScene);
  const std::vector<std::string> names = {"..json",          ".json",          "...json",          "-dash.json",
                                          "with space.json", "ünïcødé ☃.json", "back\\slash.json", "x.svg.json"};
  for (const std::string& name : names) root.write("work/" + name, kScene);
  const std::set<std::string> before = entries_under(root.path());

  // After "--" a name starting with "-" is a scene (so is ./-dash.json anywhere).
  std::vector<std::string> args = {"render",  "-o", "out",        "--format",
                                   "svg,png", "--", "../up.json", (root.path() / "elsewhere/absolute.json").string()};
  args.insert(args.end(), names.begin(), names.end());
  const RunResult r = run_pita(args, root.path() / "work");
  ASSERT_EQ(r.exit_code, 0) << r.err;

  std::set<std::string> created;
  for (const std::string& entry : entries_under(root.path())) {
    if (!before.count(entry)) created.insert(entry);
  }
  std::set<std::string> expected;
  for (const std::string stem :
       {"up", "absolute", ".", ".json", "..", "-dash", "with space", "ünïcødé ☃", "back\\slash", "x.svg"}) {
    expected.insert("work/out/" + stem + ".svg");
    expected.insert("work/out/" + stem + ".png");
  }
  EXPECT_EQ(created, expected);
  EXPECT_TRUE(is_whole_svg(read_file(root.path() / "work/out/..svg")));
}

// A symlinked output directory is followed: the files, and their temporaries
// (in the same directory, so that the rename stays atomic), land in its target.
TEST(RenderOutputs, ASymlinkedOutputDirectoryIsFollowed) {
  const ScratchDir root;
  fs::create_directories(root.path() / "real");
  fs::create_directory_symlink("real", root.path() / "out");
  root.write("x.json", kScene);
  for (const std::string output : {"out", "out/"}) {
    const RunResult r = run_pita({"render", "x.json", "-o", output, "--format", "svg,png"}, root.path());
    ASSERT_EQ(r.exit_code, 0) << output << ": " << r.err;
    EXPECT_EQ(entries_under(root.path()), (std::set<std::string>{"out", "real/x.png", "real/x.svg", "x.json"}))
        << output;
    EXPECT_TRUE(fs::is_symlink(root.path() / "out"));
  }
}

// A dangling symlink is not a directory: refused (exit 3), its target not created.
TEST(RenderOutputs, ADanglingSymlinkOutputDirectoryIsRefused) {
  const ScratchDir root;
  fs::create_symlink("missing", root.path() / "out");
  root.write("x.json", kScene);
  const RunResult r = run_pita({"render", "x.json", "-o", "out"}, root.path());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("pita: -o out: cannot create the output directory"), std::string::npos) << r.err;
  EXPECT_EQ(entries_under(root.path()), (std::set<std::string>{"out", "x.json"}));
}

// A symlink where an output goes is replaced by the file (rename does not
// follow it): nothing is written through it to the file it pointed to.
TEST(RenderOutputs, ASymlinkInPlaceOfAnOutputIsReplacedNotWrittenThrough) {
  const ScratchDir root;
  fs::create_directories(root.path() / "out");
  root.write("victim.svg", "keep");
  fs::create_symlink("../victim.svg", root.path() / "out/x.svg");
  root.write("x.json", kScene);
  const RunResult r = run_pita({"render", "x.json", "-o", "out"}, root.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_file(root.path() / "victim.svg"), "keep");
  EXPECT_FALSE(fs::is_symlink(root.path() / "out/x.svg"));
  EXPECT_TRUE(is_whole_svg(read_file(root.path() / "out/x.svg")));
}

}  // namespace
}  // namespace pita::test
