// The layers of an animation's frames drawn once (render/static_layers.hpp):
// frames drawn with the cache are the frames drawn without it, the layers
// that read the frame are drawn at each frame, the others are copied from the
// cache, and the static figure never uses it.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../core/pose_test_support.hpp"
#include "motion/stage.hpp"
#include "render/figure.hpp"
#include "render/projection.hpp"
#include "render/static_layers.hpp"
#include "render_support.hpp"

namespace pita::render::test {
namespace {

// Items and legends, compared whole (a legend by its place, size and lines).
void expect_same(const std::vector<Drawing>& a, const std::vector<Drawing>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_TRUE(a[i].items == b[i].items) << "panel " << i;
    ASSERT_EQ(a[i].legends.size(), b[i].legends.size()) << "panel " << i;
    for (std::size_t k = 0; k < a[i].legends.size(); ++k) {
      const Legend &x = a[i].legends[k], &y = b[i].legends[k];
      EXPECT_EQ(x.layer, y.layer);
      EXPECT_EQ(x.size, y.size);
      ASSERT_EQ(x.entries.size(), y.entries.size());
      for (std::size_t e = 0; e < x.entries.size(); ++e) EXPECT_EQ(x.entries[e].text, y.entries[e].text);
    }
  }
}

// Two panels: keyframes (read nothing of the frame), a pattern (moves), a
// label, and the keyframes' legend.
scene::Scene arrow_scene() {
  scene::LabelLayer label;
  label.text = "P6";
  label.at = {1.0, 2.0};
  scene::Scene s = scene_with({scene::KeyframesLayer{}, scene::PatternLayer{}, label, scene::LegendLayer{}},
                              {panel(Method::P6, three_keyframes()), panel(Method::P1, three_keyframes())});
  return s;
}

TEST(StaticLayers, FramesDrawnWithTheCacheAreTheFramesDrawnWithout) {
  const scene::Scene s = arrow_scene();
  const motion::Stage stage(s);
  StaticLayers cache;
  for (double t : {0.0, 0.3, 0.5, 0.95, 1.0}) {
    const FrameSelection frame{t, {t - 0.2, t - 0.1}};
    expect_same(frame_drawings(stage, &frame, &cache), frame_drawings(stage, &frame, nullptr));
  }
}

TEST(StaticLayers, OnlyTheLayersThatReadNothingOfTheFrameAreRecorded) {
  const scene::Scene s = arrow_scene();
  const motion::Stage stage(s);
  StaticLayers cache;
  const FrameSelection frame{0.4, {}};
  const std::vector<Drawing> drawn = frame_drawings(stage, &frame, &cache);
  for (std::size_t p = 0; p < 2; ++p) {
    EXPECT_NE(cache.find(p, 0), nullptr) << "the keyframes of panel " << p;
    EXPECT_EQ(cache.find(p, 1), nullptr) << "the pattern of panel " << p << " moves";
    EXPECT_NE(cache.find(p, 2), nullptr) << "the label of panel " << p;
  }
  // The keyframes' part is what the layer drew: three arrows' items, not moving.
  const LayerPart* keyframes = cache.find(0, 0);
  ASSERT_NE(keyframes, nullptr);
  ASSERT_FALSE(keyframes->items.empty());
  for (const Item& item : keyframes->items) {
    EXPECT_EQ(item.layer, "/layers/0");
    EXPECT_FALSE(item.moving);
  }
}

TEST(StaticLayers, ARecordedLayerIsCopiedNotDrawnAgain) {
  const scene::Scene s = arrow_scene();
  const motion::Stage stage(s);
  StaticLayers cache;
  // A part put in the cache by hand for the label of panel 0: the frame shows it.
  Drawing marker;
  Circle circle;
  circle.center = {42.0, 43.0};
  circle.radius = 1.0;
  marker.items.push_back({"/layers/2", -1, circle, false});
  cache.record(0, 2, marker, 0, 0);
  const FrameSelection frame{0.4, {}};
  const std::vector<Drawing> drawn = frame_drawings(stage, &frame, &cache);
  std::size_t circles = 0, labels = 0;
  for (const Item& item : drawn[0].items) {
    if (item.layer != "/layers/2") continue;
    circles += std::holds_alternative<Circle>(item.shape) ? 1 : 0;
    labels += std::holds_alternative<Label>(item.shape) ? 1 : 0;
  }
  EXPECT_EQ(circles, 1u);
  EXPECT_EQ(labels, 0u);
  // Panel 1's label was drawn (and recorded), a label.
  ASSERT_NE(cache.find(1, 2), nullptr);
  ASSERT_EQ(cache.find(1, 2)->items.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<Label>(cache.find(1, 2)->items.front().shape));
}

TEST(StaticLayers, TheStaticFigureNeverUsesTheCache) {
  const scene::Scene s = arrow_scene();
  const motion::Stage stage(s);
  StaticLayers cache;
  const std::vector<Drawing> figure = frame_drawings(stage, nullptr, &cache);
  EXPECT_EQ(cache.find(0, 0), nullptr);
  expect_same(figure, frame_drawings(stage, nullptr, nullptr));
}

// A pose scene of the plane: the carried shapes move, a plot of the area does not.
scene::Scene pose_scene() {
  scene::Scene s;
  s.path = "test.json";
  scene::PlanePoseKeys keys;
  keys.method = PoseMethod::sam;
  keys.poses = {{0.0, pita::test::affinity(1.0, 0.2, 0.0, 0.0, 1.0, 0.0)},
                {2.0, pita::test::affinity(-0.5, -1.4, 5.0, 1.1, 0.3, 2.0)}};
  s.keys = keys;
  scene::PoseFigure<Affine2> figure;
  figure.shapes = {scene::ShapeOutline{{{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}}, true, std::nullopt, std::nullopt}};
  scene::PlotLayer plot;
  plot.of = scene::PlotOf::area;
  plot.box = {{6.0, 0.0}, {9.0, 2.0}};
  figure.layers = {scene::ShapesLayer{}, plot};
  scene::Panel panel;
  panel.keys = s.keys;
  panel.figure = scene::PosePanelFigure<Affine2>{std::nullopt, figure.shapes};
  panel.samples = 9;
  s.figure = std::move(figure);
  s.panels = {panel};
  return s;
}

TEST(StaticLayers, PoseFramesKeepTheirMovingShapesAndCopyThePlot) {
  const scene::Scene s = pose_scene();
  const motion::Stage stage(s);
  StaticLayers cache;
  for (double t : {0.0, 0.7, 2.0}) {
    const FrameSelection frame{t, {}};
    expect_same(frame_drawings(stage, &frame, &cache), frame_drawings(stage, &frame, nullptr));
  }
  EXPECT_EQ(cache.find(0, 0), nullptr) << "the shapes move";
  EXPECT_NE(cache.find(0, 1), nullptr) << "the plot reads nothing of the frame";
}

// In space, with "auto" (the camera turned after looking at the motion's
// samples) and shadows: the view is chosen once and kept; the frames are the
// frames drawn without the cache.
TEST(StaticLayers, TheViewOfSpaceIsChosenOnceForEveryFrame) {
  const scene::Scene s = scene::parse_scene(R"({"dimension": 3, "method": "polySAM", "samples": 5,
    "poses": [{"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
              {"t": 1, "matrix": [[0, -1, 0, 2], [1, 0, 0, 0], [0, 0, 1, 1]]},
              {"t": 2, "matrix": [[0, 0, 1, 3], [1, 0, 0, 1], [0, 1, 0, 2]]}],
    "camera": {"azimuth": -70, "elevation": 28, "auto": true, "shadow": true}})",
                                            "space.json");
  const motion::Stage stage(s);
  StaticLayers cache;
  EXPECT_EQ(cache.view(0), nullptr);
  for (double t : {0.0, 0.8, 1.5, 2.0}) {
    const FrameSelection frame{t, {t - 0.3}};
    expect_same(frame_drawings(stage, &frame, &cache), frame_drawings(stage, &frame, nullptr));
    ASSERT_NE(cache.view(0), nullptr);
  }
  // The view kept is the one the frame uses: a camera put in the cache by hand moves the drawing.
  StaticLayers other;
  scene::Camera side;
  side.azimuth = 90.0;
  side.elevation = 0.0;
  other.record_view(0, SpaceView{Projection(side, Eigen::Vector3d::Zero()), cache.view(0)->ground});
  const FrameSelection frame{0.8, {}};
  const std::vector<Drawing> seen = frame_drawings(stage, &frame, &other);
  EXPECT_FALSE(seen[0].items == frame_drawings(stage, &frame, nullptr)[0].items);
}

}  // namespace
}  // namespace pita::render::test
