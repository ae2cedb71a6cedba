// What `pita animate` writes, by OUT (src/animate/output.cpp). The command's
// behaviour end to end (files, ffmpeg, interrupts) is in tests/cli/test_animate.cpp.
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "animate/output.hpp"
#include "io/output_file.hpp"
#include "render/budget.hpp"
#include "scene/scene.hpp"

namespace pita::animate {
namespace {

namespace fs = std::filesystem;

TEST(Output, KindByExtension) {
  EXPECT_EQ(output_kind("a.svg"), AnimationOutput::svg);
  EXPECT_EQ(output_kind("dir/a.SVG"), AnimationOutput::svg);
  EXPECT_EQ(output_kind("a.mp4"), AnimationOutput::mp4);
  EXPECT_EQ(output_kind("a.webm"), AnimationOutput::webm);
  EXPECT_EQ(output_kind("frames"), AnimationOutput::directory);
  EXPECT_EQ(output_kind("frames.d/"), AnimationOutput::directory);
  EXPECT_THROW(output_kind("a.gif"), AnimationError);
  EXPECT_THROW(output_kind("a.png"), AnimationError);
  try {
    output_kind("movie.avi");
  } catch (const AnimationError& error) {
    EXPECT_NE(std::string(error.what()).find("\".avi\""), std::string::npos) << error.what();
  }
}

TEST(Output, FrameFilesAreNumberedFromOneWithAtLeastFourDigits) {
  EXPECT_EQ(frame_file_name(0, 120, render::Format::png), "frame-0001.png");
  EXPECT_EQ(frame_file_name(119, 120, render::Format::svg), "frame-0120.svg");
  EXPECT_EQ(frame_file_name(0, 100000, render::Format::png), "frame-000001.png");
}

TEST(Output, DirectoryOfFramesWithTheirTimes) {
  const fs::path dir = fs::temp_directory_path() / ("pita-test-output-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const scene::Scene scene = scene::load_scene(fs::path(PITA_SOURCE_DIR) / "scenes" / "fig24-animation-frames.json");
  const Timeline timeline = make_timeline(scene, {std::nullopt, std::nullopt, 5});
  Request request;
  request.out = dir / "frames";
  request.kind = AnimationOutput::directory;
  request.progress = false;
  request.threads = 2;
  write_animation(scene, timeline, request);
  std::ifstream in(dir / "frames" / "frames.json");
  const nlohmann::json index = nlohmann::json::parse(in);
  EXPECT_EQ(index["frames"], 5);
  ASSERT_EQ(index["frame_list"].size(), 5u);
  for (int k = 0; k < 5; ++k) {
    const auto& record = index["frame_list"][static_cast<std::size_t>(k)];
    EXPECT_EQ(record["t"].get<double>(), timeline.time(k));
    EXPECT_TRUE(fs::is_regular_file(dir / "frames" / record["file"].get<std::string>()));
  }
  // nothing else beside it: the temporary directory was renamed into place
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1u);
  // again, fewer frames: the older directory is replaced, its extra frames gone
  write_animation(scene, make_timeline(scene, {std::nullopt, std::nullopt, 3}), request);
  EXPECT_FALSE(fs::exists(dir / "frames" / "frame-0004.png"));
  EXPECT_TRUE(fs::exists(dir / "frames" / "frame-0003.png"));
  entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1u);
  // a file of the user's in it: not pita's own directory any more, refused and kept
  std::ofstream(dir / "frames" / "notes.txt") << "x";
  EXPECT_THROW(write_animation(scene, timeline, request), io::OutputError);
  EXPECT_TRUE(fs::exists(dir / "frames" / "notes.txt"));
  fs::remove_all(dir);
}

TEST(Output, TotalWorkIsLimited) {
  const scene::Scene scene = scene::load_scene(fs::path(PITA_SOURCE_DIR) / "scenes" / "fig24-animation-frames.json");
  Request png;
  png.kind = AnimationOutput::directory;
  // 900 x 640 pixels a frame: 17 361 frames fit in 1e10 pixels, 17 362 do not
  EXPECT_NO_THROW(check_total_work(scene, make_timeline(scene, {std::nullopt, std::nullopt, 17361}), png));
  EXPECT_THROW(check_total_work(scene, make_timeline(scene, {std::nullopt, std::nullopt, 17362}), png), AnimationError);
  png.budget = 2.0;
  EXPECT_NO_THROW(check_total_work(scene, make_timeline(scene, {std::nullopt, std::nullopt, 30000}), png));
  Request svg;
  svg.kind = AnimationOutput::svg;
  EXPECT_NO_THROW(check_total_work(scene, make_timeline(scene, {std::nullopt, std::nullopt, 5000}), svg));
  try {
    check_total_work(scene, make_timeline(scene, {std::nullopt, std::nullopt, 5001}), svg);
    ADD_FAILURE() << "5001 SVG frames accepted";
  } catch (const AnimationError& error) {
    EXPECT_NE(std::string(error.what()).find("--frames"), std::string::npos);
  }
}

// Issue 37: frames x the figure's drawing is bounded too, for every output:
// the frames that fit in kMaxAnimationUnits are accepted, one more is not
// (unless --budget allows it), and the message names --frames and --budget.
TEST(Output, TheFramesDrawingIsLimited) {
  // Two strokes of 10 000 samples under a pattern: a heavy frame.
  const scene::Scene scene = scene::parse_scene(
      R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
          {"t": 1, "p": [4, 1], "m": 2, "w": 1}, {"t": 2, "p": [8, 0], "m": 1, "w": 3}],
          "canvas": {"width": 800, "height": 400},
          "layers": [{"type": "stroke", "samples": 10000}, {"type": "stroke", "samples": 10000, "opacity": 0.5},
                     {"type": "pattern"}]})",
      "heavy.json");
  const double one = render::estimate_cost(scene).units;
  ASSERT_GT(one, 1000.0);
  for (const AnimationOutput kind : {AnimationOutput::directory, AnimationOutput::svg, AnimationOutput::mp4}) {
    Request request;
    request.kind = kind;
    request.scale = 0.1;                                        // the pixel budget is not what limits here
    request.budget = kind == AnimationOutput::svg ? 3.0 : 1.0;  // nor the vector frames' (5000 x 3)
    const int fit = static_cast<int>(kMaxAnimationUnits * request.budget / one);
    ASSERT_LT(fit, 5000 * request.budget);
    EXPECT_NO_THROW(check_total_work(scene, make_timeline(scene, {std::nullopt, std::nullopt, fit}), request));
    try {
      check_total_work(scene, make_timeline(scene, {std::nullopt, std::nullopt, fit + 1}), request);
      ADD_FAILURE() << fit + 1 << " frames accepted";
    } catch (const AnimationError& error) {
      const std::string what = error.what();
      EXPECT_NE(what.find("--frames"), std::string::npos) << what;
      EXPECT_NE(what.find("drawing budget"), std::string::npos) << what;
      EXPECT_NE(what.find("--budget"), std::string::npos) << what;
    }
    request.budget *= 1.01;
    EXPECT_NO_THROW(check_total_work(scene, make_timeline(scene, {std::nullopt, std::nullopt, fit + 1}), request));
  }
}

// The caller says which ffmpeg to run (the CLI reads PITA_FFMPEG and PATH):
// with none, a video is refused naming the package, and nothing is written.
TEST(Output, VideoWithoutFfmpegIsRefusedNamingThePackage) {
  const fs::path dir = fs::temp_directory_path() / ("pita-test-no-ffmpeg-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const scene::Scene scene = scene::load_scene(fs::path(PITA_SOURCE_DIR) / "scenes" / "fig24-animation-frames.json");
  const Timeline timeline = make_timeline(scene, {std::nullopt, std::nullopt, 3});
  for (const AnimationOutput kind : {AnimationOutput::mp4, AnimationOutput::webm}) {
    Request request;
    request.out = dir / (kind == AnimationOutput::mp4 ? "clip.mp4" : "clip.webm");
    request.kind = kind;
    request.progress = false;
    request.ffmpeg = "";
    try {
      write_animation(scene, timeline, request);
      ADD_FAILURE() << "a video without ffmpeg";
    } catch (const AnimationError& error) {
      EXPECT_NE(std::string(error.what()).find("apt-get install ffmpeg"), std::string::npos) << error.what();
    }
  }
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace pita::animate
