// The places of pita serve's event streams and requests being received
// (src/serve/oldest_first.hpp): one more than the capacity tells the oldest
// holder to leave, never a newer one.
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "serve/oldest_first.hpp"

namespace pita::serve {
namespace {

TEST(OldestFirst, OneMoreThanTheCapacityTellsTheOldestToLeave) {
  OldestFirst places(3);
  std::vector<std::unique_ptr<Place>> held;
  for (int i = 0; i < 3; ++i) held.push_back(std::make_unique<Place>(places));
  for (const auto& place : held) EXPECT_FALSE(place->told_to_leave());
  held.push_back(std::make_unique<Place>(places));
  EXPECT_TRUE(held[0]->told_to_leave());
  for (std::size_t i = 1; i < held.size(); ++i) EXPECT_FALSE(held[i]->told_to_leave()) << i;
  EXPECT_EQ(places.held(), 3U);
  // A holder that leaves frees its place: the next one tells no one.
  held[2].reset();
  held.push_back(std::make_unique<Place>(places));
  EXPECT_FALSE(held[1]->told_to_leave());
  EXPECT_FALSE(held[3]->told_to_leave());
  // A flood: the newest always holds a place.
  for (int i = 0; i < 100; ++i) held.push_back(std::make_unique<Place>(places));
  EXPECT_FALSE(held.back()->told_to_leave());
  EXPECT_TRUE(held[1]->told_to_leave());
  held.clear();
  EXPECT_EQ(places.held(), 0U);
}

}  // namespace
}  // namespace pita::serve
