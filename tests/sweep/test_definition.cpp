// A sweep's definition (src/sweep/definition.cpp): DIR/sweep.json written and
// read back as --merge reads it, and the folders that are not a sweep's.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "sweep/definition.hpp"
#include "sweep/sweep.hpp"

namespace pita::sweep {
namespace {

namespace fs = std::filesystem;

// A fresh folder of its own under the temporary directory.
fs::path definition_folder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("pita-definition-" + std::to_string(::getpid()) + "-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write_text(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

TEST(Definition, WrittenAndReadBackAlike) {
  Definition d;
  d.scene = "scenes/fig01-eight-pitas.json";
  d.name = "fig01-eight-pitas";
  d.axes = {{"/keyframes/1/m", "0.5:2:7"}, {"/keyframes/0/w", "[0, 1]"}};
  d.axis_sizes = {7, 2};
  d.zip = false;
  d.formats = {"svg", "csv"};
  d.variants = 14;
  d.salt = "pita 0.1.0 svg csv";
  d.base = Json{{"method", "P6"}, {"samples", 3}};
  const fs::path dir = definition_folder("round-trip");
  write_text(dir / kSweepFile, definition_json(d));
  const Definition back = read_definition(dir);
  EXPECT_EQ(back.scene, d.scene);
  EXPECT_EQ(back.name, d.name);
  EXPECT_EQ(back.axes, d.axes);
  EXPECT_EQ(back.axis_sizes, d.axis_sizes);
  EXPECT_EQ(back.zip, d.zip);
  EXPECT_EQ(back.formats, d.formats);
  EXPECT_EQ(back.variants, d.variants);
  EXPECT_EQ(back.salt, d.salt);
  EXPECT_EQ(back.base, d.base);
  EXPECT_EQ(pointers_of(back), (std::vector<std::string>{"/keyframes/1/m", "/keyframes/0/w"}));
  fs::remove_all(dir);
}

TEST(Definition, AFolderWithoutOneOrWithABadOneIsNotASweeps) {
  const fs::path dir = definition_folder("bad");
  const auto message = [&] {
    try {
      (void)read_definition(dir);
    } catch (const SweepUsageError& error) {
      return std::string(error.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(message().find("no sweep.json there: it is not the output folder of a pita sweep"), std::string::npos)
      << message();
  write_text(dir / kSweepFile, R"({"scene": "s.json", "name": "../up", "axes": [], "zip": false, "formats": [],
      "variants": 1, "salt": "", "base": {}})");
  EXPECT_NE(message().find("is not a sweep definition (bad name)"), std::string::npos) << message();
  write_text(dir / kSweepFile, "{");
  EXPECT_NE(message().find("is not a sweep definition"), std::string::npos) << message();
  fs::remove_all(dir);
}

}  // namespace
}  // namespace pita::sweep
