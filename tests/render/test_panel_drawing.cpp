// Geometry of what is drawn (render/panel_drawing.hpp), checked against the
// motions themselves and the paper's definitions, not against saved output.
#include <array>
#include <cmath>
#include <complex>
#include <numbers>

#include <gtest/gtest.h>

#include "core/discrepancy.hpp"
#include "core/steady_morph.hpp"
#include "motion/stage.hpp"
#include "render/panel_drawing.hpp"
#include "render/spiral.hpp"
#include "render_support.hpp"
#include "scene/scene.hpp"
#include "support/keys.hpp"

namespace pita::render::test {
namespace {

std::vector<Arrow> frames_of(const scene::Panel& p, int n) {
  const auto motion = make_motion(track_keys(p).method, arrow_keys(p).keyframes, track_keys(p).options);
  std::vector<Arrow> frames;
  for (int i = 0; i < n; ++i) {
    const double t = arrow_keys(p).keyframes.front().t +
                     (arrow_keys(p).keyframes.back().t - arrow_keys(p).keyframes.front().t) * i / (n - 1);
    frames.push_back(motion->at(t));
  }
  return frames;
}

template <typename T>
std::vector<const T*> shapes(const Drawing& d) {
  std::vector<const T*> found;
  for (const Item& item : d.items) {
    if (const T* s = std::get_if<T>(&item.shape)) found.push_back(s);
  }
  return found;
}

TEST(PatternLayer, DrawsEachFrameFromPToQ) {
  const scene::Panel p = panel(Method::P6, three_keyframes(), 11);
  const Drawing d = panel_drawing(scene_with({scene::PatternLayer{}}, {p}), p);
  const auto lines = shapes<Polyline>(d);
  const auto frames = frames_of(p, 11);
  ASSERT_EQ(lines.size(), 11u);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    ASSERT_EQ(lines[i]->points.size(), 2u);
    EXPECT_NEAR(std::abs(lines[i]->points[0] - frames[i].p), 0.0, 1e-12) << i;
    EXPECT_NEAR(std::abs(lines[i]->points[1] - frames[i].q()), 0.0, 1e-12) << i;
    EXPECT_EQ(d.items[i].layer, "/layers/0");
    EXPECT_EQ(d.items[i].index, static_cast<int>(i));
  }
}

TEST(PatternLayer, ExtendedFormHasPAtItsMidpoint) {
  const scene::Panel p = panel(Method::P3, three_keyframes(), 5);
  scene::PatternLayer layer;
  layer.extended = true;
  const Drawing d = panel_drawing(scene_with({layer}, {p}), p);
  const auto frames = frames_of(p, 5);
  const auto lines = shapes<Polyline>(d);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    EXPECT_NEAR(std::abs(0.5 * (lines[i]->points[0] + lines[i]->points[1]) - frames[i].p), 0.0, 1e-12);
    EXPECT_NEAR(std::abs(lines[i]->points[1] - frames[i].q()), 0.0, 1e-12);
  }
}

TEST(PatternLayer, TimesAndMethodDrawAnotherMethodsFramesAtThoseTimes) {
  // Fig. 5: keyframes at a common origin; the layer draws Pa-Po (parabola,
  // polar Lagrange) at t = 1/4 and 3/4 while the panel's method is P6. Pa-
  // keeps p at 0 and -Po blends m and w by the Lagrange weights of PITA Eq. 9.
  const std::array<double, 3> m = {0.6, 2.4, 1.2}, w = {0.1, 1.6, 3.3};
  std::vector<Keyframe> keys;
  for (std::size_t i = 0; i < 3; ++i) keys.push_back({0.5 * static_cast<double>(i), Arrow{{0.0, 0.0}, m[i], w[i]}});
  const scene::Panel p = panel(Method::P6, keys, 9);
  scene::PatternLayer layer;
  layer.times = {0.25, 0.75};
  layer.method = Method::PaPo;
  const Drawing d = panel_drawing(scene_with({layer}, {p}), p);
  const auto lines = shapes<Polyline>(d);
  ASSERT_EQ(lines.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const double t = layer.times[k];
    const std::array<double, 3> L = {(t - 0.5) * (t - 1.0) / 0.5, t * (t - 1.0) / -0.25, t * (t - 0.5) / 0.5};
    const double mt = L[0] * m[0] + L[1] * m[1] + L[2] * m[2];
    const double wt = L[0] * w[0] + L[1] * w[1] + L[2] * w[2];
    EXPECT_NEAR(std::abs(lines[k]->points[0]), 0.0, 1e-12) << t;
    EXPECT_NEAR(std::abs(lines[k]->points[1] - std::polar(mt, wt)), 0.0, 1e-12) << t;
  }
}

TEST(PatternLayer, DotsDrawEachFramesStartPoint) {
  // Fig. 6: a dot (filled circle) at D(t_i).p, no segment.
  const scene::Panel p = panel(Method::P2, three_keyframes(), 7);
  scene::PatternLayer layer;
  layer.dots = true;
  const Drawing d = panel_drawing(scene_with({layer}, {p}), p);
  EXPECT_TRUE(shapes<Polyline>(d).empty());
  const auto dots = shapes<Circle>(d);
  const auto frames = frames_of(p, 7);
  ASSERT_EQ(dots.size(), 7u);
  for (std::size_t i = 0; i < 7; ++i) {
    EXPECT_NEAR(std::abs(dots[i]->center - frames[i].p), 0.0, 1e-12) << i;
    EXPECT_GT(dots[i]->radius, 0.0);
    EXPECT_TRUE(dots[i]->fill.has_value());
  }
}

TEST(PatternLayer, CoilsShowEachFramesWindingEvolvingLinearly) {
  // Fig. 3: under the steady morph the winding goes linearly from A.w to B.w
  // (PITA Eq. 21), so the coil of frame i turns through A.w + t_i (B.w - A.w).
  const Arrow A{{0.0, 0.0}, 2.0, 0.3}, B{{4.0, 1.0}, 0.6, 3.6 + 2.0 * std::numbers::pi};
  const scene::Panel p = panel(Method::SMA, {{0.0, A}, {1.0, B}}, 9);
  scene::PatternLayer layer;
  layer.coils = true;
  const Drawing d = panel_drawing(scene_with({layer}, {p}), p);
  const auto lines = shapes<Polyline>(d);
  const auto frames = frames_of(p, 9);
  ASSERT_EQ(lines.size(), 18u);  // a segment and a coil per frame
  for (std::size_t i = 0; i < 9; ++i) {
    const Polyline& coil = *lines[2 * i + 1];
    const double t = static_cast<double>(i) / 8.0;
    double turned = 0.0;
    for (std::size_t k = 1; k < coil.points.size(); ++k) {
      turned += std::arg((coil.points[k] - frames[i].p) / (coil.points[k - 1] - frames[i].p));
    }
    EXPECT_NEAR(turned, A.w + t * (B.w - A.w), 1e-9) << i;
    // It starts 0.1 m from p (render/spiral.hpp), m = A.m^(1-t) B.m^t.
    const double m = std::pow(A.m, 1.0 - t) * std::pow(B.m, t);
    EXPECT_NEAR(std::abs(coil.points.front() - frames[i].p), 0.1 * m, 1e-12) << i;
    EXPECT_EQ(d.items[2 * i + 1].index, static_cast<int>(i));
  }
  // Without the option, the frames only.
  EXPECT_EQ(shapes<Polyline>(panel_drawing(scene_with({scene::PatternLayer{}}, {p}), p)).size(), 9u);
}

TEST(LegendLayer, MethodInThePatternsColourThenTheTrajectoriesDrawn) {
  const scene::Panel p = panel(Method::P6, three_keyframes());
  scene::TrajectoryLayer path;
  path.line.color = Color{0.5, 0.5, 0.5, 1.0};
  path.line.dash = {4.0, 3.0};
  scene::PatternLayer frames;
  frames.line.color = Color{0.1, 0.3, 0.8, 1.0};
  const Drawing d = panel_drawing(scene_with({path, frames, scene::KeyframesLayer{}, scene::LegendLayer{}}, {p}), p);
  ASSERT_EQ(d.legends.size(), 1u);
  const auto& entries = d.legends[0].entries;
  ASSERT_EQ(entries.size(), 5u);  // A, B, C, the method, the path of p
  EXPECT_EQ(entries[0].text, "A  t = 0");
  EXPECT_EQ(entries[3].text, "P6 La-LP");
  EXPECT_EQ(entries[3].color.b, 0.8);
  EXPECT_EQ(entries[3].color.g, 0.3);
  EXPECT_EQ(entries[4].text, "path of p");
  EXPECT_EQ(entries[4].color.r, 0.5);
  EXPECT_EQ(entries[4].dash, (std::vector<double>{4.0, 3.0}));
  EXPECT_TRUE(entries[3].dash.empty());
  // No pattern layer: the method in dark grey, as before.
  const Drawing plain = panel_drawing(scene_with({scene::KeyframesLayer{}, scene::LegendLayer{}}, {p}), p);
  ASSERT_EQ(plain.legends.at(0).entries.size(), 4u);
  EXPECT_EQ(plain.legends[0].entries[3].color.r, 0.2);
}

TEST(PatternLayer, RangeExtrapolatesBeyondTheKnots) {
  // Sec. 7.5: the frame at t = 1.5 is the prediction D(1.5).
  const scene::Panel p = panel(Method::P8, three_keyframes());
  scene::PatternLayer layer;
  layer.samples = 4;
  layer.range = scene::TimeRange{0.0, 1.5};
  const Drawing d = panel_drawing(scene_with({layer}, {p}), p);
  const auto lines = shapes<Polyline>(d);
  const Arrow predicted = make_motion(Method::P8, arrow_keys(p).keyframes)->at(1.5);
  EXPECT_NEAR(std::abs(lines.back()->points[0] - predicted.p), 0.0, 1e-12);
}

// Fig. 4 (N57): a pattern layer with its own options draws the panel's
// method with those options changed, the others kept.
TEST(PatternLayer, OverlayDrawsItsOwnOptionsOverThePanels) {
  const Arrow A{{0.0, 0.0}, 1.6, 1.7}, B{{5.0, 0.0}, 0.4, 1.2};
  scene::Panel p = panel(Method::SMA, {{0.0, A}, {1.0, B}}, 9);
  track_keys(p).options.path_mean = MeanKind::arithmetic;
  scene::PatternLayer overlay;
  overlay.options.values.magnitude_mean = MeanKind::harmonic;
  overlay.options.given = kMagnitudeMeanOption;
  const Drawing d = panel_drawing(scene_with({overlay}, {p}), p);
  const auto lines = shapes<Polyline>(d);
  ASSERT_EQ(lines.size(), 9u);
  // The same frames as a panel given both options.
  scene::Panel both = p;
  track_keys(both).options.magnitude_mean = MeanKind::harmonic;
  const auto frames = frames_of(both, 9);
  for (std::size_t i = 0; i < 9; ++i) {
    EXPECT_NEAR(std::abs(lines[i]->points[0] - frames[i].p), 0.0, 1e-12) << i;
    EXPECT_NEAR(std::abs(lines[i]->points[1] - frames[i].q()), 0.0, 1e-12) << i;
  }
  // Independently (Sec. 2.7): at t = 1/2 the magnitude is the harmonic mean
  // of 1.6 and 0.4, 2 / (1/1.6 + 1/0.4) = 0.64, and p has turned by half the
  // twirl's angle about its fixed point f, its radius scaled by the
  // arithmetic mean of 1 and the twirl's ratio: (1 + 0.25) / 2.
  EXPECT_NEAR(std::abs(lines[4]->points[1] - lines[4]->points[0]), 0.64, 1e-12);
  const std::complex<double> z = 0.25 * std::polar(1.0, B.w - A.w);  // T_{A,B}: scale and turn
  const Point f = (B.p - z * A.p) / (1.0 - z);
  const Point p_half = f + (A.p - f) * std::polar(0.5 * (1.0 + 0.25), 0.5 * (B.w - A.w));
  EXPECT_NEAR(std::abs(lines[4]->points[0] - p_half), 0.0, 1e-12);
  // The panel's own pattern is unchanged: magnitude WGM, sqrt(1.6 * 0.4) = 0.8.
  const Drawing own = panel_drawing(scene_with({scene::PatternLayer{}}, {p}), p);
  const auto plain = shapes<Polyline>(own);
  EXPECT_NEAR(std::abs(plain[4]->points[1] - plain[4]->points[0]), 0.8, 1e-12);
}

TEST(PatternLayer, OverlayOfAnotherMethodThroughThePanelsKeyframes) {
  const scene::Panel p = panel(Method::P6, three_keyframes(), 7);
  scene::PatternLayer overlay;
  overlay.method = Method::P1;
  const Drawing d = panel_drawing(scene_with({overlay}, {p}), p);
  const auto lines = shapes<Polyline>(d);
  const auto frames = frames_of(panel(Method::P1, three_keyframes(), 7), 7);
  ASSERT_EQ(lines.size(), 7u);
  double apart = 0.0;  // and not P6's: the keyframes were chosen so they differ
  const auto p6 = frames_of(p, 7);
  for (std::size_t i = 0; i < 7; ++i) {
    EXPECT_NEAR(std::abs(lines[i]->points[0] - frames[i].p), 0.0, 1e-12) << i;
    EXPECT_NEAR(std::abs(lines[i]->points[1] - frames[i].q()), 0.0, 1e-12) << i;
    apart = std::max(apart, std::abs(lines[i]->points[1] - p6[i].q()));
  }
  EXPECT_GT(apart, 1e-3);
}

TEST(PatternLayer, OverlayWhoseMethodCannotTakeTheKeyframesIsTheLayersError) {
  scene::Panel p = panel(Method::SMA, {{0.0, Arrow{{0, 0}, 1.0, 0.0}}, {1.0, Arrow{{2, 0}, 0.5, 1.0}}});
  p.pointer = "/panels/1";
  scene::PatternLayer overlay;
  overlay.method = Method::P6;  // three keyframes, the panel has two
  scene::figure_of<scene::KeyframeKeys>(p).layers = std::vector<scene::Layer>{scene::KeyframesLayer{}, overlay};
  try {
    panel_drawing(scene_with({}, {p}), p);
    FAIL() << "expected a RenderError";
  } catch (const RenderError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("test.json: /panels/1/layers/1/method: ", 0), 0u) << error.what();
  }
}

// An option the overlay's method does not read would draw the panel's frames
// again under a legend entry that claims a difference: refused at the option.
TEST(PatternLayer, OverlayOptionItsMethodDoesNotReadIsRefused) {
  scene::Panel p = panel(Method::P6, three_keyframes());
  p.pointer = "/panels/0";
  scene::PatternLayer overlay;
  overlay.options.values.permutation = Permutation::CBA;
  overlay.options.given = kPermutationOption;
  scene::figure_of<scene::KeyframeKeys>(p).layers = std::vector<scene::Layer>{overlay};
  try {
    panel_drawing(scene_with({}, {p}), p);
    FAIL() << "expected a RenderError";
  } catch (const RenderError& error) {
    EXPECT_EQ(std::string(error.what()),
              "test.json: /panels/0/layers/0/options/permutation: P6 La-LP does not read \"permutation\", so it "
              "would change nothing here; La-T1, La-T2, Ne-M read it");
  }
  // The same option with a method that reads it is drawn.
  overlay.method = Method::LaT1;
  scene::figure_of<scene::KeyframeKeys>(p).layers = std::vector<scene::Layer>{overlay};
  EXPECT_EQ(shapes<Polyline>(panel_drawing(scene_with({}, {p}), p)).size(), frames_of(p, 9).size());
  // The means: read by SMA and P9, and by a chain's steady morphs.
  overlay = scene::PatternLayer{};
  overlay.options.given = kPathMeanOption;
  scene::figure_of<scene::KeyframeKeys>(p).layers = std::vector<scene::Layer>{overlay};
  EXPECT_THROW(panel_drawing(scene_with({}, {p}), p), RenderError);
  scene::Panel chained = panel(Method::P6, {{0.0, Arrow{{0, 0}, 1.0, 0.0}},
                                            {1.0, Arrow{{2, 0}, 0.5, 1.0}},
                                            {2.0, Arrow{{3, 1}, 0.7, 1.5}},
                                            {3.0, Arrow{{5, 0}, 1.0, 2.0}}});
  scene::figure_of<scene::KeyframeKeys>(chained).layers = std::vector<scene::Layer>{overlay};
  EXPECT_NO_THROW(panel_drawing(scene_with({}, {chained}), chained));
}

// A trajectory with its own method draws that method's path through the
// panel's keyframes (Fig. D.35), checks its options as a pattern does, and
// is left out of the legend (its pattern's entry names the colour).
TEST(TrajectoryLayer, OwnMethodDrawsThatMethodsPath) {
  scene::Panel p = panel(Method::P6, three_keyframes());
  p.pointer = "/panels/0";
  scene::TrajectoryLayer path;
  path.method = Method::P1;
  path.samples = 5;
  scene::figure_of<scene::KeyframeKeys>(p).layers = std::vector<scene::Layer>{path, scene::LegendLayer{}};
  const Drawing drawing = panel_drawing(scene_with({}, {p}), p);
  const auto lines = shapes<Polyline>(drawing);
  ASSERT_EQ(lines.size(), 1u);
  const std::vector<Arrow> p1 = frames_of(panel(Method::P1, three_keyframes()), 5);
  ASSERT_EQ(lines[0]->points.size(), p1.size());
  for (std::size_t i = 0; i < p1.size(); ++i) EXPECT_LT(std::abs(lines[0]->points[i] - p1[i].p), 1e-12) << i;
  ASSERT_EQ(drawing.legends.size(), 1u);
  for (const LegendEntry& entry : drawing.legends[0].entries) EXPECT_NE(entry.text, "path of p");

  path = scene::TrajectoryLayer{};
  path.options.values.permutation = Permutation::CBA;
  path.options.given = kPermutationOption;
  scene::figure_of<scene::KeyframeKeys>(p).layers = std::vector<scene::Layer>{path};
  try {
    panel_drawing(scene_with({}, {p}), p);
    FAIL() << "expected a RenderError";
  } catch (const RenderError& error) {
    EXPECT_EQ(std::string(error.what())
                  .rfind("test.json: /panels/0/layers/0/options/permutation: P6 La-LP does not "
                         "read \"permutation\"",
                         0),
              0u)
        << error.what();
  }
}

TEST(PatternLayer, HeadsDrawEachFrameAsAnArrowFromPToQ) {
  const scene::Panel p = panel(Method::P3, three_keyframes(), 5);
  scene::PatternLayer layer;
  layer.heads = true;
  const Drawing d = panel_drawing(scene_with({layer}, {p}), p);
  const auto arrows = shapes<ArrowShape>(d);
  const auto frames = frames_of(p, 5);
  ASSERT_EQ(arrows.size(), 5u);
  EXPECT_TRUE(shapes<Polyline>(d).empty());
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_NEAR(std::abs(arrows[i]->from - frames[i].p), 0.0, 1e-12) << i;
    EXPECT_NEAR(std::abs(arrows[i]->to - frames[i].q()), 0.0, 1e-12) << i;
  }
}

TEST(LegendLayer, OverlaidPatternsGetAnEntryEach) {
  const scene::Panel p = panel(Method::SMA, {{0.0, Arrow{{0, 0}, 1.0, 0.0}}, {1.0, Arrow{{2, 0}, 0.5, 1.0}}});
  std::vector<scene::Layer> layers;
  const std::array<MeanKind, 3> means{MeanKind::arithmetic, MeanKind::geometric, MeanKind::harmonic};
  for (std::size_t i = 0; i < 3; ++i) {
    scene::PatternLayer overlay;
    overlay.options.values.magnitude_mean = means[i];
    overlay.options.given = kMagnitudeMeanOption;
    overlay.line.color = Color{i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0, 1.0};
    overlay.label = "magnitude " + std::to_string(i);
    layers.push_back(overlay);
  }
  scene::PatternLayer other;
  other.method = Method::SMA;  // no label: named by its method
  layers.push_back(other);
  layers.push_back(scene::LegendLayer{});
  const Drawing d = panel_drawing(scene_with(layers, {p}), p);
  const auto& entries = d.legends.at(0).entries;
  ASSERT_EQ(entries.size(), 6u);  // A, B, three labelled overlays, the unlabelled one; no panel entry
  EXPECT_EQ(entries[2].text, "magnitude 0");
  EXPECT_EQ(entries[2].color.r, 1.0);
  EXPECT_EQ(entries[4].text, "magnitude 2");
  EXPECT_EQ(entries[4].color.b, 1.0);
  EXPECT_EQ(entries[5].text, "SMA");
}

TEST(StrokeLayer, QuadCornersAreTheFramesEndpoints) {
  const scene::Panel p = panel(Method::P5, three_keyframes(), 13);
  const Drawing d = panel_drawing(scene_with({scene::StrokeLayer{}}, {p}), p);
  const auto paths = shapes<FilledPath>(d);
  ASSERT_EQ(paths.size(), 1u);
  const auto frames = frames_of(p, 13);
  ASSERT_EQ(paths[0]->contours.size(), 12u);
  for (std::size_t i = 0; i + 1 < frames.size(); ++i) {
    const auto& quad = paths[0]->contours[i];
    ASSERT_EQ(quad.size(), 4u);
    // The four corners, in either orientation.
    for (Point corner : {frames[i].p, frames[i].q(), frames[i + 1].q(), frames[i + 1].p}) {
      double nearest = 1e9;
      for (Point x : quad) nearest = std::min(nearest, std::abs(x - corner));
      EXPECT_LT(nearest, 1e-12) << "quad " << i;
    }
    // Oriented counter-clockwise, so that the nonzero fill covers overlaps.
    double twice_area = 0.0;
    for (std::size_t k = 0; k < 4; ++k) {
      twice_area += quad[k].real() * quad[(k + 1) % 4].imag() - quad[(k + 1) % 4].real() * quad[k].imag();
    }
    EXPECT_GE(twice_area, 0.0) << i;
  }
}

TEST(DiscrepancyLayer, RadiusIsScaleTimesE) {
  const scene::Panel p = panel(Method::P6, three_keyframes(), 9);
  for (const auto predictor : {scene::Predictor::previous, scene::Predictor::average, scene::Predictor::pita}) {
    scene::DiscrepancyLayer layer;
    layer.predictor = predictor;
    layer.scale = 7.5;
    layer.method = Method::P1;
    const Drawing d = panel_drawing(scene_with({layer}, {p}), p);
    const auto circles = shapes<Circle>(d);
    const auto frames = frames_of(p, 9);
    const std::size_t first = predictor == scene::Predictor::previous  ? 1
                              : predictor == scene::Predictor::average ? 1
                                                                       : 3;
    const std::size_t count = predictor == scene::Predictor::average ? 7 : 9 - first;
    ASSERT_EQ(circles.size(), count);
    for (std::size_t k = 0; k < circles.size(); ++k) {
      const std::size_t i = first + k;
      Arrow predicted;
      if (predictor == scene::Predictor::previous) predicted = frames[i - 1];
      if (predictor == scene::Predictor::average) predicted = steady_average(frames[i - 1], frames[i + 1]);
      if (predictor == scene::Predictor::pita) {
        const double ti = static_cast<double>(i) / 8.0, h = 1.0 / 8.0;
        const std::vector<Keyframe> seen{
            {ti - 3 * h, frames[i - 3]}, {ti - 2 * h, frames[i - 2]}, {ti - h, frames[i - 1]}};
        predicted = make_motion(Method::P1, seen)->at(ti);
      }
      // E by its closed form (docs/paper-notes.md N5), independent of PITA Eq. 44-47.
      const Arrow& x = frames[i];
      const double E = (std::norm(predicted.p - x.p) + std::norm(predicted.q() - x.q())) *
                       (1.0 / (x.m * x.m) + 1.0 / (predicted.m * predicted.m));
      EXPECT_NEAR(circles[k]->radius, 7.5 * E, 1e-9 * (1.0 + 7.5 * E)) << k;
      EXPECT_NEAR(std::abs(circles[k]->center - x.p), 0.0, 1e-12);
      EXPECT_EQ(d.items[k].index, static_cast<int>(i));
    }
  }
}

TEST(KeyframesLayer, ArrowsAndSpiralsShowTheKeyframes) {
  std::vector<Keyframe> keys = three_keyframes();
  keys[1].arrow.w += 4.0 * std::numbers::pi;  // two extra turns
  const scene::Panel p = panel(Method::P6, keys);
  const Drawing d = panel_drawing(scene_with({scene::KeyframesLayer{}}, {p}), p);
  const auto arrows = shapes<ArrowShape>(d);
  const auto coils = shapes<Polyline>(d);
  ASSERT_EQ(arrows.size(), 3u);
  ASSERT_EQ(coils.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(std::abs(arrows[i]->from - keys[i].arrow.p), 0.0, 1e-15);
    EXPECT_NEAR(std::abs(arrows[i]->to - keys[i].arrow.q()), 0.0, 1e-12);
    // The spiral ends in the arrow's direction, having turned through w.
    const Point end = coils[i]->points.back() - keys[i].arrow.p;
    EXPECT_NEAR(std::remainder(std::arg(end) - keys[i].arrow.w, 2 * std::numbers::pi), 0.0, 1e-9);
    double turned = 0.0;
    for (std::size_t k = 1; k < coils[i]->points.size(); ++k) {
      turned += std::arg((coils[i]->points[k] - keys[i].arrow.p) / (coils[i]->points[k - 1] - keys[i].arrow.p));
    }
    EXPECT_NEAR(turned, keys[i].arrow.w, 1e-9) << i;
  }
}

TEST(TrajectoryLayer, FollowsTheChosenPoint) {
  const scene::Panel p = panel(Method::P2, three_keyframes());
  scene::TrajectoryLayer layer;
  layer.point = scene::TrackedPoint::middle;
  layer.samples = 101;
  const Drawing d = panel_drawing(scene_with({layer}, {p}), p);
  const auto lines = shapes<Polyline>(d);
  ASSERT_EQ(lines.size(), 1u);
  ASSERT_EQ(lines[0]->points.size(), 101u);
  const auto frames = frames_of(p, 101);
  for (std::size_t i = 0; i < frames.size(); i += 10) {
    EXPECT_NEAR(std::abs(lines[0]->points[i] - 0.5 * (frames[i].p + frames[i].q())), 0.0, 1e-12);
  }
}

TEST(PanelDrawing, NonexistentMotionIsARenderErrorNamingTheKeyframes) {
  // P8 has no motion when v_A + v_C = -2 v_B (kappa = -1).
  std::vector<Keyframe> keys{
      {0.0, Arrow{{0, 0}, 1.0, 0.0}}, {0.5, Arrow{{1, 0}, 1.0, std::numbers::pi}}, {1.0, Arrow{{2, 0}, 1.0, 0.0}}};
  scene::Panel p = panel(Method::P8, keys);
  p.pointer = "/panels/2";
  p.motion_pointer = "/panels/2";  // the panel's method with the scene's keyframes
  try {
    panel_drawing(scene_with({scene::PatternLayer{}}, {p}), p);
    FAIL() << "expected a RenderError";
  } catch (const RenderError& error) {
    EXPECT_EQ(std::string(error.what())
                  .rfind("test.json: /panels/2: method P8 (Lo-Pe) has no motion through "
                         "these keyframes: ",
                         0),
              0u)
        << error.what();
  }
}

TEST(PanelDrawing, OverflowingFramesAreRefusedNotDrawn) {
  scene::Panel p = panel(Method::P2, three_keyframes());
  scene::PatternLayer layer;
  layer.range = scene::TimeRange{0.0, 1e300};
  try {
    panel_drawing(scene_with({layer}, {p}), p);
    FAIL() << "expected a RenderError";
  } catch (const RenderError& error) {
    EXPECT_NE(std::string(error.what()).find("/layers/0"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace pita::render::test

namespace pita::render {
namespace {

TEST(LightnessWhites, FromNoneAtTheSmallestToFourFifthsAtTheLargest) {
  const std::vector<double> whites = lightness_whites({2.0, 4.0, 3.0});
  ASSERT_EQ(whites.size(), 3u);
  EXPECT_DOUBLE_EQ(whites[0], 0.0);
  EXPECT_DOUBLE_EQ(whites[1], 0.8);
  EXPECT_DOUBLE_EQ(whites[2], 0.4);
  EXPECT_EQ(lightness_whites({1.0, 1.0}), (std::vector<double>{0.0, 0.0}));
  EXPECT_TRUE(lightness_whites({}).empty());
  const Color c = lightened(Color{0.0, 0.5, 1.0, 0.7}, 0.5);
  EXPECT_DOUBLE_EQ(c.r, 0.5);
  EXPECT_DOUBLE_EQ(c.g, 0.75);
  EXPECT_DOUBLE_EQ(c.b, 1.0);
  EXPECT_DOUBLE_EQ(c.a, 0.7);
}

// A shapes or pattern layer with "times" draws those frames, the same in the
// figure and in every animation frame (Fig. 24's square at B: a marker, not
// the moving square); the layer without draws the moving frame and its trail.
TEST(ShapesLayer, FixedTimesStayInAnimationFrames) {
  const scene::Scene scene = scene::parse_scene(R"({"method": "P6", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [3, 2], "m": 0.8, "w": 1.5},
      {"t": 2, "p": [6, 0], "m": 1.1, "w": 3}],
      "shapes": [{"polygon": [[0, 0], [1, 0], [1, 1], [0, 1]]}],
      "layers": [{"type": "shapes"}, {"type": "shapes", "times": [1]}, {"type": "pattern", "times": [1, 2]}]})",
                                                "test.json");
  const motion::Stage stage(scene);
  const auto of_layer = [](const Drawing& drawing, const std::string& layer) {
    std::vector<const Item*> items;
    for (const Item& item : drawing.items) {
      if (item.layer == layer) items.push_back(&item);
    }
    return items;
  };
  const Drawing figure = panel_drawing(stage, 0);
  const FrameSelection selection{0.4, {0.2, 0.3}};
  const Drawing frame = panel_drawing(stage, 0, &selection);
  // The moving square: the frame and its trail of two.
  const auto moving = of_layer(frame, "/layers/0");
  ASSERT_EQ(moving.size(), 3u);
  for (const Item* item : moving) EXPECT_TRUE(item->moving);
  // The fixed square at t = 1: the figure's, unchanged and not moving.
  const auto fixed = of_layer(frame, "/layers/1");
  const auto drawn = of_layer(figure, "/layers/1");
  ASSERT_EQ(fixed.size(), 1u);
  ASSERT_EQ(drawn.size(), 1u);
  EXPECT_FALSE(fixed[0]->moving);
  const auto& square = std::get<Polyline>(fixed[0]->shape);
  EXPECT_EQ(square.points, std::get<Polyline>(drawn[0]->shape).points);
  EXPECT_EQ(square.line.opacity, std::get<Polyline>(drawn[0]->shape).line.opacity);
  // It is the square carried onto D(1) = B: its first corner at B.p.
  EXPECT_LT(std::abs(square.points.front() - Point(3, 2)), 1e-12);
  // The pattern's two fixed frames: B and C, full opacity, not moving.
  const auto frames = of_layer(frame, "/layers/2");
  ASSERT_EQ(frames.size(), 2u);
  for (const Item* item : frames) {
    EXPECT_FALSE(item->moving);
    EXPECT_EQ(std::get<Polyline>(item->shape).line.opacity, 1.0);
  }
  EXPECT_LT(std::abs(std::get<Polyline>(frames[1]->shape).points.front() - Point(6, 0)), 1e-12);
}

TEST(SelectedTimes, TheFrameAndItsTrailElseAll) {
  EXPECT_EQ(selected_times(nullptr, {0.0, 1.0}), (std::vector<double>{0.0, 1.0}));
  const FrameSelection selection{0.5, {0.3, 0.4}};
  EXPECT_EQ(selected_times(&selection, {0.0, 1.0}), (std::vector<double>{0.3, 0.4, 0.5}));
}

}  // namespace
}  // namespace pita::render
