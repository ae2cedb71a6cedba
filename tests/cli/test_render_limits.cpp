// `pita render` at the documented limits, under a memory limit (issue 11):
// every figure within the budget renders in 1 GB of address space, and every
// figure beyond it is refused with exit 2 and the field's pointer. Never a
// signal, never "internal error".
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "run_pita.hpp"

namespace pita::test {
namespace {

namespace fs = std::filesystem;

// ASan reserves terabytes of address space: a ulimit -v cannot be tested there.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

constexpr std::size_t kOneGiB = std::size_t{1} << 30;

const std::string& kKeyframes = kFigureOneFields;
const std::string kPoses = R"("method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
  {"t": 1, "matrix": [[0, -1, 3], [1, 0, 0]]}])";

std::string repeated(const std::string& item, int n) {
  std::string list;
  for (int i = 0; i < n; ++i) list += (i ? ", " : "") + item;
  return list;
}

// A circle of `points` vertices, or a zigzag whose every edge crosses the shape.
std::string polygon(int points, bool zigzag = false) {
  std::string text = "[";
  for (int i = 0; i < points; ++i) {
    const double a = 2.0 * 3.141592653589793 * i / points;
    text += (i ? ", [" : "[") +
            (zigzag ? std::to_string(i % 7) + ", " + std::to_string(i % 5)
                    : std::to_string(std::cos(a)) + ", " + std::to_string(std::sin(a))) +
            "]";
  }
  return text + "]";
}

struct Case {
  const char* name;
  std::string scene;
  std::vector<std::string> options;
  int exit_code;
  const char* error;  // what stderr must contain when refused
};

std::vector<Case> cases() {
  return {
      {"trajectories-at-the-budget",
       "{" + kKeyframes + R"(, "layers": [)" + repeated(R"({"type": "trajectory", "samples": 100000})", 19) + "]}",
       {"--format", "svg,png"},
       0,
       ""},
      {"patterns-at-the-budget",
       "{" + kKeyframes + R"(, "layers": [)" + repeated(R"({"type": "pattern", "samples": 10000})", 11) + "]}",
       {"--format", "svg,pdf"},
       0,
       ""},
      {"largest-canvas",
       "{" + kKeyframes + R"(, "canvas": {"width": 8192, "height": 8192}})",
       {"--format", "png"},
       0,
       ""},
      {"largest-existence-map",
       "{" + kPoses + R"(, "layers": [{"type": "existence", "columns": 4000, "rows": 1000}]})",
       {"--format", "svg,png"},
       0,
       ""},
      {"largest-shapes",
       "{" + kPoses + R"(, "shapes": [)" + repeated("{\"polygon\": " + polygon(10000) + "}", 64) +
           R"(], "layers": [{"type": "shapes", "samples": 2}]})",
       {"--format", "svg,png"},
       0,
       ""},
      {"zigzag-shapes",
       "{" + kPoses + R"(, "shapes": [)" + repeated("{\"polygon\": " + polygon(10000, true) + "}", 64) +
           R"(], "layers": [{"type": "shapes", "samples": 2}]})",
       {"--format", "png"},
       2,
       "/layers/0: the PNG would stroke about"},
      {"every-limit-at-once",
       "{" + kKeyframes + R"(, "layers": [)" + repeated(R"({"type": "pattern", "samples": 10000})", 64) +
           R"(], "panels": [)" + repeated("\"P6\"", 64) + "]}",
       {},
       2,
       "/layers: 4096 layer drawings"},
      {"top-level-samples",
       "{" + kKeyframes + R"(, "samples": 1000000, "panels": [)" + repeated("\"P6\"", 9) + "]}",
       {},
       2,
       "/samples: 1000000 frames for the figure's layers exceeds the figure limit"},
      {"canvas-scaled-beyond-the-pixel-budget",
       "{" + kKeyframes + R"(, "canvas": {"width": 8192, "height": 8192}})",
       {"--format", "png", "--scale", "2"},
       2,
       "/canvas: a PNG of 268 million pixels"},
  };
}

TEST(RenderLimits, EveryLimitRendersInOneGigabyteOrIsRefused) {
  if (kAddressSanitizer) GTEST_SKIP() << "ulimit -v and AddressSanitizer do not mix";
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const ScratchDir dir;
    dir.write(std::string(c.name) + ".json", c.scene);
    std::vector<std::string> args{"render", std::string(c.name) + ".json", "-o", "out"};
    args.insert(args.end(), c.options.begin(), c.options.end());
    const RunResult r = run_pita(args, dir.path(), kOneGiB);
    EXPECT_FALSE(r.signaled) << "killed by signal " << r.exit_code - 128 << "\n" << r.err;
    EXPECT_EQ(r.exit_code, c.exit_code) << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("out of memory"), std::string::npos) << r.err;
    if (c.exit_code == 0) {
      EXPECT_TRUE(fs::exists(dir.path() / "out" /
                             (std::string(c.name) + "." + (c.options.empty() ? "svg" : c.options[1].substr(0, 3)))));
    } else {
      EXPECT_NE(r.err.find(std::string(c.name) + ".json: " + c.error), std::string::npos) << r.err;
      EXPECT_FALSE(fs::exists(dir.path() / "out" / (std::string(c.name) + ".svg")));
    }
  }
}

// Out of memory is a clear error naming the scene, exit 2: a figure within
// the budget under a limit far too small for it.
TEST(RenderLimits, OutOfMemoryNamesTheScene) {
  if (kAddressSanitizer) GTEST_SKIP() << "ulimit -v and AddressSanitizer do not mix";
  const ScratchDir dir;
  dir.write("big.json",
            "{" + kKeyframes + R"(, "layers": [)" + repeated(R"({"type": "pattern", "samples": 10000})", 11) + "]}");
  const RunResult r = run_pita({"render", "big.json", "-o", "out.svg"}, dir.path(), 160u << 20);
  EXPECT_FALSE(r.signaled) << r.err;
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err.rfind("pita: big.json: ", 0), 0u) << r.err;  // cairo or pita says it
  EXPECT_NE(r.err.find("out of memory"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out.svg"));
}

}  // namespace
}  // namespace pita::test
