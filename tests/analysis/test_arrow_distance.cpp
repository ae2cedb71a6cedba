// analysis/arrow_distance.hpp: the endpoint distance of two arrows and of two
// patterns (Figs. 16, 18, B.30; docs/paper-notes.md N53, N54).
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "analysis/arrow_distance.hpp"

namespace pita::analysis {
namespace {

TEST(EndpointDistance, IsTheLargerMoveOfAnEndpoint) {
  const Arrow A = zero_turn_arrow({0.0, 0.0}, {1.0, 0.0});
  const Arrow B = zero_turn_arrow({0.0, 3.0}, {5.0, 0.0});  // p moves by 3, q by 4
  EXPECT_DOUBLE_EQ(endpoint_distance(A, B), 4.0);
  EXPECT_DOUBLE_EQ(endpoint_distance(B, A), 4.0);
  EXPECT_EQ(endpoint_distance(A, A), 0.0);
  // Windings do not count: the same segment with an extra turn is at distance 0 (to rounding).
  EXPECT_LT(endpoint_distance(A, with_turns(A, 1.0)), 1e-15);
}

TEST(PatternDistance, IsTheLargestOverTheFramesAndRefusesUnequalSizes) {
  const std::vector<Arrow> first{zero_turn_arrow({0.0, 0.0}, {1.0, 0.0}), zero_turn_arrow({2.0, 0.0}, {3.0, 0.0})};
  const std::vector<Arrow> second{zero_turn_arrow({0.0, 0.5}, {1.0, 0.0}), zero_turn_arrow({2.0, 0.0}, {3.0, -2.0})};
  EXPECT_DOUBLE_EQ(pattern_distance(first, second), 2.0);
  EXPECT_EQ(pattern_distance(first, first), 0.0);
  EXPECT_THROW(pattern_distance(first, std::vector<Arrow>{first[0]}), std::invalid_argument);
}

}  // namespace
}  // namespace pita::analysis
