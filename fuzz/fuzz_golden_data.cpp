// Bytes -> a golden data file (golden/<scene>/<scene>.data.json) as `pita
// check` reads and compares it (golden::compare_file): against the figure
// data of a small fresh rendering (what check does), and against itself
// with a trailing newline (the same numbers, so every item is walked). A
// golden that cannot be read must be a GoldenError (docs/reference/check.md "Goldens": exit
// 2, naming the file); nothing else may escape.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "fuzz_support.hpp"
#include "golden/check.hpp"
#include "golden/figure_data.hpp"
#include "render/figure.hpp"
#include "scene/scene.hpp"

namespace {

using namespace pita;
namespace fs = std::filesystem;

// The figure data of a small scene (no text, so no fonts): what a fresh
// rendering gives `pita check`.
const std::string& fresh_data() {
  static const std::string data = [] {
    const scene::Scene s = scene::parse_scene(
        R"({"method": "P6", "samples": 3,
            "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0.4}, {"t": 0.5, "p": [3, 1.5], "q": [3.5, 2]},
                          {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}],
            "layers": [{"type": "pattern"}, {"type": "keyframes"}, {"type": "trajectory", "samples": 5}]})",
        "fresh.json");
    return golden::figure_data_text(golden::figure_data("fresh", s, render::build_figure(s)));
  }();
  return data;
}

// compare_file reads the golden from a file: one per process, removed at exit.
const fs::path& golden_file() { return fuzz::scratch_path("pita-fuzz-golden-", ".data.json"); }

void compare(const std::string& actual) {
  try {
    const golden::FileCheck check =
        golden::compare_file(golden::FileKind::data, golden_file(), actual, golden::Tolerances{});
    PITA_FUZZ_CHECK(check.verdict != golden::Verdict::missing);
  } catch (const golden::GoldenError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = fuzz::text_of(data, size);
  {
    std::ofstream out(golden_file(), std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    PITA_FUZZ_CHECK(out.good());
  }
  compare(fresh_data());
  compare(std::string(text) + "\n");
  return 0;
}
