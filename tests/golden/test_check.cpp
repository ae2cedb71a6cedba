// Goldens of a scene and their comparison with a fresh rendering
// (src/golden/check.cpp): where the files live, what a missing, identical,
// tolerably or really different file gives, and a whole scene checked
// against goldens written in a scratch directory.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "golden/check.hpp"

namespace pita::golden {
namespace {

namespace fs = std::filesystem;

class GoldenCheck : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pita-test-golden-check-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const fs::path& relative, const std::string& bytes) const {
    const fs::path path = dir_ / relative;
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }

  // A P6 scene whose middle keyframe has x = `middle_x`.
  static std::string scene(const std::string& middle_x) {
    return R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0.4},
      {"t": 0.5, "p": [)" +
           middle_x + R"(, 1.5], "m": 0.6, "w": 2.0}, {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}]})";
  }

  fs::path dir_;
};

TEST(GoldenFiles, PathsMirrorTheScenes) {
  EXPECT_EQ(suffix(FileKind::data), ".data.json");
  EXPECT_EQ(suffix(FileKind::svg), ".svg");
  EXPECT_EQ(suffix(FileKind::png), ".png");
  EXPECT_EQ(golden_path("golden", "fig01-eight", FileKind::svg), fs::path("golden/fig01-eight/fig01-eight.svg"));
  EXPECT_EQ(golden_path("g", "x", FileKind::data), fs::path("g/x/x.data.json"));
  EXPECT_EQ(scene_name("scenes/fig01-eight.json"), "fig01-eight");
  EXPECT_EQ(scene_name("a.b.json"), "a.b");
}

TEST(GoldenFiles, SceneMatchesOnlyWhenEveryFileMatches) {
  SceneCheck check{"s.json", "s", {}, {}, {}};
  EXPECT_TRUE(check.matches());
  check.files.push_back(FileCheck{FileKind::data, "g", Verdict::match, "", "", "", ""});
  EXPECT_TRUE(check.matches());
  check.files.push_back(FileCheck{FileKind::png, "g", Verdict::missing, "", "", "", ""});
  EXPECT_FALSE(check.matches());
  check.files.back().verdict = Verdict::differs;
  EXPECT_FALSE(check.matches());
}

TEST_F(GoldenCheck, MissingGoldenIsMissingAndKeepsTheFreshBytes) {
  const FileCheck c = compare_file(FileKind::svg, dir_ / "none.svg", "<svg/>", Tolerances{});
  EXPECT_EQ(c.verdict, Verdict::missing);
  EXPECT_EQ(c.detail, "no golden file (create it with `pita update-goldens`)");
  EXPECT_EQ(c.expected, "");
  EXPECT_EQ(c.actual, "<svg/>");
}

TEST_F(GoldenCheck, IdenticalBytesMatchWithoutBeingParsed) {
  const fs::path golden = write("g.data.json", "not even JSON");
  const FileCheck c = compare_file(FileKind::data, golden, "not even JSON", Tolerances{});
  EXPECT_EQ(c.verdict, Verdict::match);
  EXPECT_EQ(c.detail, "identical");
  EXPECT_EQ(c.expected, "not even JSON");
}

TEST_F(GoldenCheck, SvgGeometryIsComparedWithinItsTolerance) {
  const fs::path golden = write("g.svg", R"(<svg><path d="M 0 0 L 1 1"/></svg>)");
  const FileCheck close =
      compare_file(FileKind::svg, golden, R"(<svg><path d="M 0 0 L 1 1.0001"/></svg>)", Tolerances{});
  EXPECT_EQ(close.verdict, Verdict::match);
  EXPECT_EQ(close.detail, "geometry within 0.001 px");
  const FileCheck moved = compare_file(FileKind::svg, golden, R"(<svg><path d="M 0 0 L 1 2"/></svg>)", Tolerances{});
  EXPECT_EQ(moved.verdict, Verdict::differs);
  EXPECT_EQ(moved.detail, "1 of 4 SVG numbers differ by more than 0.001 px; the worst, number 3, is 2 instead of 1");
  Tolerances loose;
  loose.svg = 2.0;
  EXPECT_EQ(compare_file(FileKind::svg, golden, R"(<svg><path d="M 0 0 L 1 2"/></svg>)", loose).verdict,
            Verdict::match);
}

TEST_F(GoldenCheck, UnreadableGoldensAreGoldenErrorsNamingTheFile) {
  const fs::path data = write("g.data.json", "{ not json");
  try {
    compare_file(FileKind::data, data, R"({"panels": []})", Tolerances{});
    FAIL() << "no error";
  } catch (const GoldenError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(data.string() + ":1:4: malformed JSON: ", 0), 0u) << error.what();
  }
  const fs::path png = write("g.png", "not a PNG");
  try {
    compare_file(FileKind::png, png, "also not a PNG", Tolerances{});
    FAIL() << "no error";
  } catch (const GoldenError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(png.string() + ": ", 0), 0u) << error.what();
  }
}

// Goldens written from one rendering match the next rendering of the same
// scene; moving a keyframe makes the numbers and the SVG differ; without
// goldens every file is missing.
TEST_F(GoldenCheck, SceneAgainstItsGoldens) {
  const fs::path scene_path = write("scenes/fig.json", scene("3"));
  const fs::path golden_dir = dir_ / "golden";
  const SceneCheck none = check_scene(scene_path, golden_dir, Tolerances{});
  EXPECT_EQ(none.name, "fig");
  EXPECT_EQ(none.scene_path, scene_path.string());
  ASSERT_EQ(none.files.size(), 3u);
  for (const FileCheck& f : none.files) EXPECT_EQ(f.verdict, Verdict::missing);
  EXPECT_FALSE(none.matches());

  const Outputs outputs = render_outputs(scene_path);
  EXPECT_EQ(outputs.png.substr(1, 3), "PNG");
  EXPECT_NE(outputs.svg.find("<svg"), std::string::npos);
  EXPECT_EQ(outputs.data.rfind("{\"scene\": \"fig\", \"panels\": [\n", 0), 0u);
  write("golden/fig/fig.data.json", outputs.data);
  write("golden/fig/fig.svg", outputs.svg);
  write("golden/fig/fig.png", outputs.png);
  const SceneCheck same = check_scene(scene_path, golden_dir, Tolerances{});
  EXPECT_TRUE(same.matches());
  ASSERT_EQ(same.files.size(), 3u);
  EXPECT_EQ(same.files[0].kind, FileKind::data);
  EXPECT_EQ(same.files[0].golden, golden_dir / "fig" / "fig.data.json");
  for (const FileCheck& f : same.files) EXPECT_EQ(f.detail, "identical");

  write("scenes/fig.json", scene("3.2"));
  const SceneCheck moved = check_scene(scene_path, golden_dir, Tolerances{});
  EXPECT_FALSE(moved.matches());
  EXPECT_EQ(moved.files[0].verdict, Verdict::differs);
  EXPECT_EQ(moved.files[1].verdict, Verdict::differs);
}

}  // namespace
}  // namespace pita::golden
