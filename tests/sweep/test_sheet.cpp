// The contact sheet (src/sweep/sheet.cpp): its whole drawing is estimated
// before any of it is drawn, and a sheet beyond kMaxContactUnits is left out
// with a note (issue 37: 32 heavy variants drew 1.6 GB of SVG in memory).
#include "sweep/sheet.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "render/budget.hpp"
#include "scene/scene.hpp"

namespace pita::sweep {
namespace {

namespace fs = std::filesystem;

// A figure of many frames: cheap to estimate, dear to draw.
const std::string kHeavy = R"({"method": "P6", "keyframes": [
  {"t": 0, "p": [0, 0], "m": 1, "w": 0.4},
  {"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": 2.0},
  {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}],
  "layers": [{"type": "pattern", "samples": 4000}, {"type": "stroke", "samples": 4000}]})";

TEST(ContactSheet, TooMuchDrawingInAllIsLeftOutBeforeAnyIsDrawn) {
  const fs::path dir = fs::temp_directory_path() / ("pita-test-sheet-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const double one = render::estimate_cost(scene::parse_scene(kHeavy, "heavy.json")).units;
  ASSERT_GT(one, 0.0);
  const auto variants = static_cast<std::int64_t>(std::floor(kMaxContactUnits / one)) + 1;
  ASSERT_LE(variants, kMaxContactCells) << "the scene is too light to exceed the budget within the cells";
  const std::vector<std::string> pointers = {"/keyframes/1/t"};
  std::string manifest = manifest_header(pointers);
  for (std::int64_t i = 0; i < variants; ++i) {
    const std::string file = variant_file("heavy", i, variants, "scene.json");
    std::ofstream(dir / file) << kHeavy;
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
  input.name = "heavy";
  input.base_path = (dir / "heavy.json").string();
  input.pointers = pointers;
  input.axis_sizes = {static_cast<std::size_t>(variants)};
  input.variants = variants;
  input.figures = true;
  const std::string note = write_contact_sheet(input);
  EXPECT_NE(note.find("more than the contact sheet's budget"), std::string::npos) << note;
  EXPECT_FALSE(fs::exists(dir / "contact.svg"));
  EXPECT_FALSE(fs::exists(dir / "contact.png"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace pita::sweep
