// The routes of `pita serve` (server.hpp lists them), what each handler is
// given, and the HTTP server's limits and token check before them. The
// server's life (binding, the saves rendered again, signals) is server.cpp's.
#pragma once

#include <cstddef>

#include "serve/live_scenes.hpp"
#include "serve/oldest_first.hpp"
#include "serve/server.hpp"

namespace httplib {
class Server;  // <httplib.h>, through http_front.hpp
}

namespace pita::serve {

// At most this many event streams are open at once: one more closes the oldest
// (its page's EventSource opens another), so that a flood of them, or of tabs,
// cannot hold the workers the page's requests need.
inline constexpr std::size_t kEventStreams = 16;

// What every route handler is given: the scenes, the command line's settings
// and the open event streams.
struct Site {
  LiveScenes& state;
  const Settings& settings;
  OldestFirst streams{kEventStreams};
};

// The HTTP server's limits, its token check and its routes.
void set_up(httplib::Server& http, Site& site);

}  // namespace pita::serve
