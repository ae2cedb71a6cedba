// The family of layers as the kind of a figure scene (src/scene/layer_family.hpp).
#include <gtest/gtest.h>

#include "scene/layer_family.hpp"

namespace pita::scene {
namespace {

// Pose scenes' shapes have an area; arrow scenes' keyframes may move.
TEST(LayerFamily, PoseScenesMovePoses) {
  EXPECT_FALSE(LayerFamily<Layer>::moves_poses);
  EXPECT_TRUE(LayerFamily<PoseLayer>::moves_poses);
}

}  // namespace
}  // namespace pita::scene
