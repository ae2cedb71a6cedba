// What a drag in `pita serve --edit` writes (src/serve/scene_edit.cpp): a
// handle per keyframe tail and tip and per pose corner, where the figure draws
// them; dragging a tail moves p, a tip sets q or m and w (keeping the turns),
// a corner moves a triangle's point or sets the matrix that maps the
// reference triangle there.
#include <cmath>
#include <numbers>
#include <string>

#include <Eigen/Core>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "motion/stage.hpp"
#include "render/figure.hpp"
#include "scene/scene.hpp"
#include "serve/json_edit.hpp"
#include "serve/scene_edit.hpp"

namespace pita::serve {
namespace {

struct Drawn {
  scene::Scene scene;
  render::Figure figure;
};

Drawn draw(const std::string& text) {
  Drawn d{scene::parse_scene(text, "e.json"), {}};
  const motion::Stage stage(d.scene);
  d.figure = render::build_figure(stage);
  return d;
}

std::string applied(std::string text, const std::vector<Change>& changes) {
  for (const Change& change : changes) text = replace_value(text, change.pointer, change.value);
  return text;
}

// A copy: the handles are often a temporary list.
Handle find(const std::vector<Handle>& all, const std::string& pointer, const std::string& part) {
  for (const Handle& h : all) {
    if (h.pointer == pointer && h.part == part) return h;
  }
  throw std::runtime_error("no handle " + pointer + " " + part);
}

const std::string kArrows = R"({"method": "P6", "keyframes": [
  {"t": 0, "p": [0, 0], "m": 1, "w": 0.4},
  {"t": 0.5, "p": [3, 1.5], "q": [3.5, 2]},
  {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5, "turns": 1}]})";

TEST(SceneEdit, HandlesAreWhereTheFigureDrawsTheArrows) {
  const Drawn d = draw(kArrows);
  const std::vector<Handle> all = handles(kArrows, motion::Stage(d.scene), d.figure.placements);
  ASSERT_EQ(all.size(), 6u);
  const auto& view = d.figure.placements[0].transform;
  EXPECT_EQ(find(all, "/keyframes/1", "tail").at, view(Point(3, 1.5)));
  EXPECT_EQ(find(all, "/keyframes/1", "tip").at, view(Point(3.5, 2)));
}

TEST(SceneEdit, DraggingATailMovesP) {
  const Drawn d = draw(kArrows);
  const auto& view = d.figure.placements[0].transform;
  const auto changes =
      drag(kArrows, motion::Stage(d.scene), d.figure.placements, 0, "/keyframes/0", "tail", view(Point(1, -2)));
  const auto edited = nlohmann::json::parse(applied(kArrows, changes));
  EXPECT_NEAR(edited["keyframes"][0]["p"][0].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(edited["keyframes"][0]["p"][1].get<double>(), -2.0, 1e-12);
}

TEST(SceneEdit, DraggingATipSetsQOrMagnitudeAndWindingKeepingTheTurns) {
  const Drawn d = draw(kArrows);
  const auto& view = d.figure.placements[0].transform;
  auto edited = nlohmann::json::parse(applied(kArrows, drag(kArrows, motion::Stage(d.scene), d.figure.placements, 0,
                                                            "/keyframes/1", "tip", view(Point(4, 1.5)))));
  EXPECT_NEAR(edited["keyframes"][1]["q"][0].get<double>(), 4.0, 1e-12);
  // keyframe 2: w = 3.5 with one more turn; the tip moved a little keeps both.
  const Point tip = Point(6, 0) + std::polar(2.0, 3.6);
  edited = nlohmann::json::parse(applied(
      kArrows, drag(kArrows, motion::Stage(d.scene), d.figure.placements, 0, "/keyframes/2", "tip", view(tip))));
  EXPECT_NEAR(edited["keyframes"][2]["m"].get<double>(), 2.0, 1e-9);
  EXPECT_NEAR(edited["keyframes"][2]["w"].get<double>(), 3.6, 1e-9);
  EXPECT_EQ(edited["keyframes"][2]["turns"], 1);
}

TEST(SceneEdit, DraggingACornerMovesTheTriangleOrSetsTheMatrix) {
  const std::string text = R"({"method": "SAM", "poses": [
    {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
    {"t": 1, "triangle": [[4, 0], [5, 0], [4, 1]]}]})";
  const Drawn d = draw(text);
  const auto& view = d.figure.placements[0].transform;
  EXPECT_EQ(handles(text, motion::Stage(d.scene), d.figure.placements).size(), 6u);
  auto edited = nlohmann::json::parse(applied(
      text, drag(text, motion::Stage(d.scene), d.figure.placements, 0, "/poses/1", "corner2", view(Point(4.5, 2)))));
  EXPECT_NEAR(edited["poses"][1]["triangle"][2][1].get<double>(), 2.0, 1e-12);
  // Corner 1 of the identity pose to (2, 0): the matrix that maps (0,0),(1,0),(0,1) to (0,0),(2,0),(0,1).
  edited = nlohmann::json::parse(applied(
      text, drag(text, motion::Stage(d.scene), d.figure.placements, 0, "/poses/0", "corner1", view(Point(2, 0)))));
  const auto& m = edited["poses"][0]["matrix"];
  EXPECT_NEAR(m[0][0].get<double>(), 2.0, 1e-12);
  EXPECT_NEAR(m[0][1].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(m[1][1].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(m[0][2].get<double>(), 0.0, 1e-12);
}

// A pose PITA (P6 over affine poses, docs/reference/pose-scenes.md): the
// corners of its three poses are handles, and a drag edits one pose only.
TEST(SceneEdit, ThePosesOfAPosePitaAreDraggedByTheirCorners) {
  const std::string text = R"({"method": "P6", "poses": [
    {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
    {"t": 1, "matrix": [[0.8, -0.9, 3], [0.7, 1.1, 1]]},
    {"t": 2, "triangle": [[5, 3], [4.4, 4.3], [3.8, 2.8]]}]})";
  const Drawn d = draw(text);
  const auto& view = d.figure.placements[0].transform;
  EXPECT_EQ(handles(text, motion::Stage(d.scene), d.figure.placements).size(), 9u);
  const auto edited = nlohmann::json::parse(applied(
      text, drag(text, motion::Stage(d.scene), d.figure.placements, 0, "/poses/2", "corner0", view(Point(5.5, 3)))));
  EXPECT_EQ(edited["method"], "P6");
  EXPECT_NEAR(edited["poses"][2]["triangle"][0][0].get<double>(), 5.5, 1e-12);
  EXPECT_EQ(edited["poses"][1], nlohmann::json::parse(text)["poses"][1]);
}

TEST(SceneEdit, AHandleTheFigureDoesNotHaveIsRefused) {
  const Drawn d = draw(kArrows);
  EXPECT_THROW(drag(kArrows, motion::Stage(d.scene), d.figure.placements, 0, "/keyframes/7", "tail", {0, 0}),
               std::invalid_argument);
  EXPECT_THROW(drag(kArrows, motion::Stage(d.scene), d.figure.placements, 0, "/keyframes/0", "corner0", {0, 0}),
               std::invalid_argument);
  EXPECT_THROW(drag(kArrows, motion::Stage(d.scene), d.figure.placements, 3, "/keyframes/0", "tail", {0, 0}),
               std::invalid_argument);
}

TEST(SceneEdit, APanelWithPosesOfItsOwnEditsThem) {
  const std::string text = R"({"method": "SAM", "poses": [
    {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[2, 0, 1], [0, 2, 0]]}],
    "panels": [{}, {"poses": [{"t": 0, "triangle": [[0, 0], [1, 0], [0, 1]]},
                              {"t": 1, "triangle": [[3, 0], [4, 0], [3, 1]]}]}]})";
  const Drawn d = draw(text);
  const std::vector<Handle> all = handles(text, motion::Stage(d.scene), d.figure.placements);
  for (const Handle& h : all) {
    EXPECT_EQ(h.pointer.rfind(h.panel == 0 ? "/poses/" : "/panels/1/poses/", 0), 0u) << h.panel << " " << h.pointer;
  }
}

TEST(SceneEdit, OnlyTheValuesADragWritesMayBeSentBack) {
  check_change(kArrows, {"/keyframes/0/p", "[1, 2]"});
  check_change(kArrows, {"/keyframes/2/w", "3.5"});
  check_change(kArrows, {"/keyframes/1/t", "0.75"});  // the timeline's
  for (const Change& bad : std::vector<Change>{{"", "{}"},
                                               {"/method", "\"P1\""},
                                               {"/keyframes/0/turns", "5"},
                                               {"/keyframes/0/t/x", "5"},
                                               {"/canvas/t", "5"},
                                               {"/keyframes/0/p", "[1, 2], \"x\": 1"},
                                               {"/keyframes/0/q", "[1, 2]"},
                                               {"/keyframes/9/p", "[1, 2]"},
                                               // Space around the value: written, never undone (fuzz_edit_body).
                                               {"/keyframes/0/p", " [1, 2]"},
                                               {"/keyframes/0/w", "3\n"},
                                               {"/camera/azimuth", " 10"},
                                               {"/keyframes/0/w", ""}}) {
    EXPECT_THROW(check_change(kArrows, bad), std::invalid_argument) << bad.pointer << " = " << bad.value;
  }
}

// A drag writes what it resolves, a tenth of the pixel: short numbers, not
// 16 or 17 digits of where the pointer happened to be.
TEST(SceneEdit, DraggedNumbersAreRoundedToATenthOfThePixel) {
  const Drawn d = draw(kArrows);
  const auto& view = d.figure.placements[0].transform;
  const double step = 0.1 / view.scale;
  const auto changes = drag(kArrows, motion::Stage(d.scene), d.figure.placements, 0, "/keyframes/0", "tail",
                            view(Point(1.23456789, -2.3456789)));
  ASSERT_EQ(changes.size(), 1U);
  const auto p = nlohmann::json::parse(changes[0].value);
  EXPECT_NEAR(p[0].get<double>(), 1.23456789, step);
  EXPECT_NEAR(p[1].get<double>(), -2.3456789, step);
  EXPECT_LE(changes[0].value.size(), 20U) << changes[0].value;  // "[1.2346, -2.3457]" at this scale, not 17 digits each
  EXPECT_EQ(rounded_json(0.8274027248313519, 0.001), "0.827");
  EXPECT_EQ(rounded_json(0.39999999999999997, 0.001), "0.4");
  EXPECT_EQ(rounded_json(1e20 + 12345, 0.001), number_json(1e20 + 12345));  // beyond a double's decimals: as it is
}

// Moving one corner of a matrix pose changes the entries that move; the
// others keep their text byte for byte (0.4 stays 0.4).
TEST(SceneEdit, AMatrixDragRewritesOnlyTheEntriesThatMove) {
  const std::string text = R"({"method": "SAM", "poses": [
    {"t": 0, "matrix": [[1, 0.4, 0], [0, 1, 0.4]]},
    {"t": 1, "matrix": [[2, 0, 1], [0, 2, 0]]}]})";
  const Drawn d = draw(text);
  const auto& view = d.figure.placements[0].transform;
  // Corner 0 (the image of (0, 0)) moved right by 0.5: only b_x changes ... and L, whose columns are edges from it.
  const Point corner0(0, 0.4);
  const auto changes =
      drag(text, motion::Stage(d.scene), d.figure.placements, 0, "/poses/0", "corner0", view(corner0 + Point(0.5, 0)));
  ASSERT_FALSE(changes.empty());
  for (const Change& c : changes) {
    EXPECT_EQ(c.pointer.rfind("/poses/0/matrix/", 0), 0U) << c.pointer;
    check_change(text, c);
  }
  const std::string edited = applied(text, changes);
  const auto m = nlohmann::json::parse(edited)["poses"][0]["matrix"];
  EXPECT_NEAR(m[0][2].get<double>(), 0.5, 0.1 / view.scale);
  EXPECT_NE(edited.find("[0, 1, 0.4]"), std::string::npos) << edited;  // the second row untouched
}

// A 3D pose scene seen by an orthographic camera at azimuth 30, elevation 20,
// looking at a target given: pose 0 a matrix, pose 1 a tetrahedron.
const std::string kSpacePoses = R"({"dimension": 3, "method": "SAM", "poses": [
    {"t": 0, "matrix": [[1, 0.4, 0, 0], [0, 1, 0, 0.25], [0, 0, 1, 0]]},
    {"t": 1, "tetrahedron": [[2, 0, 0], [3, 0.4, 0], [2, 1, 0], [2, 0, 1.5]]}],
  "camera": {"azimuth": 30, "elevation": 20, "target": [1, 0.5, 0.5]}})";

// The camera's right and up, from its azimuth and elevation (degrees): the
// eye towards (cos el cos az, cos el sin az, sin el), z up on the image.
struct CameraAxes {
  Eigen::Vector3d right, up, forward;
};
CameraAxes camera_axes(double azimuth, double elevation) {
  const double a = azimuth * std::numbers::pi / 180.0, e = elevation * std::numbers::pi / 180.0;
  return {{-std::sin(a), std::cos(a), 0.0},
          {-std::sin(e) * std::cos(a), -std::sin(e) * std::sin(a), std::cos(e)},
          {-std::cos(e) * std::cos(a), -std::cos(e) * std::sin(a), -std::sin(e)}};
}

TEST(SceneEdit, HandlesOfSpaceAreWhereTheCameraShowsTheCorners) {
  const Drawn d = draw(kSpacePoses);
  const std::vector<Handle> all = handles(kSpacePoses, motion::Stage(d.scene), d.figure.placements);
  ASSERT_EQ(all.size(), 8u);  // four corners of each of the two poses
  const auto& view = d.figure.placements[0].transform;
  const CameraAxes c = camera_axes(30, 20);
  const Eigen::Vector3d target(1, 0.5, 0.5);
  const auto drawn = [&](const Eigen::Vector3d& x) {
    return view(Point{(x - target).dot(c.right), (x - target).dot(c.up)});
  };
  // Pose 1's corners are its tetrahedron's points; pose 0 maps (0, 1, 0) to (0.4, 1.25, 0).
  EXPECT_LT(std::abs(find(all, "/poses/1", "corner1").at - drawn({3, 0.4, 0})), 1e-9);
  EXPECT_LT(std::abs(find(all, "/poses/1", "corner3").at - drawn({2, 0, 1.5})), 1e-9);
  EXPECT_LT(std::abs(find(all, "/poses/0", "corner2").at - drawn({0.4, 1.25, 0})), 1e-9);
}

// A corner dragged by (dx, dy) pixels moves in the image plane by that many
// pixels of the camera's right and up, its depth kept; the pose's other
// values keep their text.
TEST(SceneEdit, ADragOfACornerOfSpaceMovesItInTheViewsPlane) {
  const Drawn d = draw(kSpacePoses);
  const motion::Stage stage(d.scene);
  const auto& view = d.figure.placements[0].transform;
  const CameraAxes c = camera_axes(30, 20);
  const double pixel = 1.0 / view.scale;
  const auto moved_by = [&](double dx, double dy) { return (dx * c.right - dy * c.up) * pixel; };  // canvas y down

  // The tetrahedron's point 2 moved: only that point is written.
  const Handle h = find(handles(kSpacePoses, stage, d.figure.placements), "/poses/1", "corner2");
  const auto changes = drag(kSpacePoses, stage, d.figure.placements, 0, "/poses/1", "corner2", h.at + Point(37, -21));
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_EQ(changes[0].pointer, "/poses/1/tetrahedron/2");
  check_change(kSpacePoses, changes[0]);
  const auto point = nlohmann::json::parse(changes[0].value);
  const Eigen::Vector3d was(2, 1, 0), now(point[0].get<double>(), point[1].get<double>(), point[2].get<double>());
  EXPECT_LT((now - was - moved_by(37, -21)).norm(), 0.1 * pixel) << now.transpose();
  EXPECT_LT(std::abs((now - was).dot(c.forward)), 0.1 * pixel);
  const std::string edited = applied(kSpacePoses, changes);
  EXPECT_NE(edited.find("[[2, 0, 0], [3, 0.4, 0], "), std::string::npos) << edited;

  // The matrix's corner 1, the image of (1, 0, 0): its first column moves, the rest keeps its text.
  const Handle m = find(handles(kSpacePoses, stage, d.figure.placements), "/poses/0", "corner1");
  const auto entries = drag(kSpacePoses, stage, d.figure.placements, 0, "/poses/0", "corner1", m.at + Point(-15, 30));
  ASSERT_FALSE(entries.empty());
  for (const Change& change : entries) {
    EXPECT_EQ(change.pointer.rfind("/poses/0/matrix/", 0), 0u) << change.pointer;
    EXPECT_EQ(change.pointer.back(), '0') << change.pointer;  // the column of (1, 0, 0)
    check_change(kSpacePoses, change);
  }
  const std::string rewritten = applied(kSpacePoses, entries);
  const auto matrix = nlohmann::json::parse(rewritten)["poses"][0]["matrix"];
  const Eigen::Vector3d corner1(matrix[0][0].get<double>() + matrix[0][3].get<double>(),
                                matrix[1][0].get<double>() + matrix[1][3].get<double>(),
                                matrix[2][0].get<double>() + matrix[2][3].get<double>());
  EXPECT_LT((corner1 - Eigen::Vector3d(1, 0.25, 0) - moved_by(-15, 30)).norm(), 0.1 * pixel) << corner1.transpose();
  EXPECT_NE(rewritten.find(", 0.4, 0, 0], ["), std::string::npos) << rewritten;
  EXPECT_NE(rewritten.find(", 1, 0, 0.25], ["), std::string::npos) << rewritten;
  EXPECT_NE(rewritten.find(", 0, 1, 0]]}"), std::string::npos) << rewritten;
}

TEST(SceneEdit, AChangeOfSpaceNamesAPointOrAnEntryThatIsThere) {
  for (const std::string good : {"/poses/1/tetrahedron/3", "/poses/0/matrix/2/3", "/poses/0/matrix"}) {
    EXPECT_NO_THROW(check_change(kSpacePoses, {good, "[1, 2, 3]"})) << good;
  }
  for (const std::string bad : {"/poses/1/tetrahedron/4", "/poses/0/matrix/3/0", "/poses/0/matrix/0/4",
                                "/poses/1/triangle/0", "/poses/0/tetrahedron/0", "/camera/target"}) {
    EXPECT_THROW(check_change(kSpacePoses, {bad, "1"}), std::invalid_argument) << bad;
  }
}

// "Save view" writes the camera of a 3D scene: exactly its azimuth,
// elevation, distance and auto, within the reader's limits; and its undo
// removes them, or puts the camera's object back.
TEST(SceneEdit, SaveViewWritesTheCameraWithinItsLimits) {
  const std::string text = R"({"dimension": 3, "poses": [], "camera": {"shadow": true}})";
  for (const Change& good : std::vector<Change>{{"/camera/azimuth", "-52.5"},
                                                {"/camera/azimuth", "360"},
                                                {"/camera/elevation", "-90"},
                                                {"/camera/distance", "4.5"},
                                                {"/camera/auto", "false"},
                                                {"/camera/azimuth", "", true},
                                                {"/camera", "", true},
                                                {"/camera", R"({"azimuth": 10, "elevation": 20, "auto": true})"}}) {
    EXPECT_NO_THROW(check_change(text, good)) << good.pointer << " = " << good.value;
  }
  for (const Change& bad : std::vector<Change>{{"/camera/azimuth", "360.5"},
                                               {"/camera/elevation", "90.1"},
                                               {"/camera/elevation", "\"up\""},
                                               {"/camera/distance", "0"},
                                               {"/camera/distance", "-3"},
                                               {"/camera/auto", "1"},
                                               {"/camera/shadow", "false"},
                                               {"/camera/target", "[0, 0, 0]"},
                                               {"/camera/azimuth", "10, \"x\": 1"},
                                               {"/camera", R"({"shadow": false})"},
                                               {"/camera", "[]"},
                                               {"/camera/shadow", "", true},
                                               {"/poses", "", true},
                                               {"/keyframes/0/p", "", true}}) {
    EXPECT_THROW(check_change(text, bad), std::invalid_argument) << bad.pointer << " = " << bad.value;
  }
}

TEST(SceneEdit, NumbersAreWrittenShortAndExact) {
  EXPECT_EQ(number_json(3.0), "3");
  EXPECT_EQ(number_json(-0.0), "0");
  EXPECT_EQ(std::stod(number_json(0.1 + 0.2)), 0.1 + 0.2);
}

// The timeline's rows: the scene's keys and each panel's own, every time
// with the pointer a marker's drag edits.
TEST(SceneEdit, TheTimelineShowsEachKeysTimeByWhereItIsGiven) {
  const std::string text = R"({"method": "SAM", "poses": [
    {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[2, 0, 1], [0, 2, 0]]}],
    "panels": [{}, {"poses": [{"t": 0.5, "triangle": [[0, 0], [1, 0], [0, 1]]},
                              {"t": 2, "triangle": [[3, 0], [4, 0], [3, 1]]}]}, {}]})";
  const Drawn d = draw(text);
  const std::vector<KeyRow> rows = key_rows(text, d.scene);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].keys, "/poses");
  EXPECT_EQ(rows[0].panels, (std::vector<std::size_t>{0, 2}));
  ASSERT_EQ(rows[1].times.size(), 2u);
  EXPECT_EQ(rows[1].keys, "/panels/1/poses");
  EXPECT_EQ(rows[1].times[1].pointer, "/panels/1/poses/1");
  EXPECT_EQ(rows[1].times[1].t, 2.0);
  const std::vector<KeyRow> arrows = key_rows(kArrows, draw(kArrows).scene);
  ASSERT_EQ(arrows.size(), 1u);
  EXPECT_EQ(arrows[0].times.size(), 3u);
}

TEST(SceneEdit, AMovedTimeIsRoundedToWhatTheTimelineResolves) {
  const Drawn d = draw(kArrows);
  const Change change = time_change(kArrows, d.scene, "/keyframes/1", 0.7512345, 0.004);
  EXPECT_EQ(change.pointer, "/keyframes/1/t");
  EXPECT_EQ(change.value, "0.751");
  EXPECT_THROW(time_change(kArrows, d.scene, "/keyframes/7", 0.5, 0.01), std::invalid_argument);
  EXPECT_THROW(time_change(kArrows, d.scene, "/method", 0.5, 0.01), std::invalid_argument);
  EXPECT_THROW(time_change(kArrows, d.scene, "/keyframes/1", std::nan(""), 0.01), std::invalid_argument);
}

}  // namespace
}  // namespace pita::serve
