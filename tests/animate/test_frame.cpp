// Animation frames as figures (src/animate/frame.cpp).
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "animate/frame.hpp"
#include "core/carrier.hpp"
#include "motion/moving_keyframes.hpp"
#include "motion/scene_motion.hpp"
#include "render/drawing.hpp"
#include "scene/scene.hpp"
#include "support/keys.hpp"
#include "support/source_paths.hpp"

namespace pita::animate {
namespace {

using test::kScenes;

constexpr const char* kSquare = R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
    {"t": 1, "p": [3, 2], "m": 0.5, "w": 2}, {"t": 2, "p": [6, 0], "m": 1, "w": 4}],
    "handle": {"p": [0, 0], "q": [1, 0]}, "shapes": [{"polygon": [[0, 0], [1, 0], [1, 1], [0, 1]]}],
    "layers": [{"type": "pattern"}, {"type": "shapes"}, {"type": "keyframes"}, {"type": "trajectory"}],
    "samples": 9, "animation": {"frames": 5, "loop": false, "trail": 2}})";

std::size_t moving_items(const render::Figure& figure) {
  std::size_t n = 0;
  for (const render::Drawing& d : figure.drawings) {
    n += static_cast<std::size_t>(
        std::count_if(d.items.begin(), d.items.end(), [](const render::Item& i) { return i.moving; }));
  }
  return n;
}

TEST(Frame, MotionFrameDrawsTheFrameAndItsTrailOnly) {
  const scene::Scene scene = scene::parse_scene(kSquare, "square.json");
  const Timeline timeline = make_timeline(scene);
  const auto placements = animation_layout(scene, timeline);
  // frame 0: no trail; pattern 1 segment + 1 square
  EXPECT_EQ(moving_items(frame_figure(scene, timeline, timeline.time(0), placements)), 2u);
  // frame 4: 2 trail frames + itself
  const render::Figure last = frame_figure(scene, timeline, timeline.time(4), placements);
  EXPECT_EQ(moving_items(last), 6u);
  // the static layers (3 keyframe arrows with spirals, a trajectory) are there, not moving
  const auto& items = last.drawings[0].items;
  EXPECT_TRUE(std::any_of(items.begin(), items.end(), [](const render::Item& i) {
    return !i.moving && std::holds_alternative<render::ArrowShape>(i.shape);
  }));
}

TEST(Frame, TheSquareIsCarriedByTheSimilarityOfHandleAndFrame) {
  const scene::Scene scene = scene::parse_scene(kSquare, "square.json");
  const Timeline timeline = make_timeline(scene);
  const auto placements = animation_layout(scene, timeline);
  const double t = timeline.time(3);
  const render::Figure frame = frame_figure(scene, timeline, t, placements);
  const Arrow D = motion::build_motion(scene).arrow_at(t);
  // the last polyline of the shapes layer is the square at t: corners p, q, q + i(q - p), p + i(q - p)
  const render::Polyline* square = nullptr;
  for (const render::Item& item : frame.drawings[0].items) {
    if (item.layer == "/layers/1" && item.moving) square = std::get_if<render::Polyline>(&item.shape);
  }
  ASSERT_NE(square, nullptr);
  const Point v = D.q() - D.p;
  const std::vector<Point> expected{D.p, D.q(), D.q() + Point{0, 1} * v, D.p + Point{0, 1} * v};
  ASSERT_EQ(square->points.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_LT(std::abs(square->points[i] - expected[i]), 1e-12) << i;
}

TEST(Frame, EveryFrameSharesOneView) {
  const scene::Scene scene = scene::parse_scene(kSquare, "square.json");
  const Timeline timeline = make_timeline(scene);
  const auto placements = animation_layout(scene, timeline);
  // The view covers every frame: each frame's items lie inside the placement's view.
  for (int k = 0; k < timeline.frames; ++k) {
    const render::Figure frame = frame_figure(scene, timeline, timeline.time(k), placements);
    const auto box = render::bounds(frame.drawings[0]);
    ASSERT_TRUE(box);
    EXPECT_GE(box->min.real(), placements[0].view.min.real() - 1e-9) << k;
    EXPECT_LE(box->max.real(), placements[0].view.max.real() + 1e-9) << k;
    EXPECT_GE(box->min.imag(), placements[0].view.min.imag() - 1e-9) << k;
    EXPECT_LE(box->max.imag(), placements[0].view.max.imag() + 1e-9) << k;
  }
}

TEST(Frame, PatternFrameMovesEverythingButLabels) {
  const scene::Scene scene = scene::load_scene(kScenes / "fig27-animated-pattern.json");
  const Timeline timeline = make_timeline(scene);
  ASSERT_EQ(timeline.what, scene::Animation::What::pattern);
  const auto placements = animation_layout(scene, timeline);
  const render::Figure frame = frame_figure(scene, timeline, 0.5, placements);
  for (const render::Item& item : frame.drawings[0].items) {
    EXPECT_EQ(item.moving, !std::holds_alternative<render::Label>(item.shape));
  }
  // the keyframe arrows drawn are those at tau = 0.5
  const scene::Scene half = motion::scene_at(scene, 0.5);
  bool found = false;
  for (const render::Item& item : frame.drawings[0].items) {
    if (const auto* a = std::get_if<render::ArrowShape>(&item.shape)) {
      found = found || std::abs(a->from - arrow_keys(half).keyframes[0].arrow.p) < 1e-12;
    }
  }
  EXPECT_TRUE(found);
}

TEST(Frame, RecordGivesEveryPanel) {
  const scene::Scene scene = scene::load_scene(kScenes / "fig23-image-motion.json");
  const Timeline timeline = make_timeline(scene);
  const auto record = frame_record(scene, timeline, 30, "frame-0031.png");
  ASSERT_EQ(record["panels"].size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    const Arrow D = motion::build_motion(scene, scene.panels[i]).arrow_at(record["t"].get<double>());
    EXPECT_EQ(record["panels"][i]["pointer"], scene.panels[i].pointer);
    EXPECT_EQ(record["panels"][i]["D"]["w"].get<double>(), D.w) << i;
  }
  EXPECT_EQ(record["D"], record["panels"][0]["D"]);
  // (a) and (d) differ only by the ease: at a quarter of the way they are apart
  EXPECT_NE(record["panels"][0]["D"]["p"], record["panels"][3]["D"]["p"]);
}

TEST(Frame, RecordGivesTimeAndFrame) {
  const scene::Scene scene = scene::parse_scene(kSquare, "square.json");
  const Timeline timeline = make_timeline(scene);
  const auto record = frame_record(scene, timeline, 2, "frame-0003.png");
  EXPECT_EQ(record["frame"], 3);
  EXPECT_EQ(record["file"], "frame-0003.png");
  EXPECT_EQ(record["t"].get<double>(), 1.0);
  const Arrow D = motion::build_motion(scene).arrow_at(1.0);
  EXPECT_EQ(record["D"]["m"].get<double>(), D.m);
  EXPECT_EQ(record["D"]["w"].get<double>(), D.w);
}

}  // namespace
}  // namespace pita::animate
