// The "plot" layer (src/render/time_chart.cpp): the distance-time curve placed in
// its box, the diagonal, the marks at the frame times.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "motion/scene_motion.hpp"
#include "render/time_chart.hpp"
#include "scene/scene.hpp"

namespace pita::render {
namespace {

scene::Scene p6(const std::string& timing) {
  return scene::parse_scene(R"({"method": "P6", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0.4}, {"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": 2},
      {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}])" +
                                timing + "}",
                            "s.json");
}

TEST(Plot, CurveRunsFromTheBoxsLowCornerToItsHighCorner) {
  const motion::SceneMotion motion = motion::build_motion(p6(R"(, "timing": {"ease": "sine", "arc_length": "p"})"));
  scene::PlotLayer layer;
  layer.box = {Point{2.0, -3.0}, Point{6.0, -1.0}};
  layer.samples = 101;
  const std::vector<Item> items = plot_items(layer, motion, {0.0, 0.25, 0.5, 0.75, 1.0}, "/layers/3");
  const Polyline* curve = nullptr;
  int dots = 0;
  for (const Item& item : items) {
    EXPECT_EQ(item.layer, "/layers/3");
    if (const auto* line = std::get_if<Polyline>(&item.shape); line && line->points.size() == 101) curve = line;
    if (std::holds_alternative<Circle>(item.shape)) ++dots;
  }
  ASSERT_NE(curve, nullptr);
  EXPECT_NEAR(std::abs(curve->points.front() - Point{2.0, -3.0}), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(curve->points.back() - Point{6.0, -1.0}), 0.0, 1e-12);
  // Arc length under the sine ease: the curve is the ease itself, (1 - cos(pi x))/2.
  for (std::size_t i = 0; i < curve->points.size(); i += 10) {
    const double x = (curve->points[i].real() - 2.0) / 4.0, y = (curve->points[i].imag() + 3.0) / 2.0;
    EXPECT_NEAR(y, (1.0 - std::cos(M_PI * x)) / 2.0, 1e-9) << x;
  }
  EXPECT_EQ(dots, 5);
}

// Ticks: the ends of the time axis print the motion's first and last times,
// the ends of the distance axis 0 and 1 (a share of the path's length), and
// three tick marks divide each side in quarters.
TEST(Plot, AxesHaveTicksAndTheirEndValues) {
  const scene::Scene scene = scene::parse_scene(R"({"method": "P6", "keyframes": [
      {"t": 2, "p": [0, 0], "m": 1, "w": 0.4}, {"t": 3, "p": [3, 1.5], "m": 0.6, "w": 2},
      {"t": 4.5, "p": [6, 0], "m": 1.2, "w": 3.5}]})",
                                                "s.json");
  const motion::SceneMotion motion = motion::build_motion(scene);
  scene::PlotLayer layer;
  layer.box = {Point{0.0, 0.0}, Point{4.0, 2.0}};
  std::vector<std::string> texts;
  int ticks = 0;
  for (const Item& item : plot_items(layer, motion, {2.0, 4.5}, "/layers/0")) {
    if (const auto* label = std::get_if<Label>(&item.shape)) texts.push_back(label->text);
    if (const auto* line = std::get_if<Polyline>(&item.shape);
        line && line->points.size() == 2 && std::abs(line->points[1] - line->points[0]) < 0.1) {
      ++ticks;
    }
  }
  for (const char* expected : {"2", "4.5", "0", "1", "time", "distance"}) {
    EXPECT_NE(std::find(texts.begin(), texts.end(), expected), texts.end()) << expected;
  }
  EXPECT_EQ(ticks, 6);
}

// "of": "time": the warp itself. A sine ease without arc length is its own
// curve, (1 - cos(pi x))/2, whatever the motion's speed; the marks sit on it,
// the vertical axis is named "motion time", and "size" sets the axes' texts.
TEST(Plot, TimePlotsTheWarpItself) {
  const motion::SceneMotion motion = motion::build_motion(p6(R"(, "timing": {"ease": "sine"})"));
  scene::PlotLayer layer;
  layer.of = scene::PlotOf::time;
  layer.box = {Point{1.0, 1.0}, Point{3.0, 2.0}};
  layer.samples = 51;
  layer.size = 14.0;
  const std::vector<Item> items = plot_items(layer, motion, {0.0, 0.25, 0.5, 0.75, 1.0}, "/layers/0");
  const Polyline* curve = nullptr;
  std::vector<Point> dots;
  std::vector<std::pair<std::string, double>> texts;
  for (const Item& item : items) {
    if (const auto* line = std::get_if<Polyline>(&item.shape); line && line->points.size() == 51) curve = line;
    if (const auto* dot = std::get_if<Circle>(&item.shape)) dots.push_back(dot->center);
    if (const auto* label = std::get_if<Label>(&item.shape)) texts.emplace_back(label->text, label->size);
  }
  ASSERT_NE(curve, nullptr);
  const auto ease = [](double x) { return (1.0 - std::cos(M_PI * x)) / 2.0; };
  for (const Point p : curve->points) {
    const double x = (p.real() - 1.0) / 2.0, y = p.imag() - 1.0;
    EXPECT_NEAR(y, ease(x), 1e-12) << x;
  }
  ASSERT_EQ(dots.size(), 5u);
  EXPECT_NEAR(dots[1].imag() - 1.0, ease(0.25), 1e-12);
  const auto named = [&](const std::string& text) {
    return std::find_if(texts.begin(), texts.end(), [&](const auto& t) { return t.first == text; });
  };
  ASSERT_NE(named("motion time"), texts.end());
  EXPECT_EQ(named("motion time")->second, 14.0);
  EXPECT_EQ(named("time")->second, 14.0);
  EXPECT_EQ(named("1")->second, 13.0);  // an end value, one pixel smaller
  EXPECT_EQ(named("distance"), texts.end());
  // Without a timing the warp is the identity: the diagonal.
  const motion::SceneMotion plain = motion::build_motion(p6(""));
  for (const Item& item : plot_items(layer, plain, {}, "/layers/0")) {
    if (const auto* line = std::get_if<Polyline>(&item.shape); line && line->points.size() == 51) {
      for (const Point p : line->points) EXPECT_NEAR(p.imag() - 1.0, (p.real() - 1.0) / 2.0, 1e-12);
    }
  }
}

TEST(Plot, MarksCanBeLeftOut) {
  const motion::SceneMotion motion = motion::build_motion(p6(""));
  scene::PlotLayer layer;
  layer.marks = false;
  for (const Item& item : plot_items(layer, motion, {0.0, 0.5, 1.0}, "/layers/0")) {
    EXPECT_FALSE(std::holds_alternative<Circle>(item.shape));
  }
}

TEST(Plot, StillPointCannotBePlotted) {
  const scene::Scene scene = scene::parse_scene(R"({"method": "P1", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 0.5, "p": [0, 0], "m": 2, "w": 1},
      {"t": 1, "p": [0, 0], "m": 1, "w": 2}]})",
                                                "s.json");
  const motion::SceneMotion motion = motion::build_motion(scene);
  EXPECT_THROW(plot_items(scene::PlotLayer{}, motion, {0.0}, "/layers/0"), std::invalid_argument);
  scene::PlotLayer of_q;
  of_q.point = scene::TrackedPoint::end;
  EXPECT_NO_THROW(plot_items(of_q, motion, {0.0}, "/layers/0"));
}

}  // namespace
}  // namespace pita::render
