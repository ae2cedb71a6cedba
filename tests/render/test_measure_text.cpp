// The "measures" layer (src/render/measure_text.cpp): the lines it prints for
// given numbers, and where a panel's drawing puts them (a label at a world
// point, or a text-only legend in a corner).
#include <initializer_list>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "render/measure_text.hpp"
#include "render/panel_drawing.hpp"
#include "scene/measure_name.hpp"
#include "scene/scene.hpp"

namespace pita::render {
namespace {

analysis::ArrowMeasures arrow_numbers() {
  analysis::ArrowMeasures m;
  m.discrepancy = {{"previous", 8, 1.5, 0.7, 0.25}, {"average", 7, 0.0125, 0.01, 0.5}, {"pita", 0, 0.0, 0.0, 0.0}};
  m.path_p = analysis::PathStats{6.5, 1.25};
  m.path_q = analysis::PathStats{7.0, 2.0};
  m.winding_min = -0.5;
  m.winding_max = 3.25;
  m.parameters = {{.name = "B.q.x", .gain = 1.5, .turn = 0.5, .jump = 3e-9},
                  {.name = "B.q.y", .gain = 2.25, .turn = 4.5, .jump = 0.75, .pop = true},
                  {.name = "C.t", .gain = 0.5, .turn = 0.25, .jump = 1e-9}};
  m.most_sensitive = 1;
  m.largest_jump = 1;
  m.pops = true;
  return m;
}

analysis::MotionMeasures with_measures(analysis::KindMeasures measured) {
  analysis::MotionMeasures m;
  m.measured = std::move(measured);
  return m;
}

analysis::MotionMeasures arrows_measured() { return with_measures(arrow_numbers()); }

// The names as the reader parses them (scene/measure_name.hpp), of either
// scene kind: the lines do not depend on it.
std::vector<scene::MeasureName> parsed(std::initializer_list<std::string_view> names) {
  std::vector<scene::MeasureName> out;
  for (const std::string_view name : names) {
    auto measure = scene::parse_measure<scene::Layer>(name);
    if (!std::holds_alternative<scene::MeasureName>(measure)) measure = scene::parse_measure<scene::PoseLayer>(name);
    out.push_back(std::get<scene::MeasureName>(measure));
  }
  return out;
}

TEST(MeasureText, OneLinePerNameWithTheNumbers) {
  const std::vector<scene::MeasureName> show =
      parsed({"discrepancy-max", "path-length", "turning", "winding-range", "overreaction", "pop", "gain:B.q",
              "jump:C.t", "ara", "turn:B.q"});
  const std::vector<std::string> lines = measure_lines(arrows_measured(), show);
  ASSERT_EQ(lines.size(), show.size());
  EXPECT_EQ(lines[0], "E max: previous 1.5, average 0.0125, pita -");
  EXPECT_EQ(lines[1], "length p 6.5, q 7");
  EXPECT_EQ(lines[2], "turning p 1.25, q 2 rad");
  EXPECT_EQ(lines[3], "winding [-0.5, 3.25]");
  EXPECT_EQ(lines[4], "most sensitive: B.q.y (gain 2.25)");
  EXPECT_EQ(lines[5], "pop: B.q.y jumps 0.75");
  EXPECT_EQ(lines[6], "gain B.q: 2.25 (pop)");  // the larger of B.q.x and B.q.y
  EXPECT_EQ(lines[7], "jump C.t: 1e-09");
  EXPECT_EQ(lines[8], "ARA: -");  // not a pose motion
  EXPECT_EQ(lines[9], "turn B.q: 4.5 rad per unit (pop)");
}

// One predictor's largest E and when; a predictor without frames is "-".
TEST(MeasureText, DiscrepancyOfOnePredictor) {
  const std::vector<std::string> lines =
      measure_lines(arrows_measured(), parsed({"discrepancy:average", "discrepancy-t:previous", "discrepancy:pita"}));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "E max (average): 0.0125 at t = 0.5");
  EXPECT_EQ(lines[1], "E max (previous): 1.5 at t = 0.25");
  EXPECT_EQ(lines[2], "E max (pita): -");
}

TEST(MeasureText, PoseLinesAndNoPop) {
  analysis::PoseMeasures<Affine2> poses;
  poses.ara = 4.25;
  poses.area = analysis::AreaStats{false, 0.125, 0.5, 1.0, 1.0};
  poses.velocity_jump = 0.375;
  const analysis::MotionMeasures m = with_measures(poses);
  const std::vector<scene::MeasureName> show = parsed({"ara", "area", "pop", "velocity-jump"});
  EXPECT_EQ(measure_lines(m, show), (std::vector<std::string>{"ARA 4.25", "area not monotone (dip 0.125 at t = 0.5)",
                                                              "pop: -", "velocity jump 0.375"}));
  analysis::ArrowMeasures numbers = arrow_numbers();
  numbers.pops = false;
  numbers.largest_jump = 0;
  const analysis::MotionMeasures calm = with_measures(numbers);
  const std::vector<scene::MeasureName> pop = parsed({"pop"});
  EXPECT_EQ(measure_lines(calm, pop).front(), "no pop (largest jump 3e-09)");
}

// A curve through points has a path (one: no q) and nothing else.
TEST(MeasureText, PointLinesHaveOnePath) {
  const analysis::MotionMeasures m = with_measures(analysis::PointMeasures{analysis::PathStats{6.5, 1.25}});
  const std::vector<scene::MeasureName> show = parsed({"path-length", "turning", "winding-range", "pop", "gain:B.q"});
  EXPECT_EQ(measure_lines(m, show),
            (std::vector<std::string>{"length 6.5", "turning 1.25 rad", "winding: -", "pop: -", "gain B.q: -"}));
}

scene::Scene scene_with_layer(const std::string& layer) {
  return scene::parse_scene(R"({"method": "P2", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 1}, {"t": 0.5, "p": [2, 0], "m": 0.8, "w": 1.6},
      {"t": 1, "p": [0.5, 0], "m": 1.2, "w": 2.2}], "layers": [)" +
                                layer + "]}",
                            "s.json");
}

TEST(MeasureText, LabelAtAWorldPoint) {
  // P2 on a branch cut (tests/core/test_fig10.cpp pop_config): the label says it pops.
  const scene::Scene scene = scene_with_layer(R"({"type": "measures", "show": ["pop", "gain:C.p"], "at": [1, -2],
      "size": 14, "color": "#ff0000"})");
  const Drawing drawing = panel_drawing(scene, scene.panels.front());
  ASSERT_EQ(drawing.items.size(), 1u);
  const auto* label = std::get_if<Label>(&drawing.items.front().shape);
  ASSERT_NE(label, nullptr);
  EXPECT_EQ(label->at, (Point{1.0, -2.0}));
  EXPECT_EQ(label->size, 14.0);
  EXPECT_EQ(label->color, (scene::Color{1.0, 0.0, 0.0, 1.0}));
  EXPECT_EQ(label->text.rfind("pop: ", 0), 0u) << label->text;
  EXPECT_NE(label->text.find("jumps"), std::string::npos) << label->text;
  EXPECT_NE(label->text.find("\ngain C.p: "), std::string::npos) << label->text;
  EXPECT_TRUE(drawing.legends.empty());
}

TEST(MeasureText, TextOnlyLegendInACorner) {
  const scene::Scene scene = scene_with_layer(R"({"type": "measures", "at": "top-right"})");
  const Drawing drawing = panel_drawing(scene, scene.panels.front());
  EXPECT_TRUE(drawing.items.empty());
  ASSERT_EQ(drawing.legends.size(), 1u);
  EXPECT_FALSE(drawing.legends.front().swatches);
  EXPECT_EQ(drawing.legends.front().corner, scene::LegendLayer::Corner::top_right);
  ASSERT_EQ(drawing.legends.front().entries.size(), 2u);  // default: overreaction, pop
  EXPECT_EQ(drawing.legends.front().entries[0].text.rfind("most sensitive: ", 0), 0u);
}

// The pointer and reason of the RenderError drawing `scene`'s first panel throws.
std::string drawing_error(const scene::Scene& scene) {
  try {
    (void)panel_drawing(scene, scene.panels.front());
  } catch (const RenderError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(MeasuresLayer, HandleShiftWithoutShapesIsRefused) {
  // Nothing is carried, so nothing can shift: not "< 1e-12".
  const scene::Scene scene = scene_with_layer(R"({"type": "measures", "show": ["pop", "handle-shift"]})");
  const std::string error = drawing_error(scene);
  EXPECT_NE(error.find("/layers/0/show/1"), std::string::npos) << error;
  EXPECT_NE(error.find("the panel has no shapes"), std::string::npos) << error;
}

TEST(MeasuresLayer, UndefinedAngleIsRefusedNotPrintedAsNan) {
  // P1's vector blend 1 - 2 * 4t(1 - t) vanishes at t = (1 - 1/sqrt 2)/2
  // (tests/analysis/test_comparison.cpp): the angle there has no value.
  const scene::Scene scene = scene::parse_scene(R"({"method": "P1", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 0.5, "p": [0, 0], "m": 1, "w": 3.141592653589793},
      {"t": 1, "p": [0, 0], "m": 1, "w": 0}], "layers": [
      {"type": "measures", "show": ["angle:P3@0.3", "angle:P3@0.14644660940672624"]}]})",
                                                "s.json");
  const std::string error = drawing_error(scene);
  EXPECT_NE(error.find("/layers/0/show/1"), std::string::npos) << error;
  EXPECT_NE(error.find("is undefined"), std::string::npos) << error;
  EXPECT_EQ(error.find("nan"), std::string::npos) << error;
}

// The frame steps of the drawn pattern (analysis/frame_steps.hpp), on the
// steady morph: 5 frames of m = 2^t, w = 1.2 t step by ln 2 / 4 and 0.3 rad.
TEST(MeasuresLayer, FrameStepsOfTheSteadyMorph) {
  const scene::Scene scene = scene::parse_scene(R"({"method": "SMA", "samples": 5, "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [3, 1], "m": 2, "w": 1.2}], "layers": [
      {"type": "measures", "show": ["scale-step", "turn-step", "scale-min", "scale-max"], "at": [0, 0]}]})",
                                                "s.json");
  const Drawing drawing = panel_drawing(scene, scene.panels.front());
  ASSERT_EQ(drawing.items.size(), 1u);
  EXPECT_EQ(std::get<Label>(drawing.items[0].shape).text,
            "scale-step: 0.173\nturn-step: 0.3 rad\nscale-min: 1\nscale-max: 1");
}

}  // namespace
}  // namespace pita::render
