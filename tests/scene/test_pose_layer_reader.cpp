// The layer kinds of pose scenes (src/scene/pose_layer_reader.cpp): each
// kind's fields over its defaults (more in test_pose_reader.cpp, with the poses).
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "scene/color.hpp"
#include "scene/scene.hpp"
#include "scene_test_support.hpp"

namespace pita::scene {
namespace {

using test::only_layer;
using test::p6_with;

// "swept" (SAM Fig. 10): the edge, the parts hidden by false or restyled
// over their defaults, and the claim's place.
TEST(FigureReader, SweptLayer) {
  const Scene scene = parse_scene(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "matrix": [[0, -1, 2], [1, 0, 0]]}], "layers": [{"type": "swept", "edge": [[0, 1], [2, 1]],
      "instants": 5, "trace_samples": 64, "ends": false, "grazing": {"width": 3}, "claim_at": [0, -1]}]})",
                                  "s.json");
  ASSERT_EQ(figure_of<PlanePoseKeys>(scene).layers.size(), 1u);
  const auto& layer = std::get<SweptLayer>(figure_of<PlanePoseKeys>(scene).layers[0]);
  EXPECT_EQ(layer.edge[0], Point(0.0, 1.0));
  EXPECT_EQ(layer.edge[1], Point(2.0, 1.0));
  EXPECT_EQ(layer.instants, 5);
  EXPECT_EQ(layer.trace_samples, 64);
  EXPECT_FALSE(layer.ends.has_value());
  ASSERT_TRUE(layer.grazing.has_value());
  EXPECT_EQ(layer.grazing->width, 3.0);
  EXPECT_EQ(layer.grazing->color, SweptLayer{}.grazing->color);  // unset members keep the default
  ASSERT_TRUE(layer.segments.has_value());
  ASSERT_TRUE(layer.envelope.has_value());
  EXPECT_EQ(layer.claim_at, std::optional<Point>(Point(0.0, -1.0)));
  EXPECT_FALSE(SweptLayer{}.claim_at.has_value());
}

}  // namespace
}  // namespace pita::scene
