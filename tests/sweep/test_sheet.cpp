// The contact sheet (src/sweep/sheet.cpp): its whole drawing is estimated
// before any of it is drawn, and a sheet beyond kMaxContactUnits is left out
// with a note (issue 37: 32 heavy variants drew 1.6 GB of SVG in memory); a
// sweep larger than kMaxContactCells shows an evenly spaced sample.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "render/budget.hpp"
#include "scene/scene.hpp"
#include "sweep/sheet.hpp"

namespace pita::sweep {
namespace {

namespace fs = std::filesystem;

// A figure of many frames: cheap to estimate, dear to draw.
const std::string kHeavy = R"({"method": "P6", "keyframes": [
  {"t": 0, "p": [0, 0], "m": 1, "w": 0.4},
  {"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": 2.0},
  {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}],
  "layers": [{"type": "pattern", "samples": 4000}, {"type": "stroke", "samples": 4000}]})";

// DIR/manifest.csv of `variants` ok rows over /keyframes/1/t, each with its
// scene file <name>-<i>.scene.json holding `scene` when `with_scene(i)`, and
// the sheet's input for it.
template <typename WithScene>
SheetInput sweep_of(const fs::path& dir, const std::string& name, std::int64_t variants, const std::string& scene,
                    WithScene with_scene) {
  const std::vector<std::string> pointers = {"/keyframes/1/t"};
  std::string manifest = manifest_header(pointers);
  for (std::int64_t i = 0; i < variants; ++i) {
    const std::string file = variant_file(name, i, variants, "scene.json");
    if (with_scene(i)) std::ofstream(dir / file) << scene;
    Row row;
    row.index = i;
    row.values = {"0.5"};
    row.status = "ok";
    row.outputs = {file};
    row.hash = "h";
    append_row(manifest, row);
  }
  std::ofstream(dir / "manifest.csv") << manifest;
  SheetInput input;
  input.dir = dir;
  input.name = name;
  input.base_path = (dir / (name + ".json")).string();
  input.pointers = pointers;
  input.axis_sizes = {static_cast<std::size_t>(variants)};
  input.variants = variants;
  input.figures = true;
  return input;
}

TEST(ContactSheet, TooMuchDrawingInAllIsLeftOutBeforeAnyIsDrawn) {
  const fs::path dir = fs::temp_directory_path() / ("pita-test-sheet-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const double one = render::estimate_cost(scene::parse_scene(kHeavy, "heavy.json")).units;
  ASSERT_GT(one, 0.0);
  const auto variants = static_cast<std::int64_t>(std::floor(kMaxContactUnits / one)) + 1;
  ASSERT_LE(variants, kMaxContactCells) << "the scene is too light to exceed the budget within the cells";
  const SheetInput input = sweep_of(dir, "heavy", variants, kHeavy, [](std::int64_t) { return true; });
  const std::string note = write_contact_sheet(input);
  EXPECT_NE(note.find("more than the contact sheet's budget"), std::string::npos) << note;
  EXPECT_FALSE(fs::exists(dir / "contact.svg"));
  EXPECT_FALSE(fs::exists(dir / "contact.png"));
  fs::remove_all(dir);
}

TEST(ContactSheet, ALargeSweepShowsAnEvenlySpacedSampleFromFirstToLast) {
  EXPECT_EQ(contact_sample(0).size(), 0u);
  EXPECT_EQ(contact_sample(3), (std::vector<std::int64_t>{0, 1, 2}));
  EXPECT_EQ(contact_sample(kMaxContactCells).back(), kMaxContactCells - 1);
  for (const std::int64_t variants : {kMaxContactCells + 1, std::int64_t{1000}, std::int64_t{1'000'000}}) {
    const std::vector<std::int64_t> sample = contact_sample(variants);
    ASSERT_EQ(static_cast<std::int64_t>(sample.size()), kMaxContactCells) << variants;
    EXPECT_EQ(sample.front(), 0);
    EXPECT_EQ(sample.back(), variants - 1);
    // Evenly spaced: every step is the mean step, rounded down or up.
    const double mean = static_cast<double>(variants - 1) / static_cast<double>(kMaxContactCells - 1);
    for (std::size_t i = 1; i < sample.size(); ++i) {
      const std::int64_t step = sample[i] - sample[i - 1];
      EXPECT_GE(step, static_cast<std::int64_t>(std::floor(mean))) << variants << " at " << i;
      EXPECT_LE(step, static_cast<std::int64_t>(std::ceil(mean))) << variants << " at " << i;
    }
  }
}

// 1000 variants, only the sampled ones with a scene file: the sheet draws
// 16 x 16 cells (its PNG 16 cells wide, not the 32 of all 1000), reading no
// other variant.
TEST(ContactSheet, ALargeSweepIsDrawnFromItsSampleOnly) {
  const fs::path dir = fs::temp_directory_path() / ("pita-test-sample-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string light = R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
    {"t": 1, "p": [2, 0], "m": 1, "w": 0.5}], "canvas": {"width": 200, "height": 150},
    "layers": [{"type": "pattern", "samples": 5}]})";
  const std::int64_t variants = 1000;
  const std::vector<std::int64_t> sample = contact_sample(variants);
  const SheetInput input = sweep_of(dir, "light", variants, light, [&](std::int64_t i) {
    return std::binary_search(sample.begin(), sample.end(), i);
  });
  EXPECT_EQ(write_contact_sheet(input), "");
  std::ifstream png(dir / "contact.png", std::ios::binary);
  unsigned char header[24] = {};
  ASSERT_TRUE(png.read(reinterpret_cast<char*>(header), sizeof header));
  const int width = (header[16] << 24) | (header[17] << 16) | (header[18] << 8) | header[19];
  // 16 columns of 2400 / 16 = 150 px, 8 px apart, 8 px margins.
  EXPECT_EQ(width, 8 + 16 * (150 + 8) + 8);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace pita::sweep
