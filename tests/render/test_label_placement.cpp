// "place": "auto" labels (render/label_placement.hpp): the spots around a
// point, and a label over a pattern moved to where its ink meets no data
// while a free one, and an "at" one, stay where they are.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "render/canvas_geometry.hpp"
#include "render/figure.hpp"
#include "render/label_placement.hpp"
#include "render/painter.hpp"
#include "scene/scene.hpp"

namespace pita::render {
namespace {

// The box at each spot is the ink's size, `gap` from the point on its side.
TEST(LabelPlacement, SpotsSurroundThePoint) {
  const Rect ink{50, 40, 30, 10};
  const Point at{100, 100};
  const auto near = [](const Rect& r, double x, double y) {
    return std::abs(r.x - x) < 1e-12 && std::abs(r.y - y) < 1e-12 && r.width == 30 && r.height == 10;
  };
  EXPECT_TRUE(near(spot_box(ink, at, Spot::right, 4), 104, 95));
  EXPECT_TRUE(near(spot_box(ink, at, Spot::above_right, 4), 104, 86));
  EXPECT_TRUE(near(spot_box(ink, at, Spot::above, 4), 85, 86));
  EXPECT_TRUE(near(spot_box(ink, at, Spot::above_left, 4), 66, 86));
  EXPECT_TRUE(near(spot_box(ink, at, Spot::left, 4), 66, 95));
  EXPECT_TRUE(near(spot_box(ink, at, Spot::below_left, 4), 66, 104));
  EXPECT_TRUE(near(spot_box(ink, at, Spot::below, 4), 85, 104));
  EXPECT_TRUE(near(spot_box(ink, at, Spot::below_right, 4), 104, 104));
}

// Three keyframes of P6 and its pattern; a label at `at`, placed `place`.
scene::Scene labelled(const std::string& at, const std::string& place) {
  return scene::parse_scene(R"({"method": "P6", "samples": 9, "canvas": {"width": 600, "height": 400},
    "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 1.2}, {"t": 0.5, "p": [3, 1.5], "m": 0.7, "w": 2},
                  {"t": 1, "p": [6, 0], "m": 1.3, "w": 1.9}],
    "layers": [{"type": "pattern"}, {"type": "keyframes"},
               {"type": "label", "text": "the middle key", "size": 16, "at": )" +
                                at + R"(, "place": ")" + place + R"("}]})",
                            "label.json");
}

struct Placed {
  Label label;
  Rect ink;
  bool over_data = false;
  bool inside_panel = false;
};

Placed placed(const scene::Scene& scene) {
  const Figure figure = build_figure(scene);
  const Drawing& drawing = figure.drawings.at(0);
  const ViewTransform& view = figure.placements.at(0).transform;
  Placed out;
  for (const Item& item : drawing.items) {
    if (const auto* label = std::get_if<Label>(&item.shape)) out.label = *label;
  }
  out.ink = text_ink_box(out.label.text, scene.canvas.font, out.label.size, label_placement(out.label, view), false);
  for (const Item& item : drawing.items) {
    if (const auto outline = canvas_outline(item.shape, view)) {
      out.over_data = out.over_data || lies_under(*outline, shrunk(out.ink, 1.0), true);
    }
  }
  out.inside_panel = contains(drawing_area(figure.placements[0]), out.ink);
  return out;
}

TEST(LabelPlacement, AnAutoLabelLeavesTheDataItCovers) {
  // At the middle keyframe's tail, on the frames: "at" stays there, over data.
  const Placed at = placed(labelled("[2.6, 1.5]", "at"));
  EXPECT_EQ(at.label.shift, Point(0, 0));
  EXPECT_TRUE(at.over_data);
  // "auto" moves it to a spot beside its point where it covers nothing.
  const Placed moved = placed(labelled("[2.6, 1.5]", "auto"));
  EXPECT_NE(moved.label.shift, Point(0, 0));
  EXPECT_FALSE(moved.over_data);
  EXPECT_TRUE(moved.inside_panel);
  const Figure figure = build_figure(labelled("[2.6, 1.5]", "auto"));
  const Point anchor = figure.placements[0].transform({2.6, 1.5});
  const Point centre{moved.ink.x + 0.5 * moved.ink.width, moved.ink.y + 0.5 * moved.ink.height};
  EXPECT_LT(std::abs(centre - anchor), moved.ink.width);  // still beside its point
}

TEST(LabelPlacement, AFreeAutoLabelStaysAtItsPoint) {
  const Placed free = placed(labelled("[0, 3.3]", "auto"));
  EXPECT_EQ(free.label.shift, Point(0, 0));
  EXPECT_FALSE(free.over_data);
}

}  // namespace
}  // namespace pita::render
