// pita serve's answers to requests given as bytes (Service::answer, through
// src/serve/http_front.cpp and server.cpp): the bounds come before the token,
// the token before the routes. The sockets, the slow clients and the signals are tested on the
// program itself (tests/serve/test_serve_limits.py).
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

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
  Service& service() {
    if (!service_) {
      service_ = std::make_unique<Service>(settings_);
      service_->render_all();
    }
    return *service_;
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

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string post(Service& service, const std::string& target, const std::string& body) {
  return service.answer("POST " + target + " HTTP/1.1\r\nHost: localhost\r\nContent-Length: " +
                        std::to_string(body.size()) + "\r\n\r\n" + body);
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
  const std::string still = post(service(), "/api/preview/0" + token, nlohmann::json{{"views", views}}.dump());
  ASSERT_EQ(status(still), 200) << still;
  const std::string dragged =
      post(service(), "/api/preview/0" + token, nlohmann::json{{"views", views}, {"drag", drag}}.dump());
  ASSERT_EQ(status(dragged), 200) << dragged;
  const nlohmann::json a = nlohmann::json::parse(body(still)), b = nlohmann::json::parse(body(dragged));
  EXPECT_EQ(a.at("svg").get<std::string>().rfind("<?xml", 0), 0u);
  EXPECT_NE(a.at("svg"), b.at("svg"));
  // The dragged handle is where it was dropped, in the views held.
  for (const auto& h : b.at("handles")) {
    if (h.at("pointer") != handle.at("pointer") || h.at("part") != handle.at("part")) continue;
    EXPECT_NEAR(h.at("at").at(0).get<double>(), drag.at("to").at(0).get<double>(), 0.2) << h;
  }
  EXPECT_EQ(read_text(folder_.path() / "s.json"), kScene);
  // Views that are not one box per panel, or not finite, are refused with the reason.
  const std::string bad = post(service(), "/api/preview/0" + token, R"({"views": [[0, 0, -1, 1]]})");
  EXPECT_EQ(status(bad), 400) << bad;
  EXPECT_NE(body(bad).find("views/0 must have positive sizes"), std::string::npos) << bad;
  const std::string two = post(service(), "/api/preview/0" + token, R"({"views": [[0, 0, 1, 1], [0, 0, 1, 1]]})");
  EXPECT_EQ(status(two), 400) << two;
  // A handle the figure does not have: refused as an edit is.
  const std::string none = post(service(), "/api/preview/0" + token,
                                R"({"drag": {"panel": 0, "pointer": "/keyframes/9", "part": "tail", "to": [1, 1]}})");
  EXPECT_EQ(status(none), 400) << none;
  EXPECT_EQ(read_text(folder_.path() / "s.json"), kScene);
}

TEST_F(ServiceTest, APreviewNeedsEdit) {
  EXPECT_EQ(status(post(service(), "/api/preview/0?token=" + settings_.token, "{}")), 403);
  EXPECT_EQ(status(post(service(), "/api/preview/0", "{}")), 403);
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
      post(service(), "/api/edit/0" + token, R"({"time": {"pointer": "/keyframes/1", "t": 2.5, "step": 0.01}})");
  EXPECT_GE(status(past), 400) << past;
  const nlohmann::json refused = nlohmann::json::parse(body(past)).at("refused");
  EXPECT_EQ(refused.at("pointer"), "/keyframes/2/t") << past;
  EXPECT_NE(refused.at("reason").get<std::string>().find("increasing"), std::string::npos) << past;
  EXPECT_EQ(read_text(folder_.path() / "s.json"), kScene);
  const std::string moved =
      post(service(), "/api/edit/0" + token, R"({"time": {"pointer": "/keyframes/1", "t": 1.2345, "step": 0.01}})");
  ASSERT_EQ(status(moved), 200) << moved;
  std::string expected = kScene;
  expected.replace(expected.find(R"({"t": 1,)") + 6, 1, "1.23");
  EXPECT_EQ(read_text(folder_.path() / "s.json"), expected);
  // Undone byte for byte with the changes it answered.
  const nlohmann::json previous = nlohmann::json::parse(body(moved)).at("previous");
  const std::string undone = post(service(), "/api/edit/0" + token, nlohmann::json{{"changes", previous}}.dump());
  ASSERT_EQ(status(undone), 200) << undone;
  EXPECT_EQ(read_text(folder_.path() / "s.json"), kScene);
}

}  // namespace
}  // namespace pita::serve
