// Frames rendered in parallel and consumed in order (src/animate/frame_runner.cpp).
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "animate/frame_runner.hpp"

namespace pita::animate {
namespace {

TEST(FrameRunner, ConsumesEveryFrameInOrder) {
  std::vector<int> order;
  run_frames(
      50, 3,
      [](int k) {
        // uneven work: later frames often finish first
        std::this_thread::sleep_for(std::chrono::microseconds((k * 7919) % 500));
        return std::to_string(k);
      },
      [&](int k, std::string&& bytes) {
        EXPECT_EQ(bytes, std::to_string(k));
        order.push_back(k);
      });
  ASSERT_EQ(order.size(), 50u);
  for (int k = 0; k < 50; ++k) EXPECT_EQ(order[static_cast<std::size_t>(k)], k);
}

TEST(FrameRunner, HoldsABoundedNumberOfFrames) {
  // The consumer is slow: workers must not run ahead by more than the window.
  std::atomic<int> rendered{0};
  std::atomic<int> most_ahead{0};
  int consumed = 0;
  run_frames(
      40, 2,
      [&](int k) {
        ++rendered;
        return std::string(1, static_cast<char>('a' + k % 26));
      },
      [&](int, std::string&&) {
        ++consumed;
        most_ahead = std::max(most_ahead.load(), rendered.load() - consumed);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      });
  EXPECT_EQ(consumed, 40);
  EXPECT_LE(most_ahead.load(), 2 * 2);
}

TEST(FrameRunner, TheFirstFailureStopsTheRestAndIsRethrown) {
  std::atomic<int> rendered{0};
  EXPECT_THROW(run_frames(
                   1000, 2,
                   [&](int k) -> std::string {
                     ++rendered;
                     if (k == 5) throw std::runtime_error("frame 5 is bad");
                     return "x";
                   },
                   [](int, std::string&&) {}),
               std::runtime_error);
  EXPECT_LT(rendered.load(), 100);
}

TEST(FrameRunner, AFailingConsumerStopsTheWorkers) {
  EXPECT_THROW(run_frames(
                   1000, 2, [](int) { return std::string("x"); },
                   [](int k, std::string&&) {
                     if (k == 3) throw std::runtime_error("disk full");
                   }),
               std::runtime_error);
}

}  // namespace
}  // namespace pita::animate
