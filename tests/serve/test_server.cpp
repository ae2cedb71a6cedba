// pita serve's answers to requests given as bytes (Service::answer, through
// src/serve/http_front.cpp and server.cpp): the bounds come before the token,
// the token before the routes. The sockets, the slow clients and the signals are tested on the
// program itself (tests/serve/test_serve_limits.py).
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "motion/stage.hpp"
#include "render/figure.hpp"
#include "scene/scene.hpp"
#include "serve/server.hpp"
#include "support/scratch_dir.hpp"

namespace pita::serve {
namespace {

const char* const kScene = R"({"method": "P6", "keyframes": [
  {"t": 0, "p": [0, 0], "m": 1, "w": 0.4}, {"t": 1, "p": [3, 1], "m": 1.5, "w": 1.2},
  {"t": 2, "p": [5, 3], "m": 1, "w": 2}]})";

class ServiceTest : public ::testing::Test {
 protected:
  ServiceTest() {
    folder_.write("s.json", kScene);
    settings_.scenes = {folder_.path() / "s.json"};
    settings_.token = "0123456789abcdef0123456789abcdef";
  }
  std::string get(const std::string& target, const std::string& host = "127.0.0.1:8765") {
    return service().answer("GET " + target + " HTTP/1.1\r\nHost: " + host + "\r\n\r\n");
  }
  std::string post(const std::string& target, const std::string& body) {
    return service().answer("POST " + target + " HTTP/1.1\r\nHost: localhost\r\nContent-Length: " +
                            std::to_string(body.size()) + "\r\n\r\n" + body);
  }
  Service& service() {
    if (!service_) {
      service_ = std::make_unique<Service>(settings_);
      service_->render_all();
    }
    return *service_;
  }
  std::string text_of(const std::string& name) const {
    std::ifstream in(folder_.path() / name, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
  static int status(const std::string& answer) { return std::stoi(answer.substr(9, 3)); }
  static std::string body(const std::string& answer) { return answer.substr(answer.find("\r\n\r\n") + 4); }

  test::ScratchDir folder_;
  Settings settings_;
  std::unique_ptr<Service> service_;
};

TEST_F(ServiceTest, TheTokenOpensTheRoutes) {
  const std::string token = "?token=" + settings_.token;
  EXPECT_EQ(status(get("/" + token)), 200);
  EXPECT_EQ(status(get("/")), 403);
  EXPECT_EQ(status(get("/?token=" + std::string(32, '0'))), 403);
  const std::string scenes = get("/api/scenes" + token);
  ASSERT_EQ(status(scenes), 200) << scenes;
  EXPECT_EQ(nlohmann::json::parse(body(scenes)).at(0).at("name"), "s");
  EXPECT_EQ(status(get("/api/figure/1" + token)), 404);
  EXPECT_EQ(status(get("/s.json" + token)), 404);
  // The library's own refusals say why too: never an empty error.
  const std::string unknown = get("/nothing" + token);
  EXPECT_EQ(status(unknown), 404);
  EXPECT_NE(body(unknown).find("no such page"), std::string::npos) << unknown;
  const std::string put = service().answer("PUT /" + token + " HTTP/1.1\r\nHost: localhost\r\n\r\n");
  EXPECT_GE(status(put), 400);
  EXPECT_FALSE(body(put).empty()) << put;
}

TEST_F(ServiceTest, BoundsAndTheHostComeBeforeTheToken) {
  const std::string answer = get("/", "evil.example");  // neither token nor host
  EXPECT_EQ(status(answer), 403);
  EXPECT_NE(body(answer).find("DNS rebinding"), std::string::npos) << answer;
  EXPECT_EQ(status(service().answer("POST /api/edit/0 HTTP/1.1\r\nHost: localhost\r\nTransfer-Encoding: chunked\r\n\r\n"
                                    "5\r\nhello\r\n0\r\n\r\n")),
            413);
  EXPECT_EQ(status(service().answer("GET / HTTP/1.1\r\nHost: localhost\r\n")), 400);  // cut short
  std::string many = "GET / HTTP/1.1\r\nHost: localhost\r\n";
  for (int i = 0; i < 200; ++i) many += "X: y\r\n";
  EXPECT_EQ(status(service().answer(many + "\r\n")), 431);
}

TEST_F(ServiceTest, AnEventStreamIsOpenedWithTheToken) {
  // (Its messages flow only on a socket: a server that does not listen sends none.)
  const std::string answer = get("/api/events?token=" + settings_.token);
  ASSERT_EQ(status(answer), 200) << answer;
  EXPECT_NE(answer.find("Content-Type: text/event-stream"), std::string::npos) << answer;
  EXPECT_EQ(status(get("/api/events")), 403);
}

TEST_F(ServiceTest, AnEditIsRefusedWithoutEditAndAnsweredWithIt) {
  const std::string request = "POST /api/edit/0?token=" + settings_.token +
                              " HTTP/1.1\r\nHost: localhost\r\nContent-Length: 15\r\n\r\n{\"changes\": []}";
  EXPECT_EQ(status(service().answer(request)), 403);
  service_.reset();
  settings_.edit = true;
  const std::string answer = service().answer(request);
  EXPECT_EQ(status(answer), 200) << answer;
  EXPECT_EQ(nlohmann::json::parse(body(answer)).at("previous"), nlohmann::json::array());
}

// A 3D pose scene whose camera gives neither azimuth nor elevation.
const char* const kSpace = R"({"dimension": 3, "method": "polySAM", "samples": 5,
  "poses": [{"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
            {"t": 1, "matrix": [[0, -1, 0, 2], [1, 0, 0, 0], [0, 0, 1, 1]]}],
  "camera": {"shadow": true}
}
)";

// What `pita render` draws of the scene text (an SVG).
std::string rendered(const std::string& text) {
  const scene::Scene scene = scene::parse_scene(text, "s.json");
  const motion::Stage stage(scene);
  return render::render_figure(scene, render::build_figure(stage), render::Format::svg);
}

// The page turns a 3D scene: /api/figure/N?camera=AZ,EL[,DIST] is what pita
// render draws of the file with that camera written in; a bad camera is 400
// with the reason.
TEST_F(ServiceTest, TheFigureIsDrawnWithTheCameraThePageTurned) {
  folder_.write("s.json", kSpace);
  const std::string token = "?token=" + settings_.token;
  const std::string turned = get("/api/figure/0" + token + "&camera=-52.5,30");
  ASSERT_EQ(status(turned), 200) << turned;
  std::string written = kSpace;
  written.replace(written.find(R"({"shadow": true})"), 16, R"({"shadow": true, "azimuth": -52.5, "elevation": 30})");
  EXPECT_EQ(body(turned), rendered(written));
  EXPECT_NE(body(turned), body(get("/api/figure/0" + token)));
  const std::string farther = get("/api/figure/0" + token + "&camera=-52.5,30,25");
  ASSERT_EQ(status(farther), 200) << farther;
  // The page is told the camera, and the panels' as drawn.
  const auto camera = nlohmann::json::parse(body(get("/api/scenes" + token))).at(0).at("camera");
  EXPECT_EQ(camera.at("azimuth"), 35.0);
  EXPECT_EQ(camera.at("elevation"), 25.0);
  EXPECT_EQ(camera.at("auto"), false);
  EXPECT_EQ(camera.at("save"), false);
  EXPECT_EQ(camera.at("panels").at(0).at("azimuth"), 35.0);
  for (const auto& [query, reason] :
       std::vector<std::pair<std::string, std::string>>{{"nan,0", "azimuth must be a finite number"},
                                                        {"400,0", "azimuth must be within +-360"},
                                                        {"0,-91", "elevation must be within +-90"},
                                                        {"10", "two or three numbers"},
                                                        {"1,2,3,4", "two or three numbers"},
                                                        {"1,2,0", "distance must be > 0"},
                                                        {"x,2", "is not a number"},
                                                        {"1,,2", "is not a number"},
                                                        {"1e999,2", "is not a number"}}) {
    const std::string answer = get("/api/figure/0" + token + "&camera=" + query);
    EXPECT_EQ(status(answer), 400) << query << ": " << answer;
    EXPECT_NE(body(answer).find(reason), std::string::npos) << query << ": " << answer;
  }
  // A frame of the turned view: another than the scene's own camera draws.
  const std::string frame = get("/api/figure/0" + token + "&camera=10,20&at=0.5");
  ASSERT_EQ(status(frame), 200) << frame;
  EXPECT_NE(body(frame), body(get("/api/figure/0" + token + "&at=0.5")));
  EXPECT_EQ(body(frame), body(get("/api/figure/0" + token + "&at=0.5&camera=10,20")));  // the layout kept
}

TEST_F(ServiceTest, ASceneOfThePlaneHasNoCameraToTurn) {
  const std::string token = "?token=" + settings_.token;
  const std::string answer = get("/api/figure/0" + token + "&camera=10,20");
  EXPECT_EQ(status(answer), 400);
  EXPECT_NE(body(answer).find("only a 3D pose scene has a camera"), std::string::npos) << answer;
  EXPECT_TRUE(nlohmann::json::parse(body(get("/api/scenes" + token))).at(0).at("camera").is_null());
}

// "Save view": the camera's members the file lacks are added, every other
// byte kept; its undo gives the file back byte for byte.
TEST_F(ServiceTest, SaveViewAddsTheCameraAndItsUndoTakesItOut) {
  folder_.write("s.json", kSpace);
  settings_.edit = true;
  const std::string edit = "/api/edit/0?token=" + settings_.token;
  const std::string answer = post(edit, R"({"changes": [{"pointer": "/camera/azimuth", "value": "-52.5"},
                                 {"pointer": "/camera/elevation", "value": "30"}]})");
  ASSERT_EQ(status(answer), 200) << answer;
  std::string expected = kSpace;
  expected.replace(expected.find(R"({"shadow": true})"), 16, R"({"shadow": true, "azimuth": -52.5, "elevation": 30})");
  EXPECT_EQ(text_of("s.json"), expected);
  const auto previous = nlohmann::json::parse(body(answer)).at("previous");
  EXPECT_EQ(previous, nlohmann::json::parse(R"([{"pointer": "/camera/elevation", "remove": true},
                                                {"pointer": "/camera/azimuth", "remove": true}])"));
  const std::string undone = post(edit, nlohmann::json{{"changes", previous}}.dump());
  ASSERT_EQ(status(undone), 200) << undone;
  EXPECT_EQ(text_of("s.json"), kSpace);
  // Beyond the limits, or another member of the camera: refused, the file as it was.
  for (const char* bad : {R"({"changes": [{"pointer": "/camera/elevation", "value": "95"}]})",
                          R"({"changes": [{"pointer": "/camera/shadow", "value": "false"}]})",
                          R"({"changes": [{"pointer": "/camera/shadow", "remove": true}]})"}) {
    EXPECT_EQ(status(post(edit, bad)), 400) << bad;
  }
  EXPECT_EQ(text_of("s.json"), kSpace);
  // A scene without "camera": the member is added, at the end of the scene.
  std::string bare = kSpace;
  bare.replace(bare.find(",\n  \"camera\""), std::string(",\n  \"camera\": {\"shadow\": true}").size(), "");
  folder_.write("s.json", bare);
  service_.reset();  // the page's figure is of this file now
  const std::string added = post(edit, R"({"changes": [{"pointer": "/camera/azimuth", "value": "10"},
                                                        {"pointer": "/camera/elevation", "value": "20"}]})");
  ASSERT_EQ(status(added), 200) << added;
  const std::string with_camera = text_of("s.json");
  EXPECT_EQ(nlohmann::json::parse(with_camera).at("camera"),
            nlohmann::json::parse(R"({"azimuth": 10, "elevation": 20})"));
  EXPECT_EQ(rendered(with_camera), body(get("/api/figure/0?token=" + settings_.token + "&camera=10,20")));
  const auto back = nlohmann::json::parse(body(added)).at("previous");
  EXPECT_EQ(status(post(edit, nlohmann::json{{"changes", back}}.dump())), 200);
  EXPECT_EQ(text_of("s.json"), bare);
}

// The figure while dragging: the drag made in memory, in the views the page
// holds; nothing is written, and what an edit would refuse says why.
TEST_F(ServiceTest, APreviewDrawsTheDragInTheViewsHeldAndWritesNothing) {
  settings_.edit = true;
  const std::string token = "?token=" + settings_.token;
  const nlohmann::json scenes = nlohmann::json::parse(body(get("/api/scenes" + token)));
  const nlohmann::json views = scenes.at(0).at("views");
  ASSERT_EQ(views.size(), 1u);
  const nlohmann::json handle = scenes.at(0).at("handles").at(0);
  const nlohmann::json drag{{"panel", 0},
                            {"pointer", handle.at("pointer")},
                            {"part", handle.at("part")},
                            {"to", {handle.at("at").at(0).get<double>() + 30, handle.at("at").at(1)}}};
  const std::string still = post("/api/preview/0" + token, nlohmann::json{{"views", views}}.dump());
  ASSERT_EQ(status(still), 200) << still;
  const std::string dragged = post("/api/preview/0" + token, nlohmann::json{{"views", views}, {"drag", drag}}.dump());
  ASSERT_EQ(status(dragged), 200) << dragged;
  const nlohmann::json a = nlohmann::json::parse(body(still)), b = nlohmann::json::parse(body(dragged));
  EXPECT_EQ(a.at("svg").get<std::string>().rfind("<?xml", 0), 0u);
  EXPECT_NE(a.at("svg"), b.at("svg"));
  // The dragged handle is where it was dropped, in the views held.
  for (const auto& h : b.at("handles")) {
    if (h.at("pointer") != handle.at("pointer") || h.at("part") != handle.at("part")) continue;
    EXPECT_NEAR(h.at("at").at(0).get<double>(), drag.at("to").at(0).get<double>(), 0.2) << h;
  }
  EXPECT_EQ(text_of("s.json"), kScene);
  // Views that are not one box per panel, or not finite, are refused with the reason.
  const std::string bad = post("/api/preview/0" + token, R"({"views": [[0, 0, -1, 1]]})");
  EXPECT_EQ(status(bad), 400) << bad;
  EXPECT_NE(body(bad).find("views/0 must have positive sizes"), std::string::npos) << bad;
  const std::string two = post("/api/preview/0" + token, R"({"views": [[0, 0, 1, 1], [0, 0, 1, 1]]})");
  EXPECT_EQ(status(two), 400) << two;
  // A handle the figure does not have: refused as an edit is.
  const std::string none = post("/api/preview/0" + token,
                                R"({"drag": {"panel": 0, "pointer": "/keyframes/9", "part": "tail", "to": [1, 1]}})");
  EXPECT_EQ(status(none), 400) << none;
  EXPECT_EQ(text_of("s.json"), kScene);
}

TEST_F(ServiceTest, APreviewNeedsEdit) {
  EXPECT_EQ(status(post("/api/preview/0?token=" + settings_.token, "{}")), 403);
  EXPECT_EQ(status(post("/api/preview/0", "{}")), 403);
}

// The timeline: each keyframe's time and pointer; a drag of its marker edits
// "t", refused with the scene's own reason when the times would not increase.
TEST_F(ServiceTest, ATimeEditIsWrittenOrRefusedWithTheReason) {
  settings_.edit = true;
  const std::string token = "?token=" + settings_.token;
  const nlohmann::json keys = nlohmann::json::parse(body(get("/api/scenes" + token))).at(0).at("keys");
  ASSERT_EQ(keys.size(), 1u);
  EXPECT_EQ(keys.at(0).at("times").at(1), (nlohmann::json{{"pointer", "/keyframes/1"}, {"t", 1}}));
  const std::string past =
      post("/api/edit/0" + token, R"({"time": {"pointer": "/keyframes/1", "t": 2.5, "step": 0.01}})");
  EXPECT_GE(status(past), 400) << past;
  const nlohmann::json refused = nlohmann::json::parse(body(past)).at("refused");
  EXPECT_EQ(refused.at("pointer"), "/keyframes/2/t") << past;
  EXPECT_NE(refused.at("reason").get<std::string>().find("increasing"), std::string::npos) << past;
  EXPECT_EQ(text_of("s.json"), kScene);
  const std::string moved =
      post("/api/edit/0" + token, R"({"time": {"pointer": "/keyframes/1", "t": 1.2345, "step": 0.01}})");
  ASSERT_EQ(status(moved), 200) << moved;
  std::string expected = kScene;
  expected.replace(expected.find(R"({"t": 1,)") + 6, 1, "1.23");
  EXPECT_EQ(text_of("s.json"), expected);
  // Undone byte for byte with the changes it answered.
  const nlohmann::json previous = nlohmann::json::parse(body(moved)).at("previous");
  const std::string undone = post("/api/edit/0" + token, nlohmann::json{{"changes", previous}}.dump());
  ASSERT_EQ(status(undone), 200) << undone;
  EXPECT_EQ(text_of("s.json"), kScene);
}

}  // namespace
}  // namespace pita::serve
