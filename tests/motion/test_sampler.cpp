// The sampler (src/motion/sampler.cpp): uniform times and frames.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "motion/sampler.hpp"

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

TEST(UniformTimes, MiddleSampleOfAnOddCountIsTheMidpoint) {
  EXPECT_EQ(uniform_times(0.0, 1.0, 9)[4], 0.5);
}

TEST(UniformTimes, NeedsTwoSamples) {
  EXPECT_THROW(uniform_times(0.0, 1.0, 1), std::invalid_argument);
  EXPECT_THROW(uniform_times(0.0, 1.0, 0), std::invalid_argument);
}

}  // namespace
}  // namespace pita::motion
