// The HTTP server of `pita serve`: cpp-httplib's, with every request first
// received whole by pita and checked against its bounds (http_request.hpp)
// before the library reads a byte of it, the token check included. Debian's
// cpp-httplib is a compiled library, so its own bounds cannot be set: it
// reads header lines and chunked bodies without limit, and lets a request
// arrive as slowly as it likes. Here:
//
// - a request must arrive whole, head and body, within kRequestSeconds;
// - at most kReceiving requests are being received at once: one more closes
//   the oldest (408), so that slow half-requests cannot hold every worker;
// - each connection carries one request (Connection: close), so that every
//   request passes these checks;
// - stop_receiving() makes the requests being received give up at once.
#pragma once

#include <atomic>
#include <chrono>
#include <string>
#include <string_view>
#include <vector>

#include "serve/http_request.hpp"
#include "serve/oldest_first.hpp"

// Last: it includes <resolv.h>, whose macro _res would rename a parameter of Eigen's.
#include <httplib.h>

namespace pita::serve {

inline constexpr std::chrono::seconds kRequestSeconds{10};
inline constexpr std::size_t kReceiving = 16;

class HttpFront : public httplib::Server {
 public:
  HttpFront(HttpLimits limits, std::vector<std::string> hosts);

  // The bytes of the answer to `request`, a whole request as a client sends
  // it, through the same checks and routes as a request on a socket (the
  // tests, the fuzz target). A request cut short is refused (400).
  std::string answer(std::string_view request);

  // Requests still being received give up (the server is stopping).
  void stop_receiving() { stopping_ = true; }

 private:
  bool process_and_close_socket(socket_t sock) override;
  // Receives one request on `sock`, within the bounds; its bytes, or empty
  // after answering a refusal.
  std::string receive(socket_t sock);

  HttpLimits limits_;
  std::vector<std::string> hosts_;
  OldestFirst receiving_{kReceiving};
  std::atomic<bool> stopping_{false};
};

}  // namespace pita::serve
