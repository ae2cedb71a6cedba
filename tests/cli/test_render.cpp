// `pita render` through the real binary: files written (and only when the
// scene is good), formats, sizes, determinism, and the SVG read back by an
// XML parser (xmllint) and by a second renderer (librsvg's rsvg-convert).
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/stat.h>

#include "run_pita.hpp"
#include "support/sanitizers.hpp"

namespace pita::test {
namespace {

namespace fs = std::filesystem;

const std::string& kGoodScene = kFigureOneScene;

const std::string kBadScene = R"({"method": "P6", "keyframes": [
  {"t": 0, "p": [0, 0], "m": 1, "w": 0.4},
  {"t": 0.5, "p": [3, 1.5], "m": -0.6, "w": 2.0},
  {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}]})";

std::uint32_t png_dimension(const std::string& png, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t k = 0; k < 4; ++k) v = (v << 8) | static_cast<unsigned char>(png.at(at + k));
  return v;
}

int shell(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(Render, WritesEveryRequestedFormat) {
  const ScratchDir dir;
  dir.write("good.json", kGoodScene);
  const RunResult r = run_pita({"render", "good.json", "-o", "out", "--format", "svg,png,pdf"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* name : {"good.svg", "good.png", "good.pdf"}) {
    EXPECT_TRUE(fs::exists(dir.path() / "out" / name)) << name;
  }
  const std::string png = read_file(dir.path() / "out/good.png");
  EXPECT_EQ(png_dimension(png, 16), 800u);  // the default canvas
  EXPECT_EQ(png_dimension(png, 20), 600u);
  EXPECT_EQ(read_file(dir.path() / "out/good.pdf").substr(0, 5), "%PDF-");
  // No temporary file is left behind.
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir.path() / "out")) ++files;
  EXPECT_EQ(files, 3);
}

TEST(Render, SvgIsReadByAnXmlParserAndBySecondRenderer) {
  const ScratchDir dir;
  dir.write("good.json", kGoodScene);
  ASSERT_EQ(run_pita({"render", "good.json", "-o", "good.svg"}, dir.path()).exit_code, 0);
  const std::string svg = (dir.path() / "good.svg").string();
  EXPECT_EQ(shell("xmllint --noout '" + svg + "'"), 0);
  const std::string png = (dir.path() / "rsvg.png").string();
  ASSERT_EQ(shell("rsvg-convert '" + svg + "' -o '" + png + "'"), 0);
  const std::string bytes = read_file(png);
  EXPECT_EQ(png_dimension(bytes, 16), 800u);
  EXPECT_EQ(png_dimension(bytes, 20), 600u);
}

TEST(Render, PngScaleAndDpi) {
  const ScratchDir dir;
  dir.write("good.json", kGoodScene);
  ASSERT_EQ(run_pita({"render", "good.json", "-o", "a.png", "--scale", "1.5"}, dir.path()).exit_code, 0);
  EXPECT_EQ(png_dimension(read_file(dir.path() / "a.png"), 16), 1200u);
  ASSERT_EQ(run_pita({"render", "good.json", "-o", "b.png", "--dpi", "192"}, dir.path()).exit_code, 0);
  EXPECT_EQ(png_dimension(read_file(dir.path() / "b.png"), 20), 1200u);
  const RunResult too_big = run_pita({"render", "good.json", "-o", "c.png", "--scale", "100"}, dir.path());
  EXPECT_EQ(too_big.exit_code, 2);
  EXPECT_NE(too_big.err.find("--scale"), std::string::npos) << too_big.err;
  EXPECT_FALSE(fs::exists(dir.path() / "c.png"));
}

TEST(Render, SameSceneGivesIdenticalBytes) {
  const ScratchDir dir;
  dir.write("good.json", kGoodScene);
  dir.write("other.json", kGoodScene);
  ASSERT_EQ(run_pita({"render", "good.json", "-o", "one", "--format", "svg,png,pdf"}, dir.path()).exit_code, 0);
  // Rendered second in a process that has rendered another scene first.
  ASSERT_EQ(
      run_pita({"render", "other.json", "good.json", "-o", "two", "--format", "svg,png,pdf"}, dir.path()).exit_code, 0);
  for (const char* name : {"good.svg", "good.png", "good.pdf"}) {
    EXPECT_TRUE(read_file(dir.path() / "one" / name) == read_file(dir.path() / "two" / name)) << name;
  }
}

TEST(Render, BadSceneWritesNothingAndNamesThePointer) {
  const ScratchDir dir;
  dir.write("good.json", kGoodScene);
  dir.write("bad.json", kBadScene);
  const RunResult r = run_pita({"render", "bad.json", "good.json", "-o", "out", "--format", "svg,png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad.json: /keyframes/1/m"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out/bad.svg"));
  EXPECT_FALSE(fs::exists(dir.path() / "out/bad.png"));
  // The good scene is still rendered.
  EXPECT_TRUE(fs::exists(dir.path() / "out/good.svg"));
  EXPECT_TRUE(fs::exists(dir.path() / "out/good.png"));
}

// Issue 60: an image that is a FIFO (no writer) is refused at once, naming
// the image's pointer and what it is, as a directory is
// (tests/data/bad/images-path-a-folder); pita never waits in open().
TEST(Render, AnImageThatIsAFifoIsRefusedAtOnce) {
  const ScratchDir dir;
  ASSERT_EQ(::mkfifo((dir.path() / "pipe.png").c_str(), 0600), 0);
  dir.write("s.json", R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
      {"t": 0.5, "p": [1, 1], "m": 1, "w": 0}, {"t": 1, "p": [2, 0], "m": 1, "w": 0}],
      "shapes": [{"image": "pipe.png", "box": [[0, 0], [1, 1]]}]})");
  for (const char* command : {"render", "animate"}) {
    const RunResult r = run_pita({command, "s.json", "-o", "out.svg"}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err,
              "pita: s.json: /shapes/0/image: image \"pipe.png\" cannot be read: it is a named pipe (FIFO), not a "
              "regular file\n")
        << command;
    EXPECT_FALSE(fs::exists(dir.path() / "out.svg"));
  }
}

TEST(Render, BadFigureFieldsWriteNothing) {
  const ScratchDir dir;
  const std::string keyframes = R"("keyframes": [
    {"t": 0, "p": [0, 0], "m": 1, "w": 0.4}, {"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": 2.0},
    {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}])";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"("canvas": {"width": 99999})", "/canvas/width"},
      {R"("layers": [{"type": "patern"}])", "/layers/0/type"},
      {R"("layers": [{"type": "banner"}])", "/layers/0/text"},
      {R"("layers": [{"type": "pattern", "color": "#12"}])", "/layers/0/color"},
      {R"("chain": "blend", "panels": ["P7", "SMA"])", "/panels/1"},
      {R"("layers": [{"type": "stroke", "samples": 1}])", "/layers/0/samples"},
  };
  for (const auto& [field, pointer] : cases) {
    dir.write("bad.json", R"({"method": "P6", )" + keyframes + ", " + field + "}");
    const RunResult r = run_pita({"render", "bad.json", "-o", "out", "--format", "svg,png,pdf"}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << field;
    EXPECT_NE(r.err.find("bad.json: " + pointer), std::string::npos) << field << ": " << r.err;
    EXPECT_TRUE(!fs::exists(dir.path() / "out") || fs::is_empty(dir.path() / "out")) << field;
  }
}

TEST(Render, ListPrintsEveryScenesTitleAndDescription) {
  const ScratchDir dir;
  const fs::path scenes = fs::path(PITA_SOURCE_DIR) / "scenes";
  const RunResult r = run_pita({"render", "--list", scenes.string()}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::size_t count = 0;
  for (const auto& entry : fs::directory_iterator(scenes)) {
    if (entry.path().extension() != ".json") continue;
    ++count;
    const nlohmann::json scene = nlohmann::json::parse(read_file(entry.path()));
    const std::string name = entry.path().stem().string() + "\n";
    const std::size_t at = r.out.find(name);
    ASSERT_NE(at, std::string::npos) << name;
    if (scene.contains("description")) {
      EXPECT_NE(r.out.find("    " + scene["description"].get<std::string>() + "\n", at), std::string::npos) << name;
    }
  }
  EXPECT_GE(count, 30u);
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
  // Without --list, SCENE and -o are required as before.
  const RunResult bare = run_pita({"render"}, dir.path());
  EXPECT_EQ(bare.exit_code, 2);
  EXPECT_EQ(bare.err.rfind("pita: SCENE is required\n", 0), 0u) << bare.err;
  const RunResult no_output = run_pita({"render", "x.json"}, dir.path());
  EXPECT_EQ(no_output.exit_code, 2);
  EXPECT_NE(no_output.err.find("--output is required"), std::string::npos) << no_output.err;
  // An empty folder has nothing to list.
  fs::create_directory(dir.path() / "empty");
  EXPECT_EQ(run_pita({"render", "--list", "empty"}, dir.path()).exit_code, 2);
}

TEST(Render, EveryStarterSceneRenders) {
  const ScratchDir dir;
  std::vector<std::string> args{"render"};
  std::vector<fs::path> all;
  for (const auto& entry : fs::directory_iterator(fs::path(PITA_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() == ".json") all.push_back(entry.path());
  }
  std::sort(all.begin(), all.end());
  // Under the sanitizers a quarter of them (each golden test draws every one there).
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (in_sample(i, 4)) args.push_back(all[i].string());
  }
  ASSERT_GE(args.size(), kUnderSanitizers ? 10u : 40u);
  const std::size_t scenes = args.size() - 1;
  args.insert(args.end(), {"-o", "out", "--format", "svg,png"});
  const RunResult r = run_pita(args, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir.path() / "out")) {
    EXPECT_GT(fs::file_size(entry.path()), 1000u) << entry.path();
    ++files;
  }
  EXPECT_EQ(files, 2 * scenes);
}

// Issue 38: several scenes are rendered on several threads (--jobs) into the
// same bytes, with the lines printed in the order of the scenes.
TEST(Render, JobsGiveTheSameFilesAndLinesInOrder) {
  const ScratchDir dir;
  std::vector<std::string> args{"render"};
  for (const std::string name :
       {"fig01-eight-pitas", "fig13-knot-ratio", "sam-fig01-regular-patterns", "fig07-independent-pitas"}) {
    args.push_back((fs::path(PITA_SOURCE_DIR) / "scenes" / (name + ".json")).string());
  }
  dir.write("bad.json", kBadScene);
  args.insert(args.begin() + 3, "bad.json");
  const auto run_with = [&](const std::string& jobs, const std::string& out) {
    std::vector<std::string> with = args;
    with.insert(with.end(), {"-o", out, "--format", "svg,png", "--jobs", jobs});
    return run_pita(with, dir.path());
  };
  const RunResult serial = run_with("1", "one");
  const RunResult parallel = run_with("2", "two");
  EXPECT_EQ(serial.exit_code, 2);
  EXPECT_EQ(parallel.exit_code, 2);
  EXPECT_EQ(parallel.err, serial.err);
  std::string expected = serial.out;
  for (std::size_t at = expected.find("one/"); at != std::string::npos; at = expected.find("one/", at)) {
    expected.replace(at, 4, "two/");
  }
  EXPECT_EQ(parallel.out, expected);
  EXPECT_EQ(lines_of(parallel.out).size(), 8u) << parallel.out;
  for (const auto& entry : fs::directory_iterator(dir.path() / "one")) {
    EXPECT_EQ(read_file(dir.path() / "two" / entry.path().filename()), read_file(entry.path())) << entry.path();
  }
}

TEST(Render, UsageErrorsExitTwo) {
  const ScratchDir dir;
  dir.write("good.json", kGoodScene);
  const std::vector<std::vector<std::string>> cases = {
      {"render", "good.json", "good.json", "-o", "one.svg"},  // one file, two scenes
      {"render", "good.json", "-o", "x", "--format", "gif"},
      {"render", "good.json", "-o", "x.png", "--format", "svg"},
      {"render", "good.json"},  // no -o
      {"render", "good.json", "-o", "x.png", "--scale", "1", "--dpi", "96"},
      {"render", "missing.json", "-o", "x.svg"},
  };
  for (const auto& args : cases) {
    const RunResult r = run_pita(args, dir.path());
    EXPECT_EQ(r.exit_code, 2) << args.back() << ": " << r.err;
    EXPECT_FALSE(r.err.empty());
  }
}

}  // namespace
}  // namespace pita::test
