// The motion stage (src/motion/scene_motion.cpp): one build per scene or
// panel for arrows and poses, the typed NoMotion error with its pointer, and
// timing applied on top of the method.
#include <cmath>
#include <numeric>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "core/ease.hpp"
#include "core/pitas/registry.hpp"
#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"
#include "scene/scene.hpp"
#include "support/keys.hpp"

namespace pita::motion {
namespace {

const std::string kKeyframes = R"("keyframes": [
    {"t": 0, "p": [0, 0], "m": 1, "w": 0.4}, {"t": 0.25, "p": [3, 1.5], "m": 0.6, "w": 2},
    {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}])";

scene::Scene arrows(const std::string& extra = "", const std::string& method = "P6") {
  return scene::parse_scene("{\"method\": \"" + method + "\", " + kKeyframes + extra + "}", "s.json");
}

std::string error_of(const scene::Scene& scene) {
  try {
    (void)build_motion(scene);
  } catch (const NoMotion& error) {
    return error.pointer() + " | " + error.reason();
  }
  return "(no error)";
}

TEST(SceneMotion, ArrowsWithoutTimingAreTheMethodItself) {
  const scene::Scene scene = arrows();
  const SceneMotion motion = build_motion(scene);
  EXPECT_TRUE(motion.is<ArrowTrack>());
  EXPECT_EQ(motion.method_id(), "P6");
  EXPECT_EQ(motion.label(), "P6 (La-LP)");
  EXPECT_EQ(motion.knots(), (std::vector<double>{0.0, 0.25, 1.0}));
  const auto direct = make_motion(Method::P6, arrow_keys(scene).keyframes);
  for (double t : {-0.5, 0.0, 0.1, 0.25, 0.7, 1.0, 1.3}) {
    const Arrow a = motion.arrow_at(t), b = direct->at(t);
    EXPECT_EQ(a.p, b.p);
    EXPECT_EQ(a.m, b.m);
    EXPECT_EQ(a.w, b.w);
  }
}

// Keyframes "as-given" reach the method in the order written (PITA Eq. 42's
// P(b, B, a, A, c, C, t), docs/paper-notes.md N41): the motion still passes
// through each keyframe at its knot and runs from the least knot to the
// greatest; an order-independent method (P1, Fig. 10) gives the same frames as
// the sorted scene, one that is not (P6) does not.
// Each kind of motion answers for itself only: asked for another kind it
// throws NoMotion naming the file (it never dereferences a motion it lacks).
TEST(SceneMotion, EachKindAnswersForItselfAndRefusesTheOthers) {
  const scene::Scene points = scene::parse_scene(R"({"method": "P6", "points": [
      {"t": 0, "p": [0, 0]}, {"t": 1, "p": [1, 1]}, {"t": 2, "p": [2, 0]}, {"t": 3, "p": [3, 1]}]})",
                                                 "s.json");
  const scene::Scene poses = scene::parse_scene(R"({"method": "SAM", "poses": [
      {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[2, 0, 1], [0, 2, 0]]}]})",
                                                "s.json");
  const SceneMotion arrow_motion = build_motion(arrows());
  const SceneMotion point_motion = build_motion(points);
  const SceneMotion pose_motion = build_motion(poses);
  EXPECT_TRUE(arrow_motion.is<ArrowTrack>());
  EXPECT_TRUE(point_motion.is<PointTrack>());
  EXPECT_TRUE(pose_motion.is<PlanePoses>());
  EXPECT_EQ(point_motion.knots(), (std::vector<double>{0.0, 1.0, 2.0, 3.0}));
  EXPECT_LT(std::abs(point_motion.point_at(1.0) - Point(1.0, 1.0)), 1e-12);
  EXPECT_LT((pose_motion.pose_at<Affine2>(1.0).b - Eigen::Vector2d(1.0, 0.0)).norm(), 1e-12);

  const auto refused = [](auto&& ask) {
    try {
      ask();
    } catch (const NoMotion& error) {
      return error.file() + " " + error.pointer() + " | " + error.reason();
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(refused([&] { (void)arrow_motion.pose_at<Affine2>(0.5); }),
            "s.json /keyframes | this motion is of keyframe arrows, not of poses of the plane");
  EXPECT_EQ(refused([&] { (void)arrow_motion.point_at(0.5); }),
            "s.json /keyframes | this motion is of keyframe arrows, not of timed points");
  EXPECT_EQ(refused([&] { (void)arrow_motion.pose_at<Affine3>(0.5); }),
            "s.json /keyframes | this motion is of keyframe arrows, not of poses of space");
  EXPECT_EQ(refused([&] { (void)point_motion.arrow_at(0.5); }),
            "s.json /points | this panel has timed \"points\", not keyframes: draw it with a "
            "\"point-trajectory\" layer");
  EXPECT_EQ(refused([&] { (void)point_motion.point_path(scene::TrackedPoint::start); }),
            "s.json /points | this panel has timed \"points\", not keyframes: draw it with a "
            "\"point-trajectory\" layer");
  EXPECT_EQ(refused([&] { (void)pose_motion.arrows(); }),
            "s.json /poses | this motion is of poses of the plane, not of keyframe arrows");
  EXPECT_EQ(refused([&] { (void)pose_motion.pose_velocity<Affine3>(0.5); }),
            "s.json /poses | this motion is of poses of the plane, not of poses of space");
  EXPECT_FALSE(point_motion.chain().has_value());
  EXPECT_FALSE(pose_motion.chain().has_value());
}

TEST(SceneMotion, KnotsAsGivenKeepTheOrderWritten) {
  const std::string swapped = R"("options": {"knots": "as-given"}, "keyframes": [
    {"t": 0.25, "p": [3, 1.5], "m": 0.6, "w": 2}, {"t": 0, "p": [0, 0], "m": 1, "w": 0.4},
    {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}])";
  for (const std::string method : {"P1", "P6"}) {
    const scene::Scene as_given = scene::parse_scene("{\"method\": \"" + method + "\", " + swapped + "}", "s.json");
    const SceneMotion motion = build_motion(as_given);
    EXPECT_EQ(motion.knots(), (std::vector<double>{0.0, 0.25, 1.0}));
    for (const Keyframe& k : arrow_keys(as_given).keyframes) {
      const Arrow a = motion.arrow_at(k.t);
      EXPECT_LT(std::abs(a.p - k.arrow.p), 1e-12) << method;
      EXPECT_LT(std::abs(a.q() - k.arrow.q()), 1e-12) << method;
    }
    const SceneMotion sorted = build_motion(arrows("", method));
    double apart = 0;
    for (double t : {0.1, 0.4, 0.7}) apart = std::max(apart, std::abs(motion.arrow_at(t).p - sorted.arrow_at(t).p));
    if (method == "P1") {
      EXPECT_LT(apart, 1e-12);
    } else {
      EXPECT_GT(apart, 1e-2);
    }
  }
}

TEST(SceneMotion, EaseOverTheMotionWarpsTheMethodsTime) {
  const scene::Scene scene = arrows(R"(, "timing": {"ease": "ease-in"})");
  const SceneMotion motion = build_motion(scene);
  const auto direct = make_motion(Method::P6, arrow_keys(scene).keyframes);
  const Ease in = *find_named_ease("ease-in");
  for (double t : {0.1, 0.25, 0.5, 0.9}) {
    const Arrow a = motion.arrow_at(t), b = direct->at(ease(in, t));
    EXPECT_EQ(a.p, b.p) << t;
    EXPECT_EQ(a.w, b.w) << t;
  }
  // The keyframes at the ends are kept; the middle one is not reached at its knot.
  EXPECT_EQ(motion.arrow_at(0.0).p, direct->at(0.0).p);
  EXPECT_EQ(motion.arrow_at(1.0).w, direct->at(1.0).w);
  EXPECT_NEAR(std::abs(motion.arrow_at(0.0).p - arrow_keys(scene).keyframes[0].arrow.p), 0.0, 1e-15);
  EXPECT_GT(std::abs(motion.arrow_at(0.25).p - arrow_keys(scene).keyframes[1].arrow.p), 1e-3);
  // Outside the knots the warp is the identity.
  EXPECT_EQ(motion.arrow_at(1.5).p, direct->at(1.5).p);
}

TEST(SceneMotion, PerSpanReachesEveryKeyframeAtItsKnot) {
  const scene::Scene scene = arrows(R"(, "timing": {"ease": "sine", "arc_length": "mid", "per": "span"})");
  const SceneMotion motion = build_motion(scene);
  for (const Keyframe& key : arrow_keys(scene).keyframes) {
    const Arrow a = motion.arrow_at(key.t);
    EXPECT_NEAR(std::abs(a.p - key.arrow.p), 0.0, 1e-12) << key.t;
    EXPECT_NEAR(a.w, key.arrow.w, 1e-12) << key.t;
  }
}

TEST(SceneMotion, ArcLengthSpacesTheTrackedPointEvenly) {
  const SceneMotion motion = build_motion(arrows(R"(, "timing": {"arc_length": "q"})"));
  const std::vector<double> times = uniform_times(motion, 21);
  const std::vector<Frame> frames = sample_arrows(motion, times);
  // The length of q's path between consecutive frames, measured independently
  // of the table: a polyline of 4000 chords of the unwarped method per step.
  const auto direct = make_motion(Method::P6, arrow_keys(arrows()).keyframes);
  std::vector<double> steps;
  for (std::size_t i = 1; i < times.size(); ++i) {
    const double from = motion.motion_time(times[i - 1]), to = motion.motion_time(times[i]);
    double length = 0.0;
    Point previous = direct->at(from).q();
    for (int k = 1; k <= 4000; ++k) {
      const Point next = direct->at(from + (to - from) * k / 4000.0).q();
      length += std::abs(next - previous);
      previous = next;
    }
    steps.push_back(length);
  }
  const double mean = std::accumulate(steps.begin(), steps.end(), 0.0) / static_cast<double>(steps.size());
  for (std::size_t i = 0; i < steps.size(); ++i) EXPECT_NEAR(steps[i] / mean, 1.0, 1e-6) << "step " << i;
  EXPECT_EQ(frames[0].t, 0.0);  // frames report the scene time they were asked for
  EXPECT_EQ(frames[20].t, 1.0);
  EXPECT_EQ(frames[5].t, times[5]);
}

TEST(SceneMotion, NoMotionNamesTheKeyframesAndTheMethod) {
  // P7 at kappa = -1: A and C both against B with its magnitude.
  const scene::Scene scene = scene::parse_scene(R"({"method": "P7", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 3.141592653589793}, {"t": 0.5, "p": [1, 0], "m": 1, "w": 0},
      {"t": 1, "p": [2, 0], "m": 1, "w": 3.141592653589793}]})",
                                                "s.json");
  const std::string error = error_of(scene);
  EXPECT_EQ(error.rfind("/keyframes | method P7 (Ra-Pe) has no motion through these keyframes: ", 0), 0u) << error;
}

TEST(SceneMotion, ArcLengthOfAStillPointIsRefusedAtItsPointer) {
  // Every keyframe starts at the origin: P1's point p never moves.
  const scene::Scene scene = scene::parse_scene(R"({"method": "P1", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 0.5, "p": [0, 0], "m": 2, "w": 1},
      {"t": 1, "p": [0, 0], "m": 1, "w": 2}], "timing": {"arc_length": "p"}})",
                                                "s.json");
  EXPECT_EQ(error_of(scene),
            "/timing/arc_length | cannot pace P1 (Pa-Ca) by the arc length of p: the path "
            "has zero length: the point does not move");
  EXPECT_NO_THROW((void)build_motion(scene::parse_scene(R"({"method": "P1", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 0.5, "p": [0, 0], "m": 2, "w": 1},
      {"t": 1, "p": [0, 0], "m": 1, "w": 2}], "timing": {"arc_length": "q"}})",
                                                        "s.json")));
}

TEST(SceneMotion, PanelsGetTheirOwnMotionAndPointer) {
  const scene::Scene scene = scene::parse_scene("{\"method\": \"P6\", " + kKeyframes + R"(,
      "panels": ["P1", {"method": "P3", "timing": {"ease": "ease-out"}},
                 {"method": "SMA", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 2, "p": [1, 1], "m": 2, "w": 1}]}]})",
                                                "s.json");
  ASSERT_EQ(scene.panels.size(), 3u);
  EXPECT_EQ(build_motion(scene, scene.panels[0]).method_id(), "P1");
  EXPECT_EQ(build_motion(scene, scene.panels[0]).pointer(), "/panels/0");
  const SceneMotion eased = build_motion(scene, scene.panels[1]);
  EXPECT_FALSE(eased.warp().is_identity());
  EXPECT_TRUE(build_motion(scene, scene.panels[0]).warp().is_identity());
  const SceneMotion sma = build_motion(scene, scene.panels[2]);
  EXPECT_EQ(sma.pointer(), "/panels/2/keyframes");
  EXPECT_EQ(sma.knots(), (std::vector<double>{0.0, 2.0}));
}

TEST(SceneMotion, TimingAtTheTopIsEveryPanelsDefault) {
  const scene::Scene scene = scene::parse_scene(
      "{\"method\": \"P6\", " + kKeyframes + R"(, "timing": {"ease": "sine"}, "panels": ["P1", "P6"]})", "s.json");
  for (const scene::Panel& panel : scene.panels) EXPECT_EQ(panel.timing.ease, *find_named_ease("sine"));
}

TEST(SceneMotion, PosesAreBuiltOnceWithTheirTiming) {
  const scene::Scene scene = scene::parse_scene(R"({"method": "polySAM", "poses": [
      {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[0, -1, 2], [1, 0, 0]]},
      {"t": 3, "matrix": [[2, 0, 4], [0, 2, 1]]}], "timing": {"arc_length": "p", "per": "span"}})",
                                                "s.json");
  const SceneMotion motion = build_motion(scene);
  EXPECT_TRUE(motion.is<PlanePoses>());
  EXPECT_EQ(motion.method_id(), "polySAM");
  for (const TimedPose& pose : plane_keys(scene).poses) {
    EXPECT_LT((motion.pose_at<Affine2>(pose.t).L - pose.pose.L).norm(), 1e-12);
    EXPECT_LT((motion.pose_at<Affine2>(pose.t).b - pose.pose.b).norm(), 1e-12);
  }
  // The image of the reference triangle's first point moves evenly within each span.
  const auto path = motion.point_path(scene::TrackedPoint::start);
  const Point at_quarter = path(motion.motion_time(0.25)), at_half = path(motion.motion_time(0.5));
  const Point start = path(0.0);
  EXPECT_NEAR(std::abs(at_half - start) / std::abs(at_quarter - start), 2.0, 0.05);
  EXPECT_NO_THROW((void)motion.pose_velocity<Affine2>(0.5));
}

TEST(SceneMotion, NoSamBetweenPosesIsANoMotionAtThePoses) {
  const scene::Scene scene = scene::parse_scene(R"({"method": "SAM", "poses": [
      {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[-2, 0, 3], [0, -0.5, 1]]}]})",
                                                "s.json");
  const std::string error = error_of(scene);
  EXPECT_EQ(error.rfind("/poses | no SAM exists between these poses: ", 0), 0u) << error;
}

TEST(SceneMotion, NonFiniteFramesAreNoMotionNotNaN) {
  const SceneMotion motion = build_motion(arrows());
  try {
    (void)motion.arrow_at(1e300);
    FAIL() << "no error";
  } catch (const NoMotion& error) {
    EXPECT_EQ(error.pointer(), "/keyframes");
    EXPECT_NE(error.reason().find("no finite frame at t = 1e+300"), std::string::npos) << error.what();
  }
}

// 3D pose scenes: the stage builds SamFamilyMotion<Affine3> once; pose_at<Affine3> is its pose,
// and the plane's verbs refuse the motion with NoMotion at /dimension.
TEST(SceneMotion, SpaceScenesGiveTheirPosesInSpace) {
  const scene::Scene scene = scene::parse_scene(R"({"dimension": 3, "method": "SAM", "poses": [
      {"t": 1, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
      {"t": 3, "matrix": [[4, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0]]}]})",
                                                "s.json");
  const SceneMotion motion = build_motion(scene);
  ASSERT_TRUE(motion.is<SpacePoses>());
  EXPECT_EQ(motion.knots(), (std::vector<double>{1.0, 3.0}));
  // x -> 4x + 3 is a scaling by 4 about x = -1; half way it scales by 2 about it.
  const Affine3 half = motion.pose_at<Affine3>(2.0);
  EXPECT_NEAR(half.L(0, 0), 2.0, 1e-15);
  EXPECT_NEAR(half.b(0), 1.0, 1e-15);
  EXPECT_EQ(half.L(1, 1), 1.0);
  try {
    (void)motion.pose_at<Affine2>(2.0);
    ADD_FAILURE() << "no error";
  } catch (const NoMotion& error) {
    EXPECT_NE(std::string(error.what()).find("/dimension"), std::string::npos) << error.what();
  }
  const std::vector<double> times = {1.0, 2.0};
  EXPECT_EQ(sample_poses<Affine3>(motion, times).size(), 2u);
  EXPECT_NE(frames_text(scene.panels[0], motion, times, FramesFormat::csv).find("t,a,b,c,tx"), std::string::npos);
}

// "timing" in space: the warp is the 2D one; arc length follows a point of
// the reference tetrahedron through space.
const std::string kSpacePoses = R"("dimension": 3, "method": "polySAM", "poses": [
    {"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
    {"t": 1, "matrix": [[0, -2, 0, 3], [2, 0, 0, 1], [0, 0, 1.5, -2]]},
    {"t": 3, "matrix": [[-0.6, -0.8, 0.3, 1], [0.8, -0.6, 0, 4], [0, 0.2, 2.5, 7]]}])";

scene::Scene space(const std::string& extra = "") {
  return scene::parse_scene("{" + kSpacePoses + extra + "}", "s.json");
}

TEST(SceneMotion, SpaceScenesEaseTheirTime) {
  const SceneMotion eased = build_motion(space(R"(, "timing": {"ease": "cubic"})"));
  const SceneMotion plain = build_motion(space());
  for (double t : {0.0, 0.3, 1.0, 1.7, 2.5, 3.0}) {
    const double x = t / 3.0, tau = 3.0 * (3 * x * x - 2 * x * x * x);  // the cubic ease, chapter Eq. 3.20
    const Affine3 got = eased.pose_at<Affine3>(t), expected = plain.pose_at<Affine3>(tau);
    EXPECT_LT((got.L - expected.L).norm() + (got.b - expected.b).norm(), 1e-12) << t;
  }
}

TEST(SceneMotion, SpaceScenesPacedByArcLengthMoveThePointEvenly) {
  const scene::Scene scene = space(R"(, "timing": {"arc_length": "mid", "per": "span"})");
  const SceneMotion motion = build_motion(scene);
  const SceneMotion plain = build_motion(space());
  // Every pose at its knot.
  for (const TimedPoseOf<Affine3>& pose : space_keys(scene).poses) {
    const Affine3 at = motion.pose_at<Affine3>(pose.t);
    EXPECT_LT((at.L - pose.pose.L).norm() + (at.b - pose.pose.b).norm(), 1e-12) << pose.t;
  }
  // The midpoint of the reference tetrahedron's first two points covers equal
  // lengths in equal times within each span, measured by 4000 chords of the
  // unwarped motion per step.
  const Eigen::Vector3d mid(0.5, 0.0, 0.0);
  for (const auto& [from, to] : {std::pair{0.0, 1.0}, std::pair{1.0, 3.0}}) {
    std::vector<double> steps;
    for (int i = 0; i < 8; ++i) {
      const double a = motion.motion_time(from + (to - from) * i / 8.0);
      const double b = motion.motion_time(from + (to - from) * (i + 1) / 8.0);
      double length = 0.0;
      Eigen::Vector3d previous = apply(plain.pose_at<Affine3>(a), mid);
      for (int k = 1; k <= 4000; ++k) {
        const Eigen::Vector3d next = apply(plain.pose_at<Affine3>(a + (b - a) * k / 4000.0), mid);
        length += (next - previous).norm();
        previous = next;
      }
      steps.push_back(length);
    }
    const double mean = std::accumulate(steps.begin(), steps.end(), 0.0) / 8.0;
    for (std::size_t i = 0; i < steps.size(); ++i) EXPECT_NEAR(steps[i] / mean, 1.0, 1e-6) << from << " step " << i;
  }
}

TEST(SceneMotion, SpaceVelocityIncludesTheWarpsRate) {
  const SceneMotion motion = build_motion(space(R"(, "timing": {"ease": "ease-in-out", "arc_length": "p"})"));
  for (double t : {0.4, 1.5, 2.2}) {
    const double h = 1e-5;
    const Affine3 ahead = motion.pose_at<Affine3>(t + h), behind = motion.pose_at<Affine3>(t - h);
    const Affine3 rate = motion.pose_velocity<Affine3>(t);
    const Eigen::Matrix3d dL = (ahead.L - behind.L) / (2 * h);
    const Eigen::Vector3d db = (ahead.b - behind.b) / (2 * h);
    EXPECT_LT((rate.L - dL).norm() + (rate.b - db).norm(), 1e-5 * (dL.norm() + db.norm())) << t;
  }
}

TEST(SceneMotion, SpaceArcLengthOfAStillPointIsRefusedAtItsPointer) {
  // A turn about the z axis: the reference tetrahedron's first point, the
  // origin, does not move.
  const scene::Scene scene = scene::parse_scene(R"({"dimension": 3, "method": "SAM", "poses": [
      {"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
      {"t": 1, "matrix": [[0, -1, 0, 0], [1, 0, 0, 0], [0, 0, 1, 0]]}], "timing": {"arc_length": "p"}})",
                                                "s.json");
  EXPECT_EQ(error_of(scene),
            "/timing/arc_length | cannot pace SAM by the arc length of p: the path has zero "
            "length: the point does not move");
}

}  // namespace
}  // namespace pita::motion
