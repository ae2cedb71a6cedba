// The "vectors" and "fixed-points" layers of src/scene/arrow_layer_reader.cpp:
// defaults that follow the paper's figures (Figs. 9, 14, 15), the fields, and
// the errors with their pointers.
#include <string>
#include <variant>

#include <gtest/gtest.h>

#include "scene/color.hpp"
#include "scene/scene.hpp"
#include "scene_test_support.hpp"

namespace pita::scene {
namespace {

using test::error_of;
using test::only_layer;
using test::p6_with;

TEST(VectorsLayerReader, AccelerationsBlackAndBrownByDefault) {
  const VectorsLayer layer = only_layer<VectorsLayer>(R"({"type": "vectors"})");
  EXPECT_EQ(layer.of, VectorKind::acceleration);
  EXPECT_TRUE(layer.at_p && layer.at_q && layer.tail_at_point && layer.heads);
  EXPECT_EQ(layer.color_p, parse_color("black"));
  EXPECT_EQ(layer.color_q, parse_color("brown"));
  EXPECT_EQ(layer.scale, 0.1);
}

TEST(VectorsLayerReader, VelocitiesDarkGreenByDefault) {
  const VectorsLayer layer = only_layer<VectorsLayer>(R"({"type": "vectors", "of": "velocity"})");
  EXPECT_EQ(layer.of, VectorKind::velocity);
  EXPECT_EQ(layer.color_p, parse_color("#006400"));
  EXPECT_EQ(layer.color_q, parse_color("#006400"));
  EXPECT_EQ(layer.scale, 0.25);
}

TEST(VectorsLayerReader, EveryField) {
  const VectorsLayer layer = only_layer<VectorsLayer>(
      R"({"type": "vectors", "of": "velocity", "at": "q", "at_point": "head", "scale": 2, "colors": ["red"],
          "width": 3, "opacity": 0.5, "dash": [2, 1], "heads": false, "samples": 5, "range": [0.2, 0.8]})");
  EXPECT_FALSE(layer.at_p);
  EXPECT_TRUE(layer.at_q);
  EXPECT_FALSE(layer.tail_at_point);
  EXPECT_EQ(layer.scale, 2.0);
  EXPECT_EQ(layer.color_p, parse_color("red"));
  EXPECT_EQ(layer.color_q, parse_color("red"));  // one colour: both points
  EXPECT_EQ(layer.line.width, 3.0);
  EXPECT_EQ(layer.line.opacity, 0.5);
  EXPECT_EQ(layer.line.dash, (std::vector<double>{2.0, 1.0}));
  EXPECT_FALSE(layer.heads);
  EXPECT_EQ(layer.samples, 5);
  ASSERT_TRUE(layer.range);
  EXPECT_EQ(layer.range->from, 0.2);
  const VectorsLayer two = only_layer<VectorsLayer>(R"({"type": "vectors", "at": "p", "colors": ["red", "blue"]})");
  EXPECT_TRUE(two.at_p);
  EXPECT_FALSE(two.at_q);
  EXPECT_EQ(two.color_q, parse_color("blue"));
}

TEST(VectorsLayerReader, Errors) {
  const auto error = [](const std::string& layer) { return error_of(p6_with(R"(, "layers": [)" + layer + "]")); };
  EXPECT_EQ(error(R"({"type": "vectors", "of": "jerk"})"),
            "s.json: /layers/0/of: must be \"velocity\" or \"acceleration\" (got string \"jerk\")");
  EXPECT_NE(error(R"({"type": "vectors", "colors": []})").find("/layers/0/colors: must be an array of 1 or 2 colors"),
            std::string::npos);
  EXPECT_NE(error(R"({"type": "vectors", "colors": ["red", "red", "red"]})").find("/layers/0/colors"),
            std::string::npos);
  EXPECT_NE(error(R"({"type": "vectors", "scale": 0})").find("/layers/0/scale"), std::string::npos);
  EXPECT_NE(error(R"({"type": "vectors", "at_point": "middle"})").find("/layers/0/at_point"), std::string::npos);
  // A field of another layer kind says so.
  EXPECT_NE(
      error(R"({"type": "vectors", "center": "global"})").find("field \"center\" is not used by a \"vectors\" layer"),
      std::string::npos);
}

TEST(FixedPointsLayerReader, DefaultsAndFields) {
  const FixedPointsLayer plain = only_layer<FixedPointsLayer>(R"({"type": "fixed-points"})");
  EXPECT_EQ(plain.center, CenterKind::acceleration);
  EXPECT_EQ(plain.point, TrackedPoint::start);
  EXPECT_EQ(plain.line.color, parse_color("orange"));
  EXPECT_TRUE(plain.dots);
  const FixedPointsLayer layer = only_layer<FixedPointsLayer>(
      R"({"type": "fixed-points", "center": "global", "point": "mid", "color": "red", "dots": false, "samples": 4})");
  EXPECT_EQ(layer.center, CenterKind::global);
  EXPECT_EQ(layer.point, TrackedPoint::middle);
  EXPECT_EQ(layer.line.color, parse_color("red"));
  EXPECT_FALSE(layer.dots);
  EXPECT_EQ(layer.samples, 4);
  EXPECT_EQ(only_layer<FixedPointsLayer>(R"({"type": "fixed-points", "center": "velocity"})").center,
            CenterKind::velocity);
  EXPECT_NE(error_of(p6_with(R"(, "layers": [{"type": "fixed-points", "center": "local"}])"))
                .find("/layers/0/center: must be \"global\", \"acceleration\" or \"velocity\""),
            std::string::npos);
}

}  // namespace
}  // namespace pita::scene
