// The table of pose methods (src/core/pose_method.cpp).
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "core/pose_method.hpp"

namespace pita {
namespace {

TEST(PoseMethodTable, IdsAreUniqueAndEveryMethodHasItsRow) {
  std::set<std::string> ids;
  for (const PoseMethodInfo& entry : all_pose_methods()) {
    EXPECT_TRUE(ids.insert(std::string(entry.id)).second) << entry.id;
    EXPECT_EQ(info(entry.method).id, entry.id);
    EXPECT_LE(entry.min_poses, entry.max_poses);
  }
}

// The SAM family (with the pose PITAs) moves poses of space; the Fig. 2 morphs and Alexa's blend,
// defined with the reference triangle or 2x2 logs, only those of the plane.
TEST(PoseMethodTable, TheSamFamilyIsTheOneInSpace) {
  std::set<std::string> space;
  for (const PoseMethodInfo& entry : all_pose_methods()) {
    if (entry.in_space) space.insert(std::string(entry.id));
  }
  EXPECT_EQ(space, (std::set<std::string>{"SAM", "polySAM", "bezier-SAM", "biarc-SAM", "linear", "four-point-SAM", "P4",
                                          "P5", "P6", "P9"}));
}

}  // namespace
}  // namespace pita
