// The bounds of a request to `pita serve`, checked on its bytes as they
// arrive and before anything else reads them (the token included): the
// request line, the header's size and count, the body's length, chunked
// bodies, and the Host header (DNS rebinding). docs/reference/serve.md
// "Security" states the numbers.
//
// Pure: bytes in, a verdict out, so that the server (http_front.hpp) and the
// fuzz target (fuzz/fuzz_http_request.cpp) check the same way.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace pita::serve {

struct HttpLimits {
  std::size_t request_line = 8 * 1024;   // the method, the target and the version (Apache's 8190)
  std::size_t header_bytes = 64 * 1024;  // the request line and every header line (Tornado's 64 KiB)
  std::size_t header_count = 100;        // header lines (Apache's LimitRequestFields)
  std::size_t body_bytes = 64 * 1024;    // no request of the page is larger
};

// The host names a request may give in its Host header: the address served,
// and for a loopback address the names of loopback. Empty: any (the server
// listens on every address, 0.0.0.0 or ::, where no name is known).
std::vector<std::string> allowed_hosts(const std::string& served_host);

// What the bytes received so far make of a request.
struct RequestVerdict {
  enum class What { incomplete, complete, refused };
  What what = What::incomplete;
  std::size_t size = 0;  // complete: the request's bytes (its head and its body)
  int status = 0;        // refused: 400, 403, 413, 414 or 431
  std::string reason;    // refused: what is wrong, for the answer's body
};

// Checks the bytes received so far (the start of a request): incomplete
// while the head or the body is not all there and no bound is passed;
// refused as soon as one is (before the rest arrives). `hosts` as
// allowed_hosts gives them.
RequestVerdict check_request(std::string_view received, const HttpLimits& limits,
                             const std::vector<std::string>& hosts);

// The whole answer to a refused request: the status line, a JSON body
// {"error": reason}, and `Connection: close`.
std::string refusal(int status, const std::string& reason);

}  // namespace pita::serve
