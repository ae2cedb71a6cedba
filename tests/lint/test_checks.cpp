// Each check of the lint (src/lint/checks.cpp) on a scene made to trip it,
// and the same scene with the defect removed, which it must pass.
#include <algorithm>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "lint/checks.hpp"
#include "lint_support.hpp"
#include "scene/lint_settings.hpp"

namespace pita::lint {
namespace {

using test::arrow_scene;
using test::count;
using test::lint_text;
using test::listed;

TEST(LintChecks, OneFunctionPerCheckOfTheTable) { EXPECT_EQ(check_functions().size(), scene::kLintChecks.size()); }

TEST(LintChecks, AFigureWithRoomIsClean) {
  const Report report = lint_text(arrow_scene(R"("layers": [{"type": "pattern"}, {"type": "keyframes"},
      {"type": "label", "text": "P6", "at": [0, 3]}])"));
  EXPECT_TRUE(report.findings.empty()) << listed(report);
  EXPECT_TRUE(report.clean());
}

TEST(LintChecks, TextOverData) {
  // The label's box covers the middle keyframe at (3, 1.5).
  const Report over = lint_text(arrow_scene(R"("layers": [{"type": "pattern"},
      {"type": "label", "text": "over the frames", "at": [2.5, 1.5], "size": 16}])"));
  ASSERT_EQ(count(over, "text-over-data"), 1) << listed(over);
  EXPECT_EQ(over.findings[0].pointer, "/layers/1");
  EXPECT_NE(over.findings[0].message.find("/layers/0 (pattern)"), std::string::npos) << over.findings[0].message;
  EXPECT_FALSE(over.clean());
  const Report beside = lint_text(arrow_scene(R"("layers": [{"type": "pattern"},
      {"type": "label", "text": "beside", "at": [0, 3.5], "size": 16}])"));
  EXPECT_EQ(count(beside, "text-over-data"), 0) << listed(beside);
}

// "place": "auto" (render/label_placement.hpp): the same label over the
// frames moves beside them, and the lint finds nothing.
TEST(LintChecks, AnAutoLabelIsNotOverData) {
  const Report moved = lint_text(arrow_scene(R"("layers": [{"type": "pattern"},
      {"type": "label", "text": "over the frames", "at": [2.5, 1.5], "size": 16, "place": "auto"}])"));
  EXPECT_TRUE(moved.findings.empty()) << listed(moved);
}

TEST(LintChecks, TextOverlap) {
  const Report two = lint_text(arrow_scene(R"("layers": [{"type": "pattern"},
      {"type": "label", "text": "first", "at": [0, 3.5]}, {"type": "label", "text": "second", "at": [0.2, 3.5]}])"));
  ASSERT_EQ(count(two, "text-overlap"), 1) << listed(two);
  EXPECT_EQ(two.findings[0].pointer, "/layers/2");
  const Report apart = lint_text(arrow_scene(R"("layers": [{"type": "pattern"},
      {"type": "label", "text": "first", "at": [0, 3.5]}, {"type": "label", "text": "second", "at": [4, 3.5]}])"));
  EXPECT_EQ(count(apart, "text-overlap"), 0) << listed(apart);
}

TEST(LintChecks, LegendOverData) {
  // A legend of five lines in a low panel: the room it gets above the drawing is capped at a
  // third of the panel, and it lies on the trajectory along the top of the view.
  const std::string dense =
      R"("canvas": {"width": 300, "height": 150, "margin": 0, "view": {"min": [0, 0], "max": [6, 6]}},
      "layers": [{"type": "trajectory", "point": "p"}, {"type": "legend", "corner": "top-left"}],
      "keyframes": [{"t": 0, "p": [0, 5.8], "m": 1, "w": 0}, {"t": 0.5, "p": [3, 5.8], "m": 1, "w": 0},
                    {"t": 1, "p": [6, 5.8], "m": 1, "w": 0}])";
  const Report over = lint_text(R"({"method": "P6", )" + dense + "}");
  ASSERT_EQ(count(over, "legend-over-data"), 1) << listed(over);
  EXPECT_EQ(over.findings[0].pointer, "/layers/1");
  std::string below = dense;
  below.replace(below.find("top-left"), 8, "bottom-left");
  EXPECT_EQ(count(lint_text(R"({"method": "P6", )" + below + "}"), "legend-over-data"), 0);
}

TEST(LintChecks, OutsideThePanel) {
  // A fixed view that leaves out the last keyframe, and a label beyond the canvas.
  const Report cut = lint_text(
      arrow_scene(R"("layers": [{"type": "keyframes"}, {"type": "label", "text": "far away", "at": [7.5, 0]}])",
                  R"({"width": 600, "height": 400, "view": {"min": [-1, -2], "max": [4, 3]}})"));
  EXPECT_EQ(count(cut, "outside"), 2) << listed(cut);
  bool keyframes = false, label = false;
  for (const Finding& f : cut.findings) {
    keyframes = keyframes || (f.check == "outside" && f.pointer == "/layers/0");
    label = label || (f.check == "outside" && f.pointer == "/layers/1");
  }
  EXPECT_TRUE(keyframes && label) << listed(cut);
  // A title wider than the canvas.
  const Report title = lint_text(arrow_scene(
      R"("title": "a title far too long for a canvas that is only six hundred pixels wide, at eighteen pixels",
      "layers": [{"type": "pattern"}])"));
  ASSERT_EQ(count(title, "outside"), 1) << listed(title);
  EXPECT_EQ(title.findings[0].pointer, "/title");
}

TEST(LintChecks, SmallContent) {
  const std::string wide = R"({"width": 600, "height": 400, "view": {"min": [-30, -20], "max": [30, 20]}})";
  const Report small = lint_text(arrow_scene(R"("layers": [{"type": "pattern"}])", wide));
  ASSERT_EQ(count(small, "small-content"), 1) << listed(small);
  EXPECT_NE(small.findings[0].message.find("could be drawn"), std::string::npos);
  // The same with a lower threshold of the scene's.
  const Report allowed =
      lint_text(arrow_scene(R"("layers": [{"type": "pattern"}], "lint": {"min_content_share": 0.05})", wide));
  EXPECT_EQ(count(allowed, "small-content"), 0) << listed(allowed);
}

// The content fills the panel (two labels far apart) but the motion is a
// speck in its middle: small-motion, not small-content; the scene's lower
// threshold accepts it.
TEST(LintChecks, SmallMotion) {
  const std::string wide = R"({"width": 600, "height": 400, "view": {"min": [-30, -20], "max": [30, 20]}})";
  const std::string layers = R"("layers": [{"type": "pattern"}, {"type": "label", "text": "far west", "at": [-28, -18]},
      {"type": "label", "text": "far east", "at": [22, 18]})";
  const Report small = lint_text(arrow_scene(layers + "]", wide));
  ASSERT_EQ(count(small, "small-motion"), 1) << listed(small);
  EXPECT_EQ(count(small, "small-content"), 0) << listed(small);
  EXPECT_NE(small.findings[0].message.find("could be drawn"), std::string::npos);
  EXPECT_NE(small.findings[0].fix.find("\"view\""), std::string::npos) << small.findings[0].fix;
  const Report allowed = lint_text(arrow_scene(layers + R"(], "lint": {"min_motion_share": 0.05})", wide));
  EXPECT_EQ(count(allowed, "small-motion"), 0) << listed(allowed);
  // Without the far labels the view is fitted to the motion: nothing to find.
  EXPECT_EQ(count(lint_text(arrow_scene(R"("layers": [{"type": "pattern"}])")), "small-motion"), 0);
}

// Every finding says what to change in the scene.
TEST(LintChecks, EveryFindingHasAFix) {
  const std::string wide = R"({"width": 600, "height": 400, "view": {"min": [-30, -20], "max": [30, 20]}})";
  const Report report = lint_text(arrow_scene(
      R"("title": "a title far too long for a canvas that is only six hundred pixels wide, at eighteen pixels",
      "layers": [{"type": "pattern"}, {"type": "pattern"}, {"type": "label", "text": "over", "at": [0, 0]},
      {"type": "trajectory", "point": "p", "color": "#808080"}, {"type": "trajectory", "point": "q", "color": "#808080"}])",
      wide));
  ASSERT_GE(report.findings.size(), 4u) << listed(report);
  for (const Finding& f : report.findings) {
    EXPECT_FALSE(f.fix.empty()) << f.check << ": " << f.message;
    EXPECT_NE(describe(f).find("; fix: "), std::string::npos);
  }
}

TEST(LintChecks, ShortFrames) {
  // Frames of magnitude 0.01 in a view 10 units wide: under a pixel each.
  const std::string tiny = R"({"method": "P6", "canvas": {"width": 400, "height": 300},
      "keyframes": [{"t": 0, "p": [0, 0], "m": 0.01, "w": 0}, {"t": 0.5, "p": [5, 2], "m": 0.01, "w": 1},
                    {"t": 1, "p": [10, 0], "m": 0.01, "w": 2}],
      "layers": [{"type": "pattern"}, {"type": "trajectory", "point": "p"}])";
  const Report short_frames = lint_text(tiny + "}");
  ASSERT_EQ(count(short_frames, "short-frame"), 1) << listed(short_frames);
  EXPECT_EQ(short_frames.findings[0].pointer, "/layers/0");
  EXPECT_NE(short_frames.findings[0].message.find("17 of the 17 frames"), std::string::npos)
      << short_frames.findings[0].message;
  EXPECT_EQ(count(lint_text(tiny + R"(, "lint": {"min_frame_pixels": 0})" + "}"), "short-frame"), 0);
}

// Two panels, P6 and P1, over the same keyframes, and a claim that they differ.
std::string claimed_scene(const std::string& test, const std::string& view, const std::string& lint = "") {
  return arrow_scene(R"("panels": [{"method": "P6"}, {"method": "P1"}], "layers": [{"type": "pattern"}],
      "claims": [{"says": "P1 leaves P6", "panel": 1, "measure": "frame-distance:/panels/0", )" +
                         test + "}]" + lint,
                     R"({"width": 600, "height": 300, "view": )" + view + "}");
}

TEST(LintChecks, SmallFeature) {
  // The two motions differ by about a unit (the claim holds): tens of pixels
  // in a view 12 units wide, a few in one 600 units wide.
  const std::string near = R"({"min": [-3, -3], "max": [9, 3]})";
  const std::string far = R"({"min": [-300, -150], "max": [300, 150]})";
  EXPECT_EQ(count(lint_text(claimed_scene(R"("above": 0.1)", near)), "small-feature"), 0);
  const Report tiny = lint_text(claimed_scene(R"("above": 0.1)", far));
  ASSERT_EQ(count(tiny, "small-feature"), 1) << listed(tiny);
  const Finding& f = tiny.findings.back();
  EXPECT_EQ(f.pointer, "/claims/0");
  EXPECT_NE(f.message.find("\"P1 leaves P6\""), std::string::npos) << f.message;
  EXPECT_NE(f.message.find("min_feature_pixels (6 px)"), std::string::npos) << f.message;
  EXPECT_NE(f.fix.find("\"view\""), std::string::npos) << f.fix;
  // A claim that they do not differ asks nothing to be seen, and one that
  // fails is pita check's to report; the threshold is the scene's.
  EXPECT_EQ(count(lint_text(claimed_scene(R"("below": 100)", far)), "small-feature"), 0);
  EXPECT_EQ(count(lint_text(claimed_scene(R"("above": 100)", far)), "small-feature"), 0);
  EXPECT_EQ(count(lint_text(claimed_scene(R"("above": 0.1)", far, R"(, "lint": {"min_feature_pixels": 0})")),
                  "small-feature"),
            0);
  // The distance is the one drawn, not the claim's bound: a bound far below
  // it does not make the difference small.
  EXPECT_EQ(count(lint_text(claimed_scene(R"("above": 1e-6)", near)), "small-feature"), 0);
}

TEST(LintChecks, SameColorSeries) {
  const Report alike = lint_text(arrow_scene(R"("layers": [{"type": "trajectory", "point": "p", "color": "#808080"},
      {"type": "trajectory", "point": "q", "color": "#808080"}])"));
  ASSERT_EQ(count(alike, "same-color"), 1) << listed(alike);
  EXPECT_EQ(alike.findings[0].pointer, "/layers/1");
  // A dash tells them apart.
  EXPECT_EQ(count(lint_text(arrow_scene(R"("layers": [{"type": "trajectory", "point": "p", "color": "#808080"},
      {"type": "trajectory", "point": "q", "color": "#808080", "dash": [4, 3]}])")),
                  "same-color"),
            0);
  // Keyframes coloured apart, two of them alike.
  const Report keys = lint_text(R"({"method": "P9", "canvas": {"width": 600, "height": 400},
      "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [2, 1], "m": 1, "w": 0},
                    {"t": 2, "p": [4, 0], "m": 1, "w": 0}, {"t": 3, "p": [6, 1], "m": 1, "w": 0}],
      "layers": [{"type": "keyframes", "colors": ["red", "green", "green", "blue"]}]})");
  ASSERT_EQ(count(keys, "same-color"), 1) << listed(keys);
  EXPECT_NE(keys.findings[0].message.find("items 1 and 2"), std::string::npos) << keys.findings[0].message;
  // Each message names the field that fixes it.
  EXPECT_NE(keys.findings[0].fix.find("/layers/0 one colour per item in its \"colors\""), std::string::npos)
      << keys.findings[0].fix;
  EXPECT_NE(alike.findings[0].fix.find("\"dash\""), std::string::npos) << alike.findings[0].fix;
  // The default colours tell any number of keyframes apart: a newcomer's
  // first four-keyframe scene, with no "colors" and no "layers", is clean.
  const Report four = lint_text(R"({"method": "P9", "canvas": {"width": 600, "height": 400},
      "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [2, 1], "m": 1, "w": 0},
                    {"t": 2, "p": [4, 0], "m": 1, "w": 0}, {"t": 3, "p": [6, 1], "m": 1, "w": 0}]})");
  EXPECT_EQ(count(four, "same-color"), 0) << listed(four);
}

// A cube moved along the camera's line of sight: each copy behind the one
// after it. Seen across the motion, or with a lenient max_hidden_share, none.
TEST(LintChecks, HiddenCopy) {
  const auto scene = [](double azimuth, const std::string& more) {
    return fmt::format(R"({{"dimension": 3, "method": "SAM", "samples": 5, "shapes": [{{"solid": "cube"}}],
      "poses": [{{"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]}},
                {{"t": 1, "matrix": [[1, 0, 0, 8], [0, 1, 0, 0], [0, 0, 1, 0]]}}],
      "camera": {{"azimuth": {}, "elevation": 10}},
      "layers": [{{"type": "shapes", "fill": "#a0c8e8"}}{}]{}}})",
                       azimuth, R"(, {"type": "poses", "colors": ["#00a000", "#d00000"], "fill_opacity": 0})", more);
  };
  const Report along = lint_text(scene(180, ""));  // from -x: the later copies in front
  ASSERT_EQ(count(along, "hidden-copy"), 1) << listed(along);
  EXPECT_EQ(along.findings[0].pointer, "/layers/0");
  EXPECT_NE(along.findings[0].message.find("of the 5 copies of /layers/0"), std::string::npos)
      << along.findings[0].message;
  EXPECT_NE(along.findings[0].fix.find("\"auto\": true"), std::string::npos);  // the fix
  EXPECT_EQ(count(lint_text(scene(90, "")), "hidden-copy"), 0) << listed(lint_text(scene(90, "")));
  EXPECT_EQ(count(lint_text(scene(180, R"(, "lint": {"max_hidden_share": 1})")), "hidden-copy"), 0);
  // Opaque poses drawn over copies between them hide those: seen across the
  // motion, the two poses only cover the copies at their own knots, which
  // they stand for.
  const std::string opaque = fmt::format(
      R"({{"dimension": 3, "method": "SAM", "samples": 5, "shapes": [{{"solid": "cube"}}],
      "poses": [{{"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]}},
                {{"t": 1, "matrix": [[1, 0, 0, 8], [0, 1, 0, 0], [0, 0, 1, 0]]}}],
      "camera": {{"azimuth": 90, "elevation": 10}},
      "layers": [{{"type": "shapes", "fill": "#a0c8e8"}}, {{"type": "poses", "colors": ["#00a000", "#d00000"]}}]}})");
  EXPECT_EQ(count(lint_text(opaque), "hidden-copy"), 0) << listed(lint_text(opaque));
}

}  // namespace
}  // namespace pita::lint
