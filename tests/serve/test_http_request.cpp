// The bounds of a request to pita serve (src/serve/http_request.cpp): each is
// refused as soon as the bytes received pass it, before the rest arrives; a
// request within them is complete when its head and its body are there; the
// Host header names an address served.
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "serve/http_request.hpp"

namespace pita::serve {
namespace {

const std::vector<std::string> kLoopback = allowed_hosts("127.0.0.1");

RequestVerdict check(const std::string& bytes, const HttpLimits& limits = {}) {
  return check_request(bytes, limits, kLoopback);
}

TEST(HttpRequest, IsIncompleteUntilTheHeadAndTheBodyAreThere) {
  const std::string request = "POST /api/edit/0 HTTP/1.1\r\nHost: 127.0.0.1:8765\r\nContent-Length: 5\r\n\r\nhello";
  const std::size_t head = request.size() - 5;
  for (std::size_t n = 0; n < request.size(); ++n) {
    EXPECT_EQ(check(request.substr(0, n)).what, RequestVerdict::What::incomplete) << n;
  }
  const RequestVerdict whole = check(request + "GET / HTTP/1.1\r\n");  // what follows is not this request's
  ASSERT_EQ(whole.what, RequestVerdict::What::complete);
  EXPECT_EQ(whole.size, head + 5);
  // Bare line feeds end lines too, as cpp-httplib reads them.
  const std::string bare = "GET / HTTP/1.0\nHost: localhost\n\n";
  ASSERT_EQ(check(bare).what, RequestVerdict::What::complete);
  EXPECT_EQ(check(bare).size, bare.size());
}

TEST(HttpRequest, ALongRequestLineIsRefusedBeforeItEnds) {
  const std::string start = "GET /" + std::string(8 * 1024, 'a');
  const RequestVerdict verdict = check(start);  // no line end yet
  EXPECT_EQ(verdict.what, RequestVerdict::What::refused);
  EXPECT_EQ(verdict.status, 414);
  EXPECT_NE(verdict.reason.find("8 KiB"), std::string::npos) << verdict.reason;
  EXPECT_EQ(check("GET /" + std::string(8000, 'a')).what, RequestVerdict::What::incomplete);
}

TEST(HttpRequest, TooManyOrTooLargeHeadersAreRefusedBeforeTheHeadEnds) {
  std::string many = "GET / HTTP/1.1\r\nHost: localhost\r\n";
  for (int i = 0; i < 100; ++i) many += "X-A: b\r\n";
  const RequestVerdict count = check(many);
  EXPECT_EQ(count.status, 431);
  EXPECT_NE(count.reason.find("more than 100 header lines"), std::string::npos) << count.reason;

  HttpLimits small;
  small.header_bytes = 1024;
  const std::string large = "GET / HTTP/1.1\r\nCookie: " + std::string(2000, 'c');  // one line, not ended
  const RequestVerdict bytes = check(large, small);
  EXPECT_EQ(bytes.status, 431);
  EXPECT_NE(bytes.reason.find("1 KiB"), std::string::npos) << bytes.reason;
  // The default is 64 KiB: a browser's cookies of 60 kB pass.
  EXPECT_EQ(check("GET / HTTP/1.1\r\nHost: localhost\r\nCookie: " + std::string(60000, 'c') + "\r\n\r\n").what,
            RequestVerdict::What::complete);
}

TEST(HttpRequest, BodiesBeyondTheLimitAndChunkedBodiesAreRefusedFromTheHead) {
  const RequestVerdict large = check("POST /api/edit/0 HTTP/1.1\r\nHost: localhost\r\nContent-Length: 65537\r\n\r\n");
  EXPECT_EQ(large.status, 413);
  EXPECT_NE(large.reason.find("65537"), std::string::npos) << large.reason;
  EXPECT_EQ(check("POST / HTTP/1.1\r\nHost: localhost\r\nContent-Length: 65536\r\n\r\n").what,
            RequestVerdict::What::incomplete);
  const RequestVerdict chunked =
      check("POST /api/edit/0 HTTP/1.1\r\nHost: localhost\r\nTransfer-Encoding: chunked\r\n\r\n");
  EXPECT_EQ(chunked.status, 413);
  EXPECT_NE(chunked.reason.find("Content-Length"), std::string::npos) << chunked.reason;
  EXPECT_EQ(check("POST / HTTP/1.1\r\nHost: localhost\r\nContent-Length: 99999999999999999999\r\n\r\n").status, 400);
  EXPECT_EQ(check("POST / HTTP/1.1\r\nHost: localhost\r\nContent-Length: 1\r\nContent-Length: 2\r\n\r\n").status, 400);
  EXPECT_EQ(check("POST / HTTP/1.1\r\nHost: localhost\r\nContent-Length: -1\r\n\r\n").status, 400);
}

TEST(HttpRequest, MalformedHeadsAreRefused) {
  EXPECT_EQ(check("\r\n").status, 400);
  EXPECT_EQ(check("GET /\r\n").status, 400);
  EXPECT_EQ(check("GET / HTTP/2\r\n").status, 400);
  EXPECT_EQ(check("GET / HTTP/1.1\r\nno colon\r\n\r\n").status, 400);
  EXPECT_EQ(check("GET / HTTP/1.1\r\nHost: localhost\r\n folded\r\n\r\n").status, 400);
  EXPECT_EQ(check("GET / HTTP/1.1\r\nBad Name: x\r\n\r\n").status, 400);
}

TEST(HttpRequest, TheHostMustNameAnAddressServed) {
  EXPECT_EQ(check("GET / HTTP/1.1\r\n\r\n").status, 400);  // no Host
  EXPECT_EQ(check("GET / HTTP/1.1\r\nHost: localhost\r\nHost: localhost\r\n\r\n").status, 400);
  for (const char* host : {"localhost", "LOCALHOST:8765", "127.0.0.1", "127.0.0.1:1", "[::1]:8765", "[::1]"}) {
    EXPECT_EQ(check(std::string("GET / HTTP/1.1\r\nHost: ") + host + "\r\n\r\n").what, RequestVerdict::What::complete)
        << host;
  }
  for (const char* host : {"evil.example", "evil.example:8765", "localhost.evil.example", "127.0.0.1.evil.example",
                           "[::2]", "localhost:80x", "", "user@localhost"}) {
    const RequestVerdict verdict = check(std::string("GET / HTTP/1.1\r\nHost: ") + host + "\r\n\r\n");
    EXPECT_EQ(verdict.status, 403) << host;
    EXPECT_NE(verdict.reason.find("DNS rebinding"), std::string::npos) << verdict.reason;
  }
}

TEST(HttpRequest, TheHostsAllowedFollowTheAddressServed) {
  EXPECT_EQ(allowed_hosts("127.0.0.1"), (std::vector<std::string>{"localhost", "127.0.0.1", "[::1]"}));
  EXPECT_EQ(allowed_hosts("::1"), (std::vector<std::string>{"localhost", "127.0.0.1", "[::1]"}));
  EXPECT_EQ(allowed_hosts("127.0.0.2"), (std::vector<std::string>{"localhost", "127.0.0.1", "[::1]", "127.0.0.2"}));
  EXPECT_EQ(allowed_hosts("192.168.1.5"), (std::vector<std::string>{"192.168.1.5"}));
  EXPECT_EQ(allowed_hosts("fe80::1"), (std::vector<std::string>{"[fe80::1]"}));
  EXPECT_TRUE(allowed_hosts("0.0.0.0").empty());  // every address: any name
  EXPECT_TRUE(allowed_hosts("::").empty());
  EXPECT_EQ(check_request("GET / HTTP/1.1\r\nHost: anything\r\n\r\n", {}, allowed_hosts("0.0.0.0")).what,
            RequestVerdict::What::complete);
}

TEST(HttpRequest, ARefusalIsAWholeAnswerWithItsReasonAsJson) {
  const std::string answer = refusal(413, "too \"large\" \xff");
  EXPECT_EQ(answer.rfind("HTTP/1.1 413 Content Too Large\r\n", 0), 0U) << answer;
  EXPECT_NE(answer.find("Connection: close\r\n"), std::string::npos);
  const std::size_t body = answer.find("\r\n\r\n") + 4;
  EXPECT_NE(answer.find("Content-Length: " + std::to_string(answer.size() - body) + "\r\n"), std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(answer.substr(body)).at("error"), "too \"large\" \xef\xbf\xbd");
}

}  // namespace
}  // namespace pita::serve
