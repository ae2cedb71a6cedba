// What a request of `pita serve --edit` changes (src/serve/edit_request.cpp):
// the views the page holds while it edits (validated, and a drag read and
// drawn in them keeps the handle under the pointer), a time moved on the
// timeline, and changes made and undone byte for byte.
#include <cmath>
#include <optional>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "motion/stage.hpp"
#include "render/figure.hpp"
#include "scene/located_error.hpp"
#include "scene/scene.hpp"
#include "serve/edit_request.hpp"

namespace pita::serve {
namespace {

using Json = nlohmann::ordered_json;

const std::string kTwoPanelArrows = R"({"method": "P6", "keyframes": [
  {"t": 0, "p": [0, 0], "m": 1, "w": 0.4},
  {"t": 0.5, "p": [3, 1.5], "q": [3.5, 2]},
  {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5, "turns": 1}],
  "panels": [{"title": "one"}, {"title": "two"}]})";

// A copy: the handles are often a temporary list.
Handle find_handle(const std::vector<Handle>& all, std::size_t panel, const std::string& pointer,
                   const std::string& part) {
  for (const Handle& h : all) {
    if (h.panel == panel && h.pointer == pointer && h.part == part) return h;
  }
  throw std::runtime_error("no handle " + pointer + " " + part);
}

TEST(EditRequest, ViewsAreOnePerPanelFiniteWithPositiveSizes) {
  EXPECT_FALSE(views_of(Json::object(), 2));
  EXPECT_FALSE(views_of(Json{{"views", nullptr}}, 2));
  const auto views = views_of(Json::parse(R"({"views": [[0, 0, 2, 1], [-1, -2, 3, 4.5]]})"), 2);
  ASSERT_TRUE(views);
  EXPECT_EQ((*views)[1].max, Point(3, 4.5));
  for (const char* bad : {R"({"views": [[0, 0, 2, 1]]})",                  // one panel short
                          R"({"views": [[0, 0, 2, 1], [0, 0, 1]]})",       // three numbers
                          R"({"views": [[0, 0, 2, 1], [0, 0, 0, 1]]})",    // zero width
                          R"({"views": [[0, 0, 2, 1], [0, 3, 1, 1]]})",    // negative height
                          R"({"views": [[0, 0, 2, 1], [0, 0, "1", 1]]})",  // a string
                          R"({"views": [[0, 0, 2, 1], [0, 0, 1e300, 1]]})", R"({"views": {"0": [0, 0, 2, 1]}})"}) {
    EXPECT_THROW(views_of(Json::parse(bad), 2), std::invalid_argument) << bad;
  }
  try {
    views_of(Json::parse(R"({"views": [[0, 0, 2, 1], [0, 0, 0, 1]]})"), 2);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("views/1"), std::string::npos) << e.what();
  }
}

// A drag read and drawn in the views held: the dragged tail is drawn where it
// was dropped, whereas the figure refitted to its content moves it away.
TEST(EditRequest, ADragInHeldViewsStaysUnderThePointer) {
  const scene::Scene scene = scene::parse_scene(kTwoPanelArrows, "e.json");
  const motion::Stage stage(scene);
  const render::Figure fitted = render::build_figure(stage);
  Json request{{"views", Json::array()}};
  for (const auto& placement : fitted.placements) {
    request["views"].push_back(
        {placement.view.min.real(), placement.view.min.imag(), placement.view.max.real(), placement.view.max.imag()});
  }
  const Handle tail = find_handle(handles(kTwoPanelArrows, stage, fitted.placements), 1, "/keyframes/2", "tail");
  const Point to = tail.at + Point{60, 40};  // outward: the content grows
  request["drag"] = {{"panel", 1u}, {"pointer", "/keyframes/2"}, {"part", "tail"}, {"to", {to.real(), to.imag()}}};
  const Applied applied = apply_changes(kTwoPanelArrows, request_changes(kTwoPanelArrows, scene, request));

  const scene::Scene moved = scene::parse_scene(applied.text, "e.json");
  const motion::Stage moved_stage(moved);
  const render::Figure held = figure_in(moved_stage, views_of(request, 2));
  const Point there = find_handle(handles(applied.text, moved_stage, held.placements), 1, "/keyframes/2", "tail").at;
  EXPECT_LT(std::abs(there - to), 0.2) << there << " " << to;
  const render::Figure refitted = figure_in(moved_stage, std::nullopt);
  const Point refit =
      find_handle(handles(applied.text, moved_stage, refitted.placements), 1, "/keyframes/2", "tail").at;
  EXPECT_GT(std::abs(refit - to), 2.0) << "the refitted figure should move the handle (else this test shows nothing)";
}

// In space the camera looks at the centre of the solids, which a drag of a
// corner moves: the views held are measured from the world's origin, so
// that the dragged corner is still drawn under the pointer.
TEST(EditRequest, ADragOfSpaceInHeldViewsStaysUnderThePointer) {
  const std::string text = R"({"dimension": 3, "method": "SAM", "poses": [
    {"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
    {"t": 1, "tetrahedron": [[2, 0, 0], [3, 0.4, 0], [2, 1, 0], [2, 0, 1.5]]}],
    "camera": {"azimuth": -60, "elevation": 25}})";
  const scene::Scene scene = scene::parse_scene(text, "e.json");
  const motion::Stage stage(scene);
  const render::Figure fitted = render::build_figure(stage);
  Json request{{"views", views_json(stage, fitted.placements)}};
  const Handle corner = find_handle(handles(text, stage, fitted.placements), 0, "/poses/1", "corner3");
  const Point to = corner.at + Point{-50, 30};
  request["drag"] = {{"panel", 0u}, {"pointer", "/poses/1"}, {"part", "corner3"}, {"to", {to.real(), to.imag()}}};
  const Applied applied = apply_changes(text, request_changes(text, scene, request));
  const scene::Scene moved = scene::parse_scene(applied.text, "e.json");
  const motion::Stage moved_stage(moved);
  const render::Figure held = figure_in(moved_stage, views_of(request, 1));
  const Point there = find_handle(handles(applied.text, moved_stage, held.placements), 0, "/poses/1", "corner3").at;
  EXPECT_LT(std::abs(there - to), 0.2) << there << " " << to;
  // The other pose stays where it was drawn.
  const Point other = find_handle(handles(text, stage, fitted.placements), 0, "/poses/0", "corner1").at;
  EXPECT_LT(
      std::abs(find_handle(handles(applied.text, moved_stage, held.placements), 0, "/poses/0", "corner1").at - other),
      0.2);
}

// The camera the page holds while editing a scene with "auto": the scene
// drawn with it, "auto" off; numbers beyond the camera's limits, and a
// scene of the plane, refused.
TEST(EditRequest, TheHeldCameraDrawsTheSceneAsItWasShown) {
  const scene::Scene space = scene::parse_scene(
      R"({"dimension": 3, "method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
                                        {"t": 1, "matrix": [[2, 0, 0, 1], [0, 2, 0, 0], [0, 0, 2, 0]]}],
          "camera": {"auto": true}})",
      "e.json");
  EXPECT_FALSE(held_camera(space, Json{{"views", nullptr}}).has_value());
  const auto held = held_camera(space, Json::parse(R"({"camera": {"azimuth": -40.5, "elevation": 12}})"));
  ASSERT_TRUE(held.has_value());
  const scene::Camera& camera = scene::figure_of<scene::SpacePoseKeys>(*held).camera;
  EXPECT_EQ(camera.azimuth, -40.5);
  EXPECT_EQ(camera.elevation, 12.0);
  EXPECT_FALSE(camera.automatic);
  for (const char* bad : {R"({"camera": {"azimuth": 10, "elevation": 91}})", R"({"camera": {"azimuth": 10}})",
                          R"({"camera": [10, 20]})", R"({"camera": {"azimuth": "10", "elevation": 20}})"}) {
    EXPECT_THROW(held_camera(space, Json::parse(bad)), std::invalid_argument) << bad;
  }
  const scene::Scene plane = scene::parse_scene(kTwoPanelArrows, "e.json");
  EXPECT_THROW(held_camera(plane, Json::parse(R"({"camera": {"azimuth": 10, "elevation": 20}})")),
               std::invalid_argument);
}

TEST(EditRequest, ATimeIsWrittenShortAndUndoneByteForByte) {
  const scene::Scene scene = scene::parse_scene(kTwoPanelArrows, "e.json");
  const Json request = Json::parse(R"({"time": {"pointer": "/keyframes/1", "t": 0.6012345, "step": 0.002}})");
  const Applied applied = apply_changes(kTwoPanelArrows, request_changes(kTwoPanelArrows, scene, request));
  EXPECT_NE(applied.text.find(R"({"t": 0.601, "p": [3, 1.5])"), std::string::npos) << applied.text;
  EXPECT_EQ(applied.text.size(), kTwoPanelArrows.size() + 2);
  ASSERT_EQ(applied.previous.size(), 1u);
  EXPECT_EQ(applied.previous[0]["pointer"], "/keyframes/1/t");
  EXPECT_EQ(applied.previous[0]["value"], "0.5");
  // The undo (what the page sends back) restores every byte.
  const scene::Scene edited = scene::parse_scene(applied.text, "e.json");
  const Applied undone =
      apply_changes(applied.text, request_changes(applied.text, edited, {{"changes", applied.previous}}));
  EXPECT_EQ(undone.text, kTwoPanelArrows);
  // A pointer the timeline does not show is refused; so is a t that is not a number.
  EXPECT_THROW(request_changes(kTwoPanelArrows, scene, Json::parse(R"({"time": {"pointer": "/keyframes/3", "t": 2}})")),
               std::invalid_argument);
  EXPECT_THROW(
      request_changes(kTwoPanelArrows, scene, Json::parse(R"({"time": {"pointer": "/keyframes/1", "t": "x"}})")),
      nlohmann::json::exception);
}

// The times no longer increasing: the scene's own check refuses it, with the pointer.
TEST(EditRequest, ATimePastItsNeighbourIsRefusedByTheScenesCheck) {
  const scene::Scene scene = scene::parse_scene(kTwoPanelArrows, "e.json");
  const Json request = Json::parse(R"({"time": {"pointer": "/keyframes/1", "t": 1.2, "step": 0.01}})");
  const Applied applied = apply_changes(kTwoPanelArrows, request_changes(kTwoPanelArrows, scene, request));
  try {
    scene::parse_scene(applied.text, "e.json");
    FAIL() << "times that do not increase were read";
  } catch (const scene::LocatedError& e) {
    EXPECT_EQ(e.pointer(), "/keyframes/2/t") << e.what();
  }
}

}  // namespace
}  // namespace pita::serve
