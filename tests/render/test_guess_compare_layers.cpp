// The "guesses" and "compare" layers of src/render/panel_drawing.cpp (PITA
// Figs. 16, 18, B.30; docs/paper-notes.md N53, N54), checked on the scenes of
// those figures: every printed number is recomputed here independently, from
// the core methods (make_motion, not the scene's motion stage) and the closed
// form of the discrepancy, E(A, B) = (|c - a|^2 + |d - b|^2)(1/A.m^2 + 1/B.m^2)
// (PITA Eq. 47 as corrected, N5), and the figures' claims are checked: Fig. B.30's
// two patterns agree on the left and P10 pops on the right, Fig. 18's moves
// bring D(1/4) close to E.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/pitas/registry.hpp"
#include "render/panel_drawing.hpp"
#include "render_support.hpp"
#include "scene/scene.hpp"
#include "support/keys.hpp"

namespace pita::render {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(PITA_SOURCE_DIR) / "scenes";

// The lines a layer printed in a corner (text-only legends), in order.
std::vector<std::string> printed_lines(const Drawing& drawing) {
  std::vector<std::string> lines;
  for (const Legend& legend : drawing.legends) {
    for (const LegendEntry& entry : legend.entries) lines.push_back(entry.text);
  }
  return lines;
}

// "NAME = 0.0123" -> 0.0123 when the line starts with `prefix`.
double printed_value(const std::vector<std::string>& lines, const std::string& prefix) {
  for (const std::string& line : lines) {
    if (line.rfind(prefix, 0) != 0) continue;
    const std::size_t equals = line.rfind("= ");
    return std::stod(line.substr(equals + 2));
  }
  ADD_FAILURE() << "no printed line starts with " << prefix;
  return std::nan("");
}

// Printed with three significant digits ({:.3g}).
void expect_printed(double printed, double expected, const std::string& what) {
  EXPECT_LE(std::abs(printed - expected), 5e-3 * std::abs(expected) + 1e-300)
      << what << ": printed " << printed << ", recomputed " << expected;
}

double closed_form_discrepancy(const Arrow& A, const Arrow& B) {
  const double a2 = A.m * A.m, b2 = B.m * B.m;
  return (std::norm(B.p - A.p) + std::norm(B.q() - A.q())) * (1.0 / a2 + 1.0 / b2);
}

double endpoint_gap(const Arrow& A, const Arrow& B) { return std::max(std::abs(A.p - B.p), std::abs(A.q() - B.q())); }

Arrow core_frame(Method method, const std::vector<Keyframe>& keyframes, double t) {
  return make_motion(method, keyframes)->at(t);
}

TEST(GuessesLayer, Fig16PrintsEachPitasDiscrepanciesFromTheGuesses) {
  const scene::Scene scene = scene::load_scene(kScenes / "fig16-inbetweening.json");
  ASSERT_EQ(scene.panels.size(), 8u);
  const auto& layer = std::get<scene::GuessesLayer>(scene::figure_of<scene::KeyframeKeys>(scene).layers.at(2));
  ASSERT_EQ(layer.guesses.size(), 2u);
  std::vector<double> all;
  for (const scene::Panel& panel : scene.panels) {
    const Drawing drawing = panel_drawing(scene, panel);
    const std::vector<std::string> lines = printed_lines(drawing);
    ASSERT_EQ(lines.size(), 2u) << method_id(panel.keys);
    for (const scene::Guess& guess : layer.guesses) {
      const Arrow frame = core_frame(track_keys(panel).method, arrow_keys(panel).keyframes, guess.t);
      const double expected = closed_form_discrepancy(guess.arrow, frame);
      const std::string prefix = "E(" + guess.name + ", D(" + (guess.t == 2.0 ? "2" : "4") + "))";
      expect_printed(printed_value(lines, prefix), expected, method_id(panel.keys) + " " + prefix);
      all.push_back(expected);
      // D(t) is drawn under the guess, from D(t).p to D(t).q.
      bool drawn = false;
      for (const Item& item : drawing.items) {
        const auto* arrow = std::get_if<ArrowShape>(&item.shape);
        if (arrow && std::abs(arrow->from - frame.p) < 1e-12 && std::abs(arrow->to - frame.q()) < 1e-12) drawn = true;
      }
      EXPECT_TRUE(drawn) << method_id(panel.keys) << ": D(" << guess.t << ") not drawn";
    }
  }
  // The guesses are no PITA's frames: every discrepancy is positive, and they
  // differ across the methods (the figure compares them).
  EXPECT_GT(*std::min_element(all.begin(), all.end()), 1e-3);
  EXPECT_GT(*std::max_element(all.begin(), all.end()), 2.0 * *std::min_element(all.begin(), all.end()));
}

TEST(GuessesLayer, Fig18FourMovesBringDQuarterCloseToTheTarget) {
  const scene::Scene scene = scene::load_scene(kScenes / "fig18-editing.json");
  ASSERT_EQ(scene.panels.size(), 2u);
  const scene::Guess target =
      std::get<scene::GuessesLayer>(scene::figure_of<scene::KeyframeKeys>(scene).layers.at(2)).guesses.at(0);
  ASSERT_EQ(target.t, 0.25);
  std::vector<double> distances;
  for (const scene::Panel& panel : scene.panels) {
    ASSERT_EQ(track_keys(panel).method, Method::P8);
    const std::vector<std::string> lines = printed_lines(panel_drawing(scene, panel));
    const Arrow frame = core_frame(Method::P8, arrow_keys(panel).keyframes, 0.25);
    const double d = endpoint_gap(target.arrow, frame);
    expect_printed(printed_value(lines, "d(E, D(0.25))"), d, "d");
    expect_printed(printed_value(lines, "E(E, D(0.25))"), closed_form_discrepancy(target.arrow, frame), "E");
    distances.push_back(d);
  }
  // Only B moved: A and C are the same in both panels.
  EXPECT_EQ(arrow_keys(scene.panels[0]).keyframes[0].arrow.p, arrow_keys(scene.panels[1]).keyframes[0].arrow.p);
  EXPECT_EQ(arrow_keys(scene.panels[0]).keyframes[2].arrow.q(), arrow_keys(scene.panels[1]).keyframes[2].arrow.q());
  EXPECT_GT(distances[0], 0.5);   // the target is visibly off at first
  EXPECT_LT(distances[1], 0.05);  // a slight expansion covers it after the moves
  EXPECT_LT(distances[1], distances[0] / 10.0);
}

TEST(CompareLayer, FigB30P3EqualsP10UntilATweakOfAwMakesP10Pop) {
  const scene::Scene scene = scene::load_scene(kScenes / "appB-fig30-p3-p10.json");
  ASSERT_EQ(scene.panels.size(), 2u);
  const std::vector<double> times = layer_times(scene.panels[0], std::nullopt, std::nullopt);
  ASSERT_EQ(times.size(), 9u);
  std::vector<std::vector<Arrow>> p3(2), p10(2);
  std::vector<double> printed;
  for (std::size_t k = 0; k < 2; ++k) {
    const scene::Panel& panel = scene.panels[k];
    ASSERT_EQ(track_keys(panel).method, Method::P3);
    double largest = 0.0;
    for (const double t : times) {
      p3[k].push_back(core_frame(Method::P3, arrow_keys(panel).keyframes, t));
      p10[k].push_back(core_frame(Method::P10, arrow_keys(panel).keyframes, t));
      largest = std::max(largest, endpoint_gap(p3[k].back(), p10[k].back()));
    }
    printed.push_back(printed_value(printed_lines(panel_drawing(scene, panel)), "max |P3 \u2212 P10|"));
    if (k == 1) {
      expect_printed(printed[k], largest, "right");
    } else {
      EXPECT_LT(largest, 1e-12);
    }
  }
  // Left: identical, to rounding. Right: A.w crossed pi; P3 barely moved
  // (continuous in A.w) while P10 jumped by about its whole extent.
  EXPECT_LT(printed[0], 1e-12);
  EXPECT_LT(arrow_keys(scene.panels[0]).keyframes[0].arrow.w, std::numbers::pi);
  EXPECT_GT(arrow_keys(scene.panels[1]).keyframes[0].arrow.w, std::numbers::pi);
  double p3_moved = 0.0, p10_moved = 0.0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    p3_moved = std::max(p3_moved, endpoint_gap(p3[0][i], p3[1][i]));
    p10_moved = std::max(p10_moved, endpoint_gap(p10[0][i], p10[1][i]));
  }
  EXPECT_LE(p3_moved, 0.11);
  EXPECT_GT(p10_moved, 1.0);
  EXPECT_GT(printed[1], 1.0);
}

TEST(CompareLayer, DrawsTheOtherMethodsFramesDashed) {
  scene::CompareLayer layer;
  layer.method = Method::P1;
  layer.method_name = "P1";
  const scene::Panel p = test::panel(Method::P6, test::three_keyframes(), 5);
  const Drawing d = panel_drawing(test::scene_with({layer}, {p}), p);
  ASSERT_EQ(d.items.size(), 5u);
  const std::vector<Keyframe> keys = test::three_keyframes();
  for (std::size_t i = 0; i < 5; ++i) {
    const auto& line = std::get<Polyline>(d.items[i].shape);
    const Arrow expected = core_frame(Method::P1, keys, 0.25 * static_cast<double>(i));
    EXPECT_LT(std::abs(line.points[0] - expected.p), 1e-12) << i;
    EXPECT_LT(std::abs(line.points[1] - expected.q()), 1e-12) << i;
    EXPECT_EQ(line.line.dash, layer.line.dash);
  }
  // P1 and P6 differ, and the printed distance says by how much.
  double largest = 0.0;
  for (std::size_t i = 0; i < 5; ++i) {
    const double t = 0.25 * static_cast<double>(i);
    largest = std::max(largest, endpoint_gap(core_frame(Method::P1, keys, t), core_frame(Method::P6, keys, t)));
  }
  expect_printed(printed_value(printed_lines(d), "max |P6 \u2212 P1|"), largest, "P6 - P1");
}

// (The default names G1, G2, ... are the reader's: tests/scene/test_arrow_layer_reader_guesses.cpp.)
TEST(GuessesLayer, AGuessOnTheFrameHasZeroDiscrepancyAndDistance) {
  const std::vector<Keyframe> keys = test::three_keyframes();
  const scene::Panel p = test::panel(Method::P6, keys);
  scene::GuessesLayer layer;
  const Arrow frame = core_frame(Method::P6, keys, 0.5);  // D(b) = B
  layer.guesses.push_back({0.5, frame, "G1", scene::Color{}});
  layer.show = {scene::GuessMeasure::discrepancy, scene::GuessMeasure::distance};
  const std::vector<std::string> lines = printed_lines(panel_drawing(test::scene_with({layer}, {p}), p));
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].rfind("E(G1, D(0.5)) = ", 0), 0u) << lines[0];
  EXPECT_EQ(lines[1].rfind("d(G1, D(0.5)) = ", 0), 0u) << lines[1];
  EXPECT_LT(printed_value(lines, "E(G1"), 1e-24);
  EXPECT_LT(printed_value(lines, "d(G1"), 1e-12);
}

}  // namespace
}  // namespace pita::render
