// pita serve's answers to requests given as bytes (Service::answer, through
// src/serve/http_front.cpp and server.cpp): the bounds come before the token,
// the token before the routes. The sockets, the slow clients and the signals are tested on the
// program itself (tests/serve/test_serve_limits.py).
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

}  // namespace
}  // namespace pita::serve
