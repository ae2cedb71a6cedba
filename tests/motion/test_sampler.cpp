// The sampler (src/motion/sampler.cpp): uniform times and frames.
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"
#include "scene/scene.hpp"

namespace pita::motion {
namespace {

TEST(UniformTimes, EvenlySpacedWithExactEnds) {
  EXPECT_EQ(uniform_times(0.0, 1.0, 5), (std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0}));
  EXPECT_EQ(uniform_times(-1.0, 1.0, 2), (std::vector<double>{-1.0, 1.0}));
  const std::vector<double> times = uniform_times(0.1, 0.7, 7);
  ASSERT_EQ(times.size(), 7u);
  EXPECT_EQ(times.front(), 0.1);
  EXPECT_EQ(times.back(), 0.7);
  for (std::size_t i = 0; i < times.size(); ++i) {
    EXPECT_NEAR(times[i], 0.1 + 0.1 * static_cast<double>(i), 1e-15) << "sample " << i;
  }
}

TEST(UniformTimes, MiddleSampleOfAnOddCountIsTheMidpoint) { EXPECT_EQ(uniform_times(0.0, 1.0, 9)[4], 0.5); }

TEST(UniformTimes, NeedsTwoSamples) {
  EXPECT_THROW(uniform_times(0.0, 1.0, 1), std::invalid_argument);
  EXPECT_THROW(uniform_times(0.0, 1.0, 0), std::invalid_argument);
}

TEST(UniformTimes, OneAtATimeIsTheSameSequence) {
  for (const int count : {2, 3, 9, 1000}) {
    const std::vector<double> all = uniform_times(-0.3, 2.7, count);
    for (int i = 0; i < count; ++i) EXPECT_EQ(uniform_time(-0.3, 2.7, count, i), all[static_cast<std::size_t>(i)]);
  }
}

// Fig. 1's keyframes (P6).
const scene::Scene& fig01() {
  static const scene::Scene scene = scene::parse_scene(R"({"method": "P6", "keyframes": [
    {"t": 0, "p": [0, 0], "m": 1, "w": 0.4}, {"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": 2},
    {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}]})",
                                                       "s.json");
  return scene;
}

TEST(FrameTimes, UniformTimesComputedWhenAsked) {
  const SceneMotion motion = build_motion(fig01());
  const FrameTimes lazy(motion, 37);
  const std::vector<double> all = uniform_times(motion, 37);
  ASSERT_EQ(lazy.size(), all.size());
  for (std::size_t i = 0; i < all.size(); ++i) EXPECT_EQ(lazy.at(i), all[i]) << i;
  EXPECT_THROW(FrameTimes(motion, 1), std::invalid_argument);
}

// The streamed text arrives in chunks of about kFramesChunkBytes and joins
// into the document the whole-text writer prints for the same frames.
TEST(WriteFrames, ChunksJoinIntoTheWholeDocument) {
  const SceneMotion motion = build_motion(fig01());
  const std::vector<double> times = uniform_times(motion, 5000);
  for (const FramesFormat format : {FramesFormat::json, FramesFormat::csv}) {
    std::vector<std::string> chunks;
    write_frames(scene::scene_panel(fig01()), motion, FrameTimes(motion, 5000), format,
                 TextSink{[&](std::string_view bytes) { chunks.emplace_back(bytes); }, false});
    ASSERT_GT(chunks.size(), 2u);
    std::string joined;
    for (std::size_t i = 0; i < chunks.size(); ++i) {
      if (i + 1 < chunks.size()) {
        EXPECT_GE(chunks[i].size(), kFramesChunkBytes) << i;
        EXPECT_LT(chunks[i].size(), kFramesChunkBytes + 1024) << i;  // a row more at most
      }
      joined += chunks[i];
    }
    const std::vector<Frame> frames = sample_arrows(motion, times);
    EXPECT_EQ(joined,
              format == FramesFormat::json ? scene::frames_to_json("P6", frames) : scene::frames_to_csv(frames));
  }
}

// Standard output cannot take bytes back: a frame that is not finite, even
// the last of many chunks' worth, is found before anything is written.
TEST(WriteFrames, AnIrrevocableSinkGetsNothingWhenALateFrameIsNotFinite) {
  const SceneMotion motion = build_motion(fig01());
  std::vector<double> times = uniform_times(motion, 5000);
  times.push_back(1e300);  // extrapolated this far, the frame overflows
  std::size_t written = 0;
  const TextSink irrevocable{[&](std::string_view bytes) { written += bytes.size(); }, false};
  EXPECT_THROW(write_frames(scene::scene_panel(fig01()), motion, FrameTimes(times), FramesFormat::csv, irrevocable),
               std::exception);
  EXPECT_EQ(written, 0u);
  // A sink that drops what it got on a throw is written to as frames come.
  const TextSink droppable{[&](std::string_view bytes) { written += bytes.size(); }, true};
  EXPECT_THROW(write_frames(scene::scene_panel(fig01()), motion, FrameTimes(times), FramesFormat::csv, droppable),
               std::exception);
  EXPECT_GT(written, kFramesChunkBytes);
}

}  // namespace
}  // namespace pita::motion
