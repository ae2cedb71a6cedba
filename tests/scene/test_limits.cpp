// The limits of scene/limits.hpp: each is enforced at its bound (the value at
// the bound is accepted, one step beyond is refused with the field's pointer).
#include <string>

#include <gtest/gtest.h>

#include "scene/limits.hpp"
#include "scene/scene.hpp"
#include "scene_test_support.hpp"

namespace pita::scene {
namespace {

using test::kKeyframes;

std::string pointer_of(const std::string& extra) {
  try {
    parse_scene(R"({"method": "P6", )" + kKeyframes + extra + "}", "s.json");
  } catch (const SceneError& error) {
    return error.pointer();
  }
  return "(no error)";
}

std::string n(long long x) { return std::to_string(x); }

TEST(Limits, SamplesAtTheirBounds) {
  EXPECT_EQ(pointer_of(R"(, "samples": )" + n(kMinSamples)), "(no error)");
  EXPECT_EQ(pointer_of(R"(, "samples": )" + n(kMaxSamples)), "(no error)");
  EXPECT_EQ(pointer_of(R"(, "samples": )" + n(kMinSamples - 1)), "/samples");
  EXPECT_EQ(pointer_of(R"(, "samples": )" + n(kMaxSamples + 1)), "/samples");
}

TEST(Limits, CanvasSides) {
  EXPECT_EQ(pointer_of(R"(, "canvas": {"width": )" + n(kMaxCanvasSide) + "}"), "(no error)");
  EXPECT_EQ(pointer_of(R"(, "canvas": {"width": )" + n(kMaxCanvasSide + 1) + "}"), "/canvas/width");
  EXPECT_EQ(pointer_of(R"(, "canvas": {"height": )" + n(kMinCanvasSide - 1) + "}"), "/canvas/height");
  EXPECT_EQ(pointer_of(R"(, "canvas": {"columns": )" + n(kMaxColumns + 1) + "}"), "/canvas/columns");
}

TEST(Limits, FigureAndTrajectorySamples) {
  EXPECT_EQ(pointer_of(R"(, "layers": [{"type": "pattern", "samples": )" + n(kMaxFigureSamples) + "}]"), "(no error)");
  EXPECT_EQ(pointer_of(R"(, "layers": [{"type": "pattern", "samples": )" + n(kMaxFigureSamples + 1) + "}]"),
            "/layers/0/samples");
  EXPECT_EQ(pointer_of(R"(, "layers": [{"type": "trajectory", "samples": )" + n(kMaxTrajectorySamples + 1) + "}]"),
            "/layers/0/samples");
  EXPECT_EQ(pointer_of(R"(, "layers": [{"type": "plot", "box": {"min": [0, 0], "max": [1, 1]}, "samples": )" +
                       n(kMaxTrajectorySamples + 1) + "}]"),
            "/layers/0/samples");
}

TEST(Limits, LayersAndPanels) {
  std::string layers, panels;
  for (int i = 0; i <= kMaxLayers; ++i) layers += std::string(i ? ", " : "") + R"({"type": "pattern"})";
  for (int i = 0; i <= kMaxPanels; ++i) panels += std::string(i ? ", " : "") + R"("P1")";
  EXPECT_EQ(pointer_of(", \"layers\": [" + layers + "]"), "/layers");
  EXPECT_EQ(pointer_of(", \"panels\": [" + panels + "]"), "/panels");
}

TEST(Limits, ExistenceAndPatchSides) {  // and the 3D existence plot's steps
  const auto pose = [](const std::string& layer) {
    try {
      parse_scene(R"({"method": "SAM", "layers": [)" + layer + "]}", "s.json");
    } catch (const SceneError& error) {
      return error.pointer();
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(pose(R"({"type": "existence", "columns": )" + n(kMaxExistenceSide) + R"(, "rows": 2})"), "(no error)");
  EXPECT_EQ(pose(R"({"type": "existence", "columns": )" + n(kMaxExistenceSide + 1) + "}"), "/layers/0/columns");
  EXPECT_EQ(pose(R"({"type": "existence", "columns": 4000, "rows": 1001})"), "/layers/0/rows");  // cells
  EXPECT_EQ(pose(R"({"type": "patch", "rows": )" + n(kMaxPatchSide + 1) + "}"), "/layers/0/rows");
  EXPECT_EQ(pose(R"({"type": "sam3d-existence", "steps": )" + n(kMaxSam3dExistenceSteps) + "}"), "(no error)");
  EXPECT_EQ(pose(R"({"type": "sam3d-existence", "steps": )" + n(kMaxSam3dExistenceSteps + 1) + "}"), "/layers/0/steps");
  EXPECT_EQ(pose(R"({"type": "sam3d-existence", "subdivisions": )" + n(kMaxSam3dExistenceSubdivisions + 1) + "}"),
            "/layers/0/subdivisions");
}

}  // namespace
}  // namespace pita::scene
