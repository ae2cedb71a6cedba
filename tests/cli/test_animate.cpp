// `pita animate` through the real binary (docs/reference/animate.md "Animation", src/animate/):
// the frame directory (counts, times of src/animate/timeline.hpp, sizes), each
// frame equal to `pita render --at t_k`, the animated SVG (valid XML, one
// group per frame, small enough, and played by headless Chromium as the PNG
// frames show it), videos read back by ffprobe, bad input refused before
// anything is written, interrupted runs leaving nothing, and the progress bar
// only on a terminal.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include "golden/check.hpp"
#include "golden/image_compare.hpp"
#include "run_pita.hpp"
#include "support/sanitizers.hpp"

namespace pita::test {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using namespace std::chrono_literals;

const fs::path kScenes = fs::path(PITA_SOURCE_DIR) / "scenes";
const fs::path kFig23 = kScenes / "fig23-image-motion.json";          // looping, an image, 120 frames
const fs::path kFig27 = kScenes / "fig27-animated-pattern.json";      // "what": "pattern", not looping
const fs::path kPoses = kScenes / "sam-fig01-regular-patterns.json";  // a pose scene (SAM), looping

// ------------------------------------------------------------ helpers

Json read_json(const fs::path& path) { return Json::parse(read_file(path)); }

// What the test knows of a scene's animation, from its JSON alone (not from
// pita): the time range [first, last] of timeline.hpp, whether it loops, the
// canvas.
struct SceneClock {
  double first = 0.0, last = 1.0;
  bool loop = true;
  int width = 0, height = 0;
};

SceneClock clock_of(const fs::path& scene_path) {
  const Json scene = read_json(scene_path);
  SceneClock clock;
  const Json animation = scene.value("animation", Json::object());
  clock.loop = animation.value("loop", true);
  const Json canvas =
      scene.value("canvas", Json::object());  // the defaults: docs/reference/scene-format.md "Scene format"
  clock.width = canvas.value("width", 800);
  clock.height = canvas.value("height", 600);
  if (animation.value("what", std::string("motion")) == "pattern") return clock;  // tau over [0, 1]
  // "motion": the knots of the scene's keyframes / poses / points and of every
  // panel's own.
  std::vector<const Json*> holders = {&scene};
  if (scene.contains("panels")) {
    for (const Json& panel : scene["panels"]) {
      if (panel.is_object()) holders.push_back(&panel);
    }
  }
  bool any = false;
  for (const Json* holder : holders) {
    for (const char* field : {"keyframes", "poses", "points"}) {
      if (!holder->contains(field) || (*holder)[field].empty()) continue;
      const double front = (*holder)[field].front().at("t").get<double>();
      const double back = (*holder)[field].back().at("t").get<double>();
      clock.first = any ? std::min(clock.first, front) : front;
      clock.last = any ? std::max(clock.last, back) : back;
      any = true;
    }
  }
  EXPECT_TRUE(any) << scene_path;
  return clock;
}

// t_k of timeline.hpp, written out independently.
double frame_time(const SceneClock& clock, int k, int count) {
  return clock.loop ? clock.first + (clock.last - clock.first) * k / count
                    : clock.first + (clock.last - clock.first) * k / (count - 1);
}

std::string time_arg(double t) { return fmt::format("{:.17g}", t); }

// A PNG's width and height from its IHDR chunk.
std::pair<int, int> png_size(const std::string& png) {
  if (png.size() < 24 || png.compare(1, 3, "PNG") != 0) return {-1, -1};
  const auto be32 = [&](std::size_t at) {
    return (static_cast<unsigned char>(png[at]) << 24) | (static_cast<unsigned char>(png[at + 1]) << 16) |
           (static_cast<unsigned char>(png[at + 2]) << 8) | static_cast<unsigned char>(png[at + 3]);
  };
  return {static_cast<int>(be32(16)), static_cast<int>(be32(20))};
}

// Names in `dir` (not recursive).
std::set<std::string> names_in(const fs::path& dir) {
  std::set<std::string> names;
  if (!fs::exists(dir)) return names;
  for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename().string());
  return names;
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

// Single-quoted for sh.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

struct CommandResult {
  int exit_code = -1;
  std::string out;  // stdout (and stderr when the command redirects it)
};

// Runs `command` with sh, capturing its stdout.
CommandResult run_command(const std::string& command) {
  CommandResult result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) result.out.append(buffer, n);
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return result;
}

bool have_program(const std::string& name) {
  return run_command("command -v " + name + " >/dev/null 2>&1").exit_code == 0;
}

// Writes `pita render SCENE --at T` as `out` (a PNG) and returns its bytes.
std::string render_at(const fs::path& scene, double t, const fs::path& out, const fs::path& dir,
                      const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"render", scene.string(), "--at", time_arg(t), "-o", out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = run_pita(args, dir);
  EXPECT_EQ(r.exit_code, 0) << "render --at " << time_arg(t) << ": " << r.err;
  return read_file(dir / out);
}

mode_t current_umask() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return mask;
}

mode_t permissions_of(const fs::path& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) return 0;
  return status.st_mode & 07777;
}

// ------------------------------------------------------------ 1. frame directory: counts, times, sizes

struct DirectoryCase {
  const char* name;
  fs::path scene;
  double scale;
};
void PrintTo(const DirectoryCase& c, std::ostream* os) { *os << c.name; }

class AnimateFrames : public ::testing::TestWithParam<DirectoryCase> {};

// --frames 7: frame-0001.png .. frame-0007.png and frames.json, nothing else;
// each record's "t" is t_k (looping: k / N; not looping: k / (N - 1), both
// ends shown); every PNG is the canvas times --scale. Quiet on stderr (not a
// terminal), and the directory gets the ordinary permissions (0777 less the
// umask), like any other output.
TEST_P(AnimateFrames, SevenFramesAtTheDocumentedTimesAndSize) {
  const DirectoryCase& c = GetParam();
  const SceneClock clock = clock_of(c.scene);
  const ScratchDir dir;
  const RunResult r =
      run_pita({"animate", c.scene.string(), "-o", "frames", "--frames", "7", "--scale", fmt::format("{}", c.scale)},
               dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "") << "no progress bar when stderr is not a terminal";
  EXPECT_NE(r.out.find("wrote frames (7 frames"), std::string::npos) << r.out;

  std::set<std::string> expected_names = {"frames.json"};
  for (int k = 1; k <= 7; ++k) expected_names.insert(fmt::format("frame-{:04}.png", k));
  EXPECT_EQ(names_in(dir.path() / "frames"), expected_names);
  EXPECT_TRUE(hidden_in(dir.path()).empty()) << joined(hidden_in(dir.path()));
  EXPECT_EQ(permissions_of(dir.path() / "frames"), 0777 & ~current_umask());
  EXPECT_EQ(permissions_of(dir.path() / "frames" / "frame-0001.png"), 0666 & ~current_umask());

  const Json index = read_json(dir.path() / "frames" / "frames.json");
  EXPECT_EQ(index.at("frames").get<int>(), 7);
  EXPECT_EQ(index.at("loop").get<bool>(), clock.loop);
  const int width = static_cast<int>(std::lround(clock.width * c.scale));
  const int height = static_cast<int>(std::lround(clock.height * c.scale));
  EXPECT_EQ(index.at("width").get<int>(), width);
  EXPECT_EQ(index.at("height").get<int>(), height);
  const Json& list = index.at("frame_list");
  ASSERT_EQ(list.size(), 7u);
  for (int k = 0; k < 7; ++k) {
    SCOPED_TRACE(fmt::format("frame {}", k + 1));
    EXPECT_EQ(list[k].at("frame").get<int>(), k + 1);
    EXPECT_EQ(list[k].at("file").get<std::string>(), fmt::format("frame-{:04}.png", k + 1));
    EXPECT_DOUBLE_EQ(list[k].at("t").get<double>(), frame_time(clock, k, 7));
    EXPECT_EQ(png_size(read_file(dir.path() / "frames" / fmt::format("frame-{:04}.png", k + 1))),
              std::make_pair(width, height));
  }
  // The ends: a looping animation stops one step short of t_n (frame N would
  // be frame 0 again); one that does not loop shows t_n itself.
  EXPECT_DOUBLE_EQ(list[0].at("t").get<double>(), clock.first);
  if (clock.loop) {
    EXPECT_LT(list[6].at("t").get<double>(), clock.last);
  } else {
    EXPECT_EQ(list[6].at("t").get<double>(), clock.last);
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, AnimateFrames,
                         ::testing::Values(DirectoryCase{"fig23_looping", kFig23, 1.0},
                                           DirectoryCase{"fig27_pattern_not_looping", kFig27, 0.5},
                                           DirectoryCase{"sam_poses_looping", kPoses, 0.25}),
                         [](const ::testing::TestParamInfo<DirectoryCase>& param) { return param.param.name; });

// SVG frames: frame-0001.svg ..., each a whole SVG document.
TEST(AnimateFrameFormats, SvgFrames) {
  const ScratchDir dir;
  const RunResult r =
      run_pita({"animate", kFig23.string(), "-o", "frames/", "--frames", "3", "--format", "svg"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(names_in(dir.path() / "frames"),
            (std::set<std::string>{"frame-0001.svg", "frame-0002.svg", "frame-0003.svg", "frames.json"}));
  const std::string svg = read_file(dir.path() / "frames/frame-0002.svg");
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

// ------------------------------------------------------------ 2. frame k == render --at t_k

// `frames`: --frames given to animate only, or 0 for the scene's own
// timeline. A scene with a "trail" (fig23, the SAM scene) spaces its trail by
// the animation's frame step: on another timeline, `render --at` is given the
// same --frames (in `extra`) to draw the same trail.
struct AtCase {
  const char* name;
  fs::path scene;
  int frames;
  std::vector<int> ks;
  std::vector<std::string> extra;  // flags given to both animate and render
};
void PrintTo(const AtCase& c, std::ostream* os) { *os << c.name; }

class AnimateFrameEqualsRenderAt : public ::testing::TestWithParam<AtCase> {};

TEST_P(AnimateFrameEqualsRenderAt, ByteForByte) {
  const AtCase& c = GetParam();
  const SceneClock clock = clock_of(c.scene);
  const ScratchDir dir;
  std::vector<std::string> args = {"animate", c.scene.string(), "-o", "frames"};
  if (c.frames > 0) args.insert(args.end(), {"--frames", std::to_string(c.frames)});
  args.insert(args.end(), c.extra.begin(), c.extra.end());
  const RunResult r = run_pita(args, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const int count = read_json(dir.path() / "frames/frames.json").at("frames").get<int>();
  if (c.frames > 0) {
    EXPECT_EQ(count, c.frames);
  }
  for (const int k : c.ks) {
    SCOPED_TRACE(fmt::format("frame {} (k = {})", k + 1, k));
    const double t = frame_time(clock, k, count);
    const std::string frame = read_file(dir.path() / "frames" / fmt::format("frame-{:04}.png", k + 1));
    const std::string rendered = render_at(c.scene, t, fmt::format("at-{}.png", k), dir.path(), c.extra);
    ASSERT_FALSE(frame.empty());
    EXPECT_TRUE(frame == rendered) << "frame-" << k + 1 << ".png differs from render --at " << time_arg(t);
  }
  // And the frames do move: the first and a later one differ.
  EXPECT_NE(read_file(dir.path() / "frames/frame-0001.png"),
            read_file(dir.path() / "frames" / fmt::format("frame-{:04}.png", c.ks.back() + 1)));
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, AnimateFrameEqualsRenderAt,
    ::testing::Values(
        AtCase{"fig23_image_motion", kFig23, 0, {0, 1, 3, 60, 119}, {"--scale", "0.5"}},
        AtCase{"fig27_pattern", kFig27, 7, {0, 3, 6}, {"--scale", "0.5"}},
        AtCase{"fig27_pattern_own_timeline", kFig27, 0, {0, 45, 89}, {"--scale", "0.25"}},
        AtCase{"sam_poses", kPoses, 0, {0, 2, 45, 89}, {"--scale", "0.5"}},
        AtCase{"fig23_trail_on_nine_frames", kFig23, 0, {0, 4, 8}, {"--frames", "9", "--scale", "0.5"}},
        AtCase{
            "space_polysam", kScenes / "sam-3d-fig13-polysam.json", 0, {0, 4, 8}, {"--frames", "9", "--scale", "0.5"}},
        // two panels whose strokes do not move: PNG frames over a backdrop (render/backdrop.hpp)
        AtCase{"two_panels_over_a_backdrop",
               kScenes / "tracks-fig01-eight-keyframes.json",
               0,
               {0, 4, 8},
               {"--frames", "9", "--scale", "0.5"}},
        AtCase{"two_panels_at_a_fractional_scale",
               kScenes / "tracks-fig01-eight-keyframes.json",
               0,
               {0, 5},
               {"--frames", "6", "--scale", "0.37"}}),
    [](const ::testing::TestParamInfo<AtCase>& param) { return param.param.name; });

// ------------------------------------------------------------ 3. animated SVG

constexpr std::size_t kMaxAnimatedSvgBytes = 2u << 20;  // fig23's 120 frames stay under 2 MB

std::size_t count_of(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + needle.size())) ++n;
  return n;
}

TEST(AnimateSvg, Fig23IsValidXmlWithOneGroupPerFrameUnderTwoMegabytes) {
  if (!have_program("xmllint")) GTEST_SKIP() << "xmllint is not installed (Debian libxml2-utils)";
  const ScratchDir dir;
  const RunResult r = run_pita({"animate", kFig23.string(), "-o", "fig23.svg"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("wrote fig23.svg (120 frames at 30 fps: 4 s)"), std::string::npos) << r.out;
  // -q: errors only; the same file.
  const RunResult quiet = run_pita({"animate", kFig23.string(), "-o", "quiet.svg", "-q"}, dir.path());
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_EQ(quiet.out + quiet.err, "");
  EXPECT_EQ(read_file(dir.path() / "quiet.svg"), read_file(dir.path() / "fig23.svg"));
  const fs::path svg_path = dir.path() / "fig23.svg";
  const std::string svg = read_file(svg_path);
  const CommandResult lint = run_command("xmllint --noout " + quoted(svg_path.string()) + " 2>&1");
  EXPECT_EQ(lint.exit_code, 0) << lint.out;
  EXPECT_EQ(count_of(svg, "<animate attributeName=\"visibility\""), 120u);
  EXPECT_LT(svg.size(), kMaxAnimatedSvgBytes);
  EXPECT_EQ(count_of(svg, "repeatCount=\"indefinite\""), 120u) << "a looping scene loops";
  EXPECT_EQ(count_of(svg, "<script"), 0u) << "SMIL only";
  EXPECT_EQ(permissions_of(svg_path), 0666 & ~current_umask());
}

// An animation never replaces an input: here an image the scene draws (a PNG
// named .svg, the one extension an image and an animation can share).
TEST(AnimateSvg, TheOutputIsNeverAnInput) {
  const ScratchDir dir;
  std::string scene = read_file(kFig23);
  const std::string image = "images/picture.png";
  ASSERT_NE(scene.find(image), std::string::npos);
  scene.replace(scene.find(image), image.size(), "pic.svg");
  dir.write("f.json", scene);
  fs::copy_file(kFig23.parent_path() / image, dir.path() / "pic.svg");
  const std::string before = read_file(dir.path() / "pic.svg");
  const RunResult r = run_pita({"animate", "f.json", "-o", "pic.svg", "--frames", "3"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("the output pic.svg is an image its shapes draw, which it would replace"), std::string::npos)
      << r.err;
  EXPECT_EQ(read_file(dir.path() / "pic.svg"), before);
}

// --frames and --fps decide the groups and the playing time; a scene that does
// not loop plays once.
TEST(AnimateSvg, FramesFlagAndANonLoopingScene) {
  if (!have_program("xmllint")) GTEST_SKIP() << "xmllint is not installed (Debian libxml2-utils)";
  const ScratchDir dir;
  const RunResult r =
      run_pita({"animate", kFig27.string(), "-o", "fig27.svg", "--frames", "7", "--fps", "7"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = read_file(dir.path() / "fig27.svg");
  const CommandResult lint = run_command("xmllint --noout " + quoted((dir.path() / "fig27.svg").string()) + " 2>&1");
  EXPECT_EQ(lint.exit_code, 0) << lint.out;
  EXPECT_EQ(count_of(svg, "<animate attributeName=\"visibility\""), 7u);
  EXPECT_EQ(count_of(svg, "repeatCount=\"indefinite\""), 0u) << "fig27 does not loop";
  EXPECT_EQ(count_of(svg, "dur=\"1s\""), 7u);
}

// ------------------------------------------------------------ 4. Chromium plays the animated SVG

// Chromium (Skia) and cairo antialias edges differently (glyph outlines, the
// thin trajectory, the image's edges), so a browser's frame cannot match
// cairo's PNG at the goldens' tolerance (a channel 16 off in at most 0.2% of
// the pixels: golden/check.hpp). Measured on fig23, 800 x 600, frames 10 and
// 70 (Chromium 156, Debian 12): 1.50% and 1.47% of the pixels differ by more
// than 16, 0.93% and 0.92% by more than 32; the neighbouring frames (1/30 s
// away) differ from the screenshot in 1.68% to 1.92% by more than 32. So: a
// channel may differ by 32, in at most 1.25% of the pixels, which takes the
// right frame with some room and still refuses its neighbours.
constexpr int kBrowserChannelTolerance = 32;
constexpr double kBrowserDifferingShare = 0.0125;

const char* chromium_path() {
  static const std::string path = [] {
    if (::access("/usr/bin/chromium", X_OK) == 0) return std::string("/usr/bin/chromium");
    const CommandResult found = run_command("command -v chromium 2>/dev/null");
    std::string text = found.exit_code == 0 ? found.out : "";
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    return text;
  }();
  return path.c_str();
}

// The animated SVG inlined in a page, paused at `seconds`, screenshot by
// headless Chromium at the canvas size into dir/name.png; returns Chromium's
// exit code and output.
CommandResult chromium_screenshot(const std::string& svg_text, double seconds, int width, int height,
                                  const fs::path& dir, const std::string& name) {
  std::string svg = svg_text;
  if (svg.rfind("<?xml", 0) == 0) svg.erase(0, svg.find("?>") + 2);
  const fs::path page = dir / (name + ".html");
  const fs::path shot = dir / (name + ".png");
  std::ofstream(page, std::ios::binary)
      << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><style>html,body{margin:0;overflow:hidden} "
         "svg{display:block}</style></head><body>"
      << svg << "<script>const s=document.querySelector(\"svg\"); s.pauseAnimations(); s.setCurrentTime("
      << fmt::format("{:.17g}", seconds) << ");</script></body></html>\n";
  const std::string command = fmt::format(
      "timeout 120 {} --headless --no-sandbox --disable-gpu --hide-scrollbars --force-device-scale-factor=1 "
      "--user-data-dir={} --window-size={},{} --screenshot={} {} 2>&1",
      quoted(chromium_path()), quoted((dir / (name + "-profile")).string()), width, height, quoted(shot.string()),
      quoted("file://" + page.string()));
  CommandResult r = run_command(command);
  r.out = command + "\n" + r.out;
  return r;
}

TEST(AnimateChromium, TheAnimatedSvgShowsFrameKDuringItsTime) {
  if (*chromium_path() == '\0') GTEST_SKIP() << "chromium is not installed (Debian package chromium): not played";
  const SceneClock clock = clock_of(kFig23);
  const ScratchDir dir;
  const RunResult r = run_pita({"animate", kFig23.string(), "-o", "fig23.svg"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = read_file(dir.path() / "fig23.svg");
  constexpr int kFrames = 120;  // the scene's: 4 s at 30 fps
  constexpr double kFps = 30.0;
  const golden::ImageTolerance browser{kBrowserChannelTolerance, kBrowserDifferingShare};

  // Two Chromiums at once (each takes seconds to start), each paused in the
  // middle of frame k's 1/fps.
  const std::vector<int> ks = {10, 70};
  std::vector<CommandResult> runs(ks.size());
  {
    std::vector<std::thread> threads;
    for (std::size_t i = 0; i < ks.size(); ++i) {
      threads.emplace_back([&, i] {
        runs[i] = chromium_screenshot(svg, (ks[i] + 0.5) / kFps, clock.width, clock.height, dir.path(),
                                      fmt::format("chromium-{}", ks[i]));
      });
    }
    for (std::thread& thread : threads) thread.join();
  }
  std::vector<std::string> shots;
  for (std::size_t i = 0; i < ks.size(); ++i) {
    const int k = ks[i];
    SCOPED_TRACE(fmt::format("frame k = {}", k));
    const double seconds = (k + 0.5) / kFps;
    EXPECT_EQ(runs[i].exit_code, 0) << runs[i].out;
    const std::string shot = read_file(dir.path() / fmt::format("chromium-{}.png", k));
    const std::string frame =
        render_at(kFig23, frame_time(clock, k, kFrames), fmt::format("frame-{}.png", k), dir.path());
    ASSERT_FALSE(shot.empty());
    const golden::ImageComparison same = golden::compare_png(frame, shot, browser);
    EXPECT_TRUE(same.same_size) << same.actual_width << " x " << same.actual_height;
    const golden::ImageComparison strict =
        golden::compare_png(frame, shot, {golden::kDefaultChannelTolerance, golden::kDefaultDifferingShare});
    std::printf(
        "[ chromium ] frame %d: %.2f%% of the pixels differ by more than %d, %.2f%% by more than %d "
        "(largest channel difference %d)\n",
        k, 100.0 * strict.share, golden::kDefaultChannelTolerance, 100.0 * same.share, kBrowserChannelTolerance,
        same.max_channel_difference);
    EXPECT_TRUE(same.matches) << "Chromium's frame at " << seconds << " s differs from render --at in "
                              << 100.0 * same.share << "% of the pixels";
    // Not some other frame: the neighbours (1/30 s away) do not match, and are
    // further away than the frame itself.
    for (const int other : {k - 1, k + 1}) {
      const std::string neighbour =
          render_at(kFig23, frame_time(clock, other, kFrames), fmt::format("frame-{}.png", other), dir.path());
      const golden::ImageComparison near = golden::compare_png(neighbour, shot, browser);
      EXPECT_FALSE(near.matches) << "frame " << other << " matches the screenshot of frame " << k << " ("
                                 << 100.0 * near.share << "% differ)";
      EXPECT_GT(near.differing, same.differing) << "frame " << other << " fits the screenshot as well as frame " << k;
    }
    shots.push_back(shot);
  }
  const golden::ImageComparison between = golden::compare_png(shots[0], shots[1], browser);
  EXPECT_FALSE(between.matches) << "the two screenshots are the same: the SVG does not play";
}

// ------------------------------------------------------------ 5. video

struct VideoCase {
  const char* extension;
};
void PrintTo(const VideoCase& c, std::ostream* os) { *os << c.extension; }

class AnimateVideo : public ::testing::TestWithParam<VideoCase> {};

TEST_P(AnimateVideo, TwelveFramesAtSixFpsAreTwoSecondsAtTheCanvasSize) {
  if (!have_program("ffmpeg") || !have_program("ffprobe")) {
    GTEST_SKIP() << "ffmpeg/ffprobe are not installed (Debian package ffmpeg)";
  }
  const SceneClock clock = clock_of(kFig23);
  const ScratchDir dir;
  const std::string out = std::string("clip.") + GetParam().extension;
  const RunResult r = run_pita({"animate", kFig23.string(), "-o", out, "--frames", "12", "--fps", "6"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(r.out, "wrote " + out + " (12 frames at 6 fps: 2 s)\n");
  EXPECT_TRUE(hidden_in(dir.path()).empty()) << joined(hidden_in(dir.path()));
  EXPECT_EQ(permissions_of(dir.path() / out), 0666 & ~current_umask());
  const CommandResult probe = run_command(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames,width,height "
      "-show_entries format=duration -of json " +
      quoted((dir.path() / out).string()));
  ASSERT_EQ(probe.exit_code, 0) << probe.out;
  const Json info = Json::parse(probe.out);
  const Json& stream = info.at("streams").at(0);
  EXPECT_EQ(stream.at("nb_read_frames").get<std::string>(), "12");
  EXPECT_EQ(stream.at("width").get<int>(), clock.width);
  EXPECT_EQ(stream.at("height").get<int>(), clock.height);
  EXPECT_NEAR(std::stod(info.at("format").at("duration").get<std::string>()), 2.0, 0.01);
}

INSTANTIATE_TEST_SUITE_P(Formats, AnimateVideo, ::testing::Values(VideoCase{"mp4"}, VideoCase{"webm"}),
                         [](const ::testing::TestParamInfo<VideoCase>& param) { return param.param.extension; });

// Issue 37: ffmpeg may exit 0 having written a broken file ("Error writing
// trailer" on a full disk or a file-size limit). pita checks its stderr and
// the file (not empty; readable by ffprobe beside ffmpeg) before the rename:
// exit 3, nothing committed. Stand-in ffmpegs make each failure certain.
TEST(AnimateVideoVerified, ABrokenVideoIsNeverCommitted) {
  const ScratchDir dir;
  struct Fake {
    const char* name;
    std::string body;     // the script after reading its input
    bool with_ffprobe;    // /usr/bin/ffprobe linked beside it
    std::string message;  // part of pita's stderr
  };
  const std::vector<Fake> fakes = {
      {"trailer", "printf 'partial' > \"$out\"; echo \"Error writing trailer of $out: No space left on device\" >&2",
       false, "ffmpeg reported an error: Error writing trailer"},
      {"empty", ": > \"$out\"", false, "ffmpeg wrote an empty file"},
      {"garbage", "printf 'not a video at all' > \"$out\"", true, "the video ffmpeg wrote is not readable"},
  };
  for (const Fake& fake : fakes) {
    SCOPED_TRACE(fake.name);
    if (fake.with_ffprobe && !have_program("ffprobe")) continue;
    const fs::path bin = dir.path() / fake.name;
    fs::create_directories(bin);
    dir.write(std::string(fake.name) + "/ffmpeg",
              "#!/bin/sh\nfor a; do out=$a; done\ncat > /dev/null\n" + fake.body + "\nexit 0\n");
    fs::permissions(bin / "ffmpeg", fs::perms::owner_all);
    if (fake.with_ffprobe) {
      const std::string ffprobe = run_command("command -v ffprobe").out;
      fs::create_symlink(ffprobe.substr(0, ffprobe.find('\n')), bin / "ffprobe");
    }
    fs::create_directories(dir.path() / "out");
    Started started = start_pita({"animate", kFig23.string(), "-o", "out/clip.mp4", "--frames", "3"}, dir.path(),
                                 {"PITA_FFMPEG=" + (bin / "ffmpeg").string()});
    const RunResult r = finish_pita(started);
    EXPECT_EQ(r.exit_code, 3) << r.err;
    EXPECT_NE(r.err.find(fake.message), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("wrote"), std::string::npos) << r.out;
    EXPECT_TRUE(names_in(dir.path() / "out").empty()) << joined(hidden_in(dir.path() / "out"));
  }
  // The real ffmpeg under a file-size limit.
  if (have_program("ffmpeg")) {
    const CommandResult limited = run_command(
        "cd " + quoted(dir.path().string()) + " && (trap '' XFSZ; ulimit -f 64; exec " + quoted(pita_binary()) +
        " animate " + quoted(kFig23.string()) + " -o out/v.mp4 --frames 300 -q) 2>&1");
    EXPECT_EQ(limited.exit_code, 3) << limited.out;
    EXPECT_FALSE(fs::exists(dir.path() / "out/v.mp4"));
    EXPECT_TRUE(names_in(dir.path() / "out").empty()) << joined(hidden_in(dir.path() / "out"));
  }
}

// No ffmpeg: exit 2 before anything is written, naming the Debian package.
TEST(AnimateVideoWithoutFfmpeg, ExitTwoNamingThePackage) {
  const ScratchDir dir;
  fs::create_directories(dir.path() / "out");
  for (const char* out : {"out/clip.mp4", "out/clip.webm"}) {
    Started started =
        start_pita({"animate", kFig23.string(), "-o", out, "--frames", "3"}, dir.path(), {"PITA_FFMPEG=/nonexistent"});
    const RunResult r = finish_pita(started);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("ffmpeg"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("apt-get install ffmpeg"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_TRUE(names_in(dir.path() / "out").empty()) << joined(hidden_in(dir.path() / "out"));
  }
}

// ------------------------------------------------------------ 6. bad input: exit 2, nothing written

struct BadCase {
  const char* name;
  std::vector<std::string> flags;
  std::string out;      // OUT, inside the folder "out"
  std::string message;  // part of stderr: the flag or the field
};
void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

class AnimateBadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(AnimateBadInput, ExitTwoNamingTheFlagAndNothingWritten) {
  const BadCase& c = GetParam();
  const ScratchDir dir;
  fs::create_directories(dir.path() / "out");
  std::vector<std::string> args = {"animate", kFig23.string(), "-o", "out/" + c.out};
  args.insert(args.end(), c.flags.begin(), c.flags.end());
  const RunResult r = run_pita(args, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("internal"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(fs::exists(dir.path() / "out" / c.out));
  EXPECT_TRUE(names_in(dir.path() / "out").empty()) << joined(hidden_in(dir.path() / "out"));
}

INSTANTIATE_TEST_SUITE_P(
    Flags, AnimateBadInput,
    ::testing::Values(
        BadCase{"fps_zero", {"--fps", "0"}, "frames", "--fps"}, BadCase{"fps_241", {"--fps", "241"}, "frames", "--fps"},
        BadCase{"fps_zero_svg", {"--fps", "0"}, "a.svg", "--fps"},
        BadCase{"duration_zero", {"--duration", "0"}, "frames", "--duration"},
        BadCase{"frames_one", {"--frames", "1"}, "frames", "--frames"},
        BadCase{"frames_100001", {"--frames", "100001"}, "a.mp4", "--frames"},
        BadCase{"gif_output", {}, "a.gif", "-o out/a.gif"},
        BadCase{"pdf_frames", {"--format", "pdf"}, "frames", "--format"},
        BadCase{"png_format_for_svg_output", {"--format", "png"}, "a.svg", "--format"},
        BadCase{"scale_zero", {"--scale", "0"}, "frames", "--scale"},
        // total work: 5001 frames of vector output, 20 834 frames of 800 x 600 pixels
        BadCase{"svg_frames_beyond_the_limit", {"--frames", "5001"}, "a.svg", "--frames: 5001 frames of vector output"},
        BadCase{
            "pixels_beyond_the_budget", {"--frames", "20834"}, "frames", "--frames: 20834 frames of 800 x 600 pixels"}),
    [](const ::testing::TestParamInfo<BadCase>& param) { return param.param.name; });

// Issue 37: frames x the figure's drawing is refused before anything is drawn
// (two 10 000-sample strokes, 100 000 small frames), naming --frames and
// --budget; --budget raises it.
TEST(AnimateBudget, TheFramesDrawingIsRefusedUpFront) {
  const ScratchDir dir;
  dir.write("heavy.json", R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
      {"t": 1, "p": [4, 1], "m": 2, "w": 1}, {"t": 2, "p": [8, 0], "m": 1, "w": 3}],
      "canvas": {"width": 800, "height": 400},
      "layers": [{"type": "stroke", "samples": 10000}, {"type": "stroke", "samples": 10000, "opacity": 0.5},
                 {"type": "pattern"}]})");
  fs::create_directories(dir.path() / "out");
  for (const char* out : {"out/frames", "out/a.svg", "out/a.mp4"}) {
    const RunResult r =
        run_pita({"animate", "heavy.json", "-o", out, "--frames", "100000", "--scale", "0.1"}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("--frames: 100000 frames"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("drawing budget"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--budget F"), std::string::npos) << r.err;
    EXPECT_TRUE(names_in(dir.path() / "out").empty()) << out << ": " << joined(hidden_in(dir.path() / "out"));
  }
}

// Issue 60: 30 frames of a 1000-keyframe track paced by arc length span by
// span took more than a minute, four times the motion's build (seconds) for
// the layout and the frames. It is built once: the animation takes about as
// long as `pita render` of the scene. (Under the sanitizers, the first 300
// keyframes.)
TEST(AnimateBudget, ALongTrackPacedByArcLengthIsBuiltOnce) {
  const ScratchDir dir;
  Json scene =
      Json::parse(read_file(fs::path(PITA_SOURCE_DIR) / "tests/data/long-tracks/arc-length-per-span-1000.json"));
  ASSERT_EQ(scene["keyframes"].size(), 1000u);
  if (kUnderSanitizers) scene["keyframes"].erase(scene["keyframes"].begin() + 300, scene["keyframes"].end());
  dir.write("long.json", scene.dump());
  const auto timed = [&](const std::vector<std::string>& args) {
    const auto start = std::chrono::steady_clock::now();
    const RunResult r = run_pita(args, dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const double render = timed({"render", "long.json", "-o", "still.svg"});
  const double animate = timed({"animate", "long.json", "-o", "moving.svg", "--quiet"});
  EXPECT_LT(animate, 1.8 * render + 2.0) << "render " << render << " s";
  EXPECT_TRUE(fs::exists(dir.path() / "moving.svg"));
}

// Issue 60: the same track with a moving keyframe is a "pattern" animation,
// whose motion is built anew for each frame and each frame of the layout (63
// builds of seconds each): refused at once, before anything is built, naming
// the timing and --budget F; the still figure (one build) renders.
TEST(AnimateBudget, ALongMovingTrackPacedByArcLengthIsRefusedAtOnce) {
  const ScratchDir dir;
  dir.write("moving.json",
            read_file(fs::path(PITA_SOURCE_DIR) / "tests/data/long-tracks/moving-arc-length-per-span-1000.json"));
  fs::create_directories(dir.path() / "out");
  for (const char* out : {"out/frames", "out/a.svg"}) {
    const auto start = std::chrono::steady_clock::now();
    const RunResult r = run_pita({"animate", "moving.json", "-o", out}, dir.path());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("/timing: the animation would build the motions 63 times"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--budget F"), std::string::npos) << r.err;
    EXPECT_LT(seconds, kUnderSanitizers ? 30.0 : 5.0);
    EXPECT_TRUE(names_in(dir.path() / "out").empty()) << out << ": " << joined(hidden_in(dir.path() / "out"));
  }
}

// A scene whose image is missing (fig23 copied without its images/): exit 2
// naming the image, before any output exists.
TEST(AnimateBadScene, AMissingImageWritesNothing) {
  const ScratchDir dir;
  dir.write("fig23.json", read_file(kFig23));
  fs::create_directories(dir.path() / "out");
  for (const char* out : {"out/frames", "out/a.svg", "out/a.mp4"}) {
    const RunResult r = run_pita({"animate", "fig23.json", "-o", out, "--frames", "3"}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("images/picture.png"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
    EXPECT_TRUE(names_in(dir.path() / "out").empty()) << out << ": " << joined(hidden_in(dir.path() / "out"));
  }
}

// A directory pita did not write (no frames.json) is not replaced: exit 3,
// untouched.
TEST(AnimateFrameDirectory, AForeignDirectoryIsRefusedAndLeftAlone) {
  const ScratchDir dir;
  fs::create_directories(dir.path() / "out/frames/sub");
  dir.write("out/frames/notes.txt", "mine");
  dir.write("out/frames/sub/data", "also mine");
  const RunResult r = run_pita({"animate", kFig23.string(), "-o", "out/frames", "--frames", "3"}, dir.path());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("out/frames"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("frames.json"), std::string::npos) << r.err;
  EXPECT_EQ(names_in(dir.path() / "out/frames"), (std::set<std::string>{"notes.txt", "sub"}));
  EXPECT_EQ(read_file(dir.path() / "out/frames/notes.txt"), "mine");
  EXPECT_EQ(read_file(dir.path() / "out/frames/sub/data"), "also mine");
  EXPECT_EQ(names_in(dir.path() / "out"), (std::set<std::string>{"frames"}));  // no temporary left
  // A file in the way is refused too.
  dir.write("out/file", "a file");
  const RunResult file = run_pita({"animate", kFig23.string(), "-o", "out/file", "--frames", "3"}, dir.path());
  EXPECT_EQ(file.exit_code, 3) << file.err;
  EXPECT_EQ(read_file(dir.path() / "out/file"), "a file");
  EXPECT_EQ(names_in(dir.path() / "out"), (std::set<std::string>{"file", "frames"}));
}

// A frame directory of an earlier run is replaced whole: its extra frames are
// gone, and no temporary (the older frames, swapped out) remains.
TEST(AnimateFrameDirectory, AnEarlierRunIsReplaced) {
  const ScratchDir dir;
  const RunResult first = run_pita({"animate", kFig23.string(), "-o", "out/frames", "--frames", "5"}, dir.path());
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const RunResult second = run_pita({"animate", kFig23.string(), "-o", "out/frames/", "--frames", "3"}, dir.path());
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_EQ(names_in(dir.path() / "out/frames"),
            (std::set<std::string>{"frame-0001.png", "frame-0002.png", "frame-0003.png", "frames.json"}));
  EXPECT_EQ(read_json(dir.path() / "out/frames/frames.json").at("frames").get<int>(), 3);
  EXPECT_EQ(names_in(dir.path() / "out"), (std::set<std::string>{"frames"}));
  EXPECT_EQ(permissions_of(dir.path() / "out/frames"), 0777 & ~current_umask());
  // An empty directory is taken as well.
  fs::create_directories(dir.path() / "out/empty");
  const RunResult empty = run_pita({"animate", kFig23.string(), "-o", "out/empty", "--frames", "2"}, dir.path());
  ASSERT_EQ(empty.exit_code, 0) << empty.err;
  EXPECT_EQ(names_in(dir.path() / "out/empty"),
            (std::set<std::string>{"frame-0001.png", "frame-0002.png", "frames.json"}));
  EXPECT_EQ(names_in(dir.path() / "out"), (std::set<std::string>{"empty", "frames"}));
}

// Only what pita's frame writer makes is ever replaced: a frame directory with
// a file of the user's in it, a folder holding some other frames.json, and a
// file named with a trailing slash are refused (exit 3) and left as they were.
TEST(AnimateFrameDirectory, NothingButPitasOwnFramesIsReplaced) {
  const ScratchDir dir;
  ASSERT_EQ(run_pita({"animate", kFig23.string(), "-o", "out/frames", "--frames", "2"}, dir.path()).exit_code, 0);
  dir.write("out/frames/notes.txt", "mine");
  const RunResult user_file = run_pita({"animate", kFig23.string(), "-o", "out/frames", "--frames", "2"}, dir.path());
  EXPECT_EQ(user_file.exit_code, 3) << user_file.err;
  EXPECT_EQ(read_file(dir.path() / "out/frames/notes.txt"), "mine");
  EXPECT_TRUE(fs::exists(dir.path() / "out/frames/frame-0002.png"));

  fs::create_directories(dir.path() / "proj/src");
  dir.write("proj/frames.json", "{}");
  dir.write("proj/src/main.c", "code");
  const RunResult project = run_pita({"animate", kFig23.string(), "-o", "proj", "--frames", "2"}, dir.path());
  EXPECT_EQ(project.exit_code, 3) << project.err;
  EXPECT_EQ(read_file(dir.path() / "proj/src/main.c"), "code");
  EXPECT_EQ(read_file(dir.path() / "proj/frames.json"), "{}");

  dir.write("victim.txt", "precious");
  const RunResult slash = run_pita({"animate", kFig23.string(), "-o", "victim.txt/", "--frames", "2"}, dir.path());
  EXPECT_EQ(slash.exit_code, 3) << slash.err;
  EXPECT_NE(slash.err.find("not a directory"), std::string::npos) << slash.err;
  EXPECT_EQ(read_file(dir.path() / "victim.txt"), "precious");
  EXPECT_TRUE(hidden_in(dir.path()).empty()) << joined(hidden_in(dir.path()));
}

// A PNG whose header is good but whose data is cut short passes the reader's
// checks and fails when cairo decodes it: exit 2 naming the scene and the
// image's pointer, before any output exists.
TEST(AnimateBadScene, ACorruptImageIsNamedByItsPointer) {
  const ScratchDir dir;
  const std::string png = read_file(fs::path(PITA_SOURCE_DIR) / "scenes/images/picture.png");
  fs::create_directories(dir.path() / "images");
  dir.write("images/picture.png", png.substr(0, png.size() / 2));
  dir.write("fig23.json", read_file(kFig23));
  for (const char* out : {"frames", "a.svg"}) {
    const RunResult r = run_pita({"animate", "fig23.json", "-o", out, "--frames", "2"}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("fig23.json: /shapes/0/image: cannot read the image"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("corrupt PNG"), std::string::npos) << r.err;  // not "out of memory" (issue 37)
    EXPECT_EQ(r.err.find("out of memory"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir.path() / out));
  }
  const RunResult render = run_pita({"render", "fig23.json", "-o", "x.png"}, dir.path());
  EXPECT_EQ(render.exit_code, 2) << render.err;
  EXPECT_NE(render.err.find("/shapes/0/image"), std::string::npos) << render.err;
  EXPECT_FALSE(fs::exists(dir.path() / "x.png"));
}

// Flags that are not numbers, or numbers that make no animation.
TEST(AnimateBadInput, NonsenseNumbersAreNamed) {
  const ScratchDir dir;
  const auto refused = [&](std::vector<std::string> args, const std::string& flag) {
    const RunResult r = run_pita(args, dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(flag), std::string::npos) << r.err;
  };
  refused({"animate", kFig23.string(), "-o", "a.svg", "--fps", "1e-300", "--frames", "2"}, "--fps");
  refused({"animate", kFig23.string(), "-o", "a.svg", "--budget", "nan"}, "--budget");
  refused({"animate", kFig23.string(), "-o", ""}, "-o");
  refused({"animate", kFig23.string(), "-o", "."}, "-o");
  refused({"render", kFig23.string(), "-o", "a.png", "--at", "nan"}, "--at");
  refused({"render", kFig23.string(), "-o", "a.png", "--at", "inf"}, "--at");
  refused({"render", kFig23.string(), "-o", "a.png", "--budget", "nan"}, "--budget");
  EXPECT_TRUE(names_in(dir.path()).empty()) << joined(hidden_in(dir.path()));
}

// ------------------------------------------------------------ 7. interrupted runs

template <class Condition>
bool wait_until(Condition condition, std::chrono::milliseconds limit) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (!condition()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(5ms);
  }
  return true;
}

// The command lines of the running processes that contain `text` (ffmpeg's command
// line names its output file), one a line.
std::string processes_naming(const std::string& text) {
  std::string found;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string pid = entry.path().filename().string();
    if (pid.find_first_not_of("0123456789") != std::string::npos) continue;
    std::string command = read_file(entry.path() / "cmdline");
    std::replace(command.begin(), command.end(), '\0', ' ');
    if (command.find(text) != std::string::npos) found += pid + ": " + command + "\n";
  }
  return found;
}

struct InterruptCase {
  const char* name;
  std::string out;  // in the folder "out"
  int signal;
};
void PrintTo(const InterruptCase& c, std::ostream* os) { *os << c.name; }

class AnimateInterrupt : public ::testing::TestWithParam<InterruptCase> {};

// A long job (3000 frames of fig23), signalled once its temporary is being
// filled (for the SVG, built in memory: after a second): pita exits with
// 128 + signal, and neither OUT nor any temporary remains.
TEST_P(AnimateInterrupt, LeavesNothingAndExits128PlusSignal) {
  const InterruptCase& c = GetParam();
  if ((c.out.ends_with(".mp4") || c.out.ends_with(".webm")) && !have_program("ffmpeg")) {
    GTEST_SKIP() << "ffmpeg is not installed (Debian package ffmpeg)";
  }
  const ScratchDir dir;
  fs::create_directories(dir.path() / "out");
  dir.write("out/keep.txt", "other work");
  const auto start = std::chrono::steady_clock::now();
  // The SVG is built in memory, 4 times faster than PNG frames: more of them.
  // (12 000 vector frames exceed the default limit of 5000: --budget 3 allows them.)
  const std::string frames = c.out.ends_with(".svg") ? "12000" : "3000";
  Started started =
      start_pita({"animate", kFig23.string(), "-o", "out/" + c.out, "--frames", frames, "--budget", "3"}, dir.path());
  std::string temporary;
  if (!c.out.ends_with(".svg")) {
    ASSERT_TRUE(wait_until([&] { return !hidden_in(dir.path() / "out").empty(); }, 60s)) << "no temporary appeared";
    temporary = hidden_in(dir.path() / "out").front();
    EXPECT_EQ(temporary.rfind("." + c.out + ".", 0), 0u) << temporary;
  }
  std::this_thread::sleep_until(std::max(start + 1s, std::chrono::steady_clock::now() + 300ms));
  ASSERT_EQ(::waitpid(started.pid, nullptr, WNOHANG), 0) << "pita ended before the signal";
  ASSERT_EQ(::kill(started.pid, c.signal), 0);
  int status = 0;
  const RunResult r = finish_pita(started, &status);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 128 + c.signal) << r.err;
  const std::string name = c.signal == SIGINT ? "SIGINT" : "SIGTERM";
  EXPECT_NE(r.err.find("pita: interrupted (" + name + ")"), std::string::npos) << r.err;
  EXPECT_EQ(names_in(dir.path() / "out"), (std::set<std::string>{"keep.txt"}))
      << "left: " << joined(hidden_in(dir.path() / "out"));
  EXPECT_EQ(read_file(dir.path() / "out/keep.txt"), "other work");
  if (!temporary.empty()) {
    EXPECT_EQ(processes_naming(temporary), "") << "ffmpeg was left running";
  }
}

INSTANTIATE_TEST_SUITE_P(Jobs, AnimateInterrupt,
                         ::testing::Values(InterruptCase{"directory_SIGTERM", "frames", SIGTERM},
                                           InterruptCase{"directory_SIGINT", "frames", SIGINT},
                                           InterruptCase{"mp4_SIGTERM", "clip.mp4", SIGTERM},
                                           InterruptCase{"mp4_SIGINT", "clip.mp4", SIGINT},
                                           InterruptCase{"svg_SIGTERM", "a.svg", SIGTERM}),
                         [](const ::testing::TestParamInfo<InterruptCase>& param) { return param.param.name; });

// An interrupted run over an earlier frame directory leaves it as it was.
TEST(AnimateInterruptOverOlder, TheEarlierFramesStay) {
  const ScratchDir dir;
  const RunResult first = run_pita({"animate", kFig23.string(), "-o", "frames", "--frames", "2"}, dir.path());
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const std::string index = read_file(dir.path() / "frames/frames.json");
  Started started = start_pita({"animate", kFig23.string(), "-o", "frames", "--frames", "3000"}, dir.path());
  ASSERT_TRUE(wait_until([&] { return !hidden_in(dir.path()).empty(); }, 60s)) << "no temporary appeared";
  std::this_thread::sleep_for(300ms);
  ASSERT_EQ(::kill(started.pid, SIGTERM), 0);
  int status = 0;
  const RunResult r = finish_pita(started, &status);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM) << r.err;
  EXPECT_TRUE(hidden_in(dir.path()).empty()) << joined(hidden_in(dir.path()));
  EXPECT_EQ(names_in(dir.path() / "frames"),
            (std::set<std::string>{"frame-0001.png", "frame-0002.png", "frames.json"}));
  EXPECT_EQ(read_file(dir.path() / "frames/frames.json"), index);
}

// ------------------------------------------------------------ 8. progress bar

// On a terminal (util-linux `script` gives pita a pty) stderr shows the bar;
// --quiet silences it, and so does CI=true (a CI service's terminal). stdout
// goes to a file, so that the pty carries stderr only. (Without a terminal
// stderr stays empty: the tests above.)
TEST(AnimateProgressBar, ShownOnATerminalOnly) {
  if (!have_program("script")) GTEST_SKIP() << "util-linux `script` is not installed: no pty to test the bar on";
  const ScratchDir dir;
  const auto on_pty_env = [&](const std::string& env, const std::string& flags) {
    const std::string inner = fmt::format("env {} {} animate {} -o frames --frames 12 {} >stdout.txt", env,
                                          quoted(pita_binary()), quoted(kFig23.string()), flags);
    return run_command("cd " + quoted(dir.path().string()) + " && script -qec " + quoted(inner) + " /dev/null");
  };
  const CommandResult in_ci = on_pty_env("CI=true", "");
  EXPECT_EQ(in_ci.exit_code, 0) << in_ci.out;
  EXPECT_EQ(in_ci.out.find("%)"), std::string::npos) << "a bar in CI: " << in_ci.out;
  const CommandResult shown = on_pty_env("-u CI", "");
  EXPECT_EQ(shown.exit_code, 0) << shown.out;
  EXPECT_NE(shown.out.find("frames ["), std::string::npos) << shown.out;
  EXPECT_NE(shown.out.find("12/12 (100%)"), std::string::npos) << shown.out;
  EXPECT_NE(read_file(dir.path() / "stdout.txt").find("wrote frames (12 frames"), std::string::npos);
  const CommandResult quiet = on_pty_env("-u CI", "-q");
  EXPECT_EQ(quiet.exit_code, 0) << quiet.out;
  EXPECT_EQ(quiet.out.find("frames ["), std::string::npos) << quiet.out;
  EXPECT_EQ(quiet.out.find("%)"), std::string::npos) << quiet.out;
}

// 3D pose scenes animate as the plane's do (frame k == render --at t_k is in
// AnimateFrameEqualsRenderAt): frames.json records each frame's pose of space
// as the 3x4 rows `pita eval` prints at that time, the first pose at the
// first knot.
TEST(AnimateSpace, FramesRecordThePoseInSpace) {
  const ScratchDir dir;
  const fs::path scene = kScenes / "sam-3d-fig13-polysam.json";
  const RunResult animate = run_pita({"animate", scene.string(), "-o", "frames", "--frames", "4", "-q"}, dir.path());
  ASSERT_EQ(animate.exit_code, 0) << animate.err;
  const Json index = read_json(dir.path() / "frames/frames.json");
  const Json& records = index.at("frame_list");
  ASSERT_EQ(records.size(), 4u);
  std::string times;
  for (const Json& record : records) times += (times.empty() ? "" : ",") + record.at("t").dump();
  const RunResult eval = run_pita({"eval", scene.string(), "--t", times}, dir.path());
  ASSERT_EQ(eval.exit_code, 0) << eval.err;
  const Json frames = Json::parse(eval.out).at("frames");
  ASSERT_EQ(frames.size(), 4u);
  const Json first_pose = read_json(scene).at("poses").at(0);
  EXPECT_EQ(records.at(0).at("t").get<double>(), first_pose.at("t").get<double>());
  for (std::size_t k = 0; k < 4; ++k) {
    const Json& A = records.at(k).at("A");
    ASSERT_EQ(A.size(), 3u) << A.dump();
    for (std::size_t r = 0; r < 3; ++r) {
      ASSERT_EQ(A.at(r).size(), 4u) << A.dump();
      for (std::size_t c = 0; c < 4; ++c) {
        EXPECT_NEAR(A.at(r).at(c).get<double>(), frames.at(k).at("matrix").at(r).at(c).get<double>(), 1e-12)
            << "frame " << k + 1 << " row " << r << " column " << c;
        if (k == 0) {
          EXPECT_NEAR(A.at(r).at(c).get<double>(), first_pose.at("matrix").at(r).at(c).get<double>(), 1e-12);
        }
      }
    }
    EXPECT_TRUE(fs::is_regular_file(dir.path() / "frames" / records.at(k).at("file").get<std::string>()));
  }
  // The same scene as a video's worth of frames in one animated SVG.
  const RunResult svg = run_pita({"animate", scene.string(), "-o", "tumble.svg", "--frames", "6", "-q"}, dir.path());
  ASSERT_EQ(svg.exit_code, 0) << svg.err;
  EXPECT_NE(read_file(dir.path() / "tumble.svg").find("</svg>"), std::string::npos);
}

}  // namespace
}  // namespace pita::test
