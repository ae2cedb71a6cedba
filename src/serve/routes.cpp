#include "serve/routes.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>
#include <sys/socket.h>

#include "animate/timeline.hpp"
#include "serve/page.hpp"

// Last: it includes cpp-httplib's <httplib.h>, whose <resolv.h> macro _res would rename a parameter of Eigen's.
#include "serve/http_front.hpp"

namespace pita::serve {

namespace {

// The scene index of /api/.../N; nullopt for anything else.
std::optional<std::size_t> scene_index(const std::string& text, std::size_t count) {
  if (text.empty() || text.size() > 6 || text.find_first_not_of("0123456789") != std::string::npos) {
    return std::nullopt;
  }
  const std::size_t i = std::stoul(text);
  return i < count ? std::optional<std::size_t>(i) : std::nullopt;
}

// A body of JSON text as it is (pita measure's report). With the charset:
// cpp-httplib compresses a bare application/json with brotli at its slowest
// setting when the browser accepts it (150 ms of a preview's 67 kB, made in 6).
void send_json_text(httplib::Response& res, int status, const std::string& text) {
  res.status = status;
  res.set_header("Cache-Control", "no-store");
  res.set_content(text, "application/json; charset=utf-8");
}

// Text that is not UTF-8 (a scene saved as Latin-1, quoted in a message) is
// sent with U+FFFD in place of its bad bytes, never a failed answer.
void send_json(httplib::Response& res, int status, const Json& body) {
  send_json_text(res, status, body.dump(-1, ' ', false, Json::error_handler_t::replace));
}

void send_error(httplib::Response& res, int status, const std::string& message) {
  send_json(res, status, Json{{"error", message}});
}

// The answer to a request on the scene at `path` that met the exception being
// handled: error_status, and error_json as the body (or as its member
// `member`: "refused" for an edit the scene would not take).
void send_failure(httplib::Response& res, const std::string& path, const char* member = nullptr) {
  const std::exception_ptr thrown = std::current_exception();
  const Json error = error_json(thrown, path);
  send_json(res, error_status(thrown), member == nullptr ? error : Json{{member, error}});
}

// The request's token matches the server's, compared in constant time: how
// long a refusal takes says nothing of the token.
bool token_matches(const std::string& given, const std::string& token) {
  unsigned difference = given.size() == token.size() ? 0U : 1U;
  for (std::size_t k = 0; k < given.size() && k < token.size(); ++k) {
    difference |= static_cast<unsigned>(given[k] ^ token[k]);
  }
  return difference == 0;
}

// The time of /api/figure/N?at=t: a finite number within 10^6; nullopt
// when not given. Throws std::invalid_argument for anything else.
std::optional<double> figure_time(const httplib::Request& req) {
  if (!req.has_param("at")) return std::nullopt;
  std::size_t used = 0;
  const std::string text = req.get_param_value("at");
  const double at = std::stod(text, &used);
  if (used != text.size() || !std::isfinite(at) || std::abs(at) > 1e6) throw std::invalid_argument(text);
  return at;
}

// What every route handler is given: the scenes and the command line's settings.

void get_page(Site&, const httplib::Request&, httplib::Response& res) {
  res.set_header("Cache-Control", "no-store");
  res.set_header(
      "Content-Security-Policy",
      "default-src 'self'; img-src 'self' data:; style-src 'self' 'unsafe-inline'; script-src 'self' 'unsafe-inline'");
  res.set_content(std::string(page_html()), "text/html; charset=utf-8");
}

void get_scenes(Site& site, const httplib::Request&, httplib::Response& res) {
  send_json(res, 200, site.state.scenes_json());
}

void get_figure(Site& site, const httplib::Request& req, httplib::Response& res) {
  const auto i = scene_index(req.matches[1], site.state.size());
  if (!i) return send_error(res, 404, "no such scene");
  std::optional<double> at;
  try {
    at = figure_time(req);
  } catch (const std::exception&) {
    return send_error(res, 400, "at: a finite number, please");
  }
  try {
    // camera=AZ,EL[,DIST]: a 3D scene turned in the page (camera_edit.hpp).
    std::optional<CameraTurn> turn;
    if (req.has_param("camera")) turn = camera_parameter(req.get_param_value("camera"));
    const auto svg = site.state.figure(*i, at, turn);
    if (!svg) return send_error(res, 409, "the scene has no good figure yet: see its error");
    res.set_header("Cache-Control", "no-store");
    // With the charset, not the bare type: cpp-httplib compresses a bare
    // image/svg+xml with brotli at its slowest setting when the browser
    // accepts it (380 ms for Fig. 1's 150 kB; 7 ms to send it as it is).
    res.set_content(*svg, "image/svg+xml; charset=utf-8");
  } catch (const CameraRefused& e) {
    send_error(res, 400, e.what());
  } catch (...) {
    send_failure(res, site.settings.scenes[*i].string());
  }
}

// The animated SVG the page seeks for every frame of the slider and of play:
// 409, with the reason, when the scene has none (no motion to play, beyond an
// animation's work or kMaxPageAnimationBytes): the page then fetches frames.
void get_animation(Site& site, const httplib::Request& req, httplib::Response& res) {
  const auto i = scene_index(req.matches[1], site.state.size());
  if (!i) return send_error(res, 404, "no such scene");
  try {
    const auto svg = site.state.animation(*i);
    if (!svg) return send_error(res, 409, "the scene has no good figure yet: see its error");
    res.set_header("Cache-Control", "no-store");
    res.set_content(*svg, "image/svg+xml; charset=utf-8");  // the charset: as get_figure
  } catch (const animate::AnimationError& e) {
    send_error(res, 409, e.what());
  } catch (...) {
    send_failure(res, site.settings.scenes[*i].string());
  }
}

// A file name of the download: the scene's name in letters, digits, '.',
// '-' and '_' only (it goes into a header), and what it holds.
std::string download_name(const fs::path& scene, const std::string& what) {
  std::string name;
  for (const char c : scene.stem().string()) {
    const bool plain =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '_';
    name += plain ? c : '_';
  }
  if (name.empty() || name.front() == '.') name.insert(0, "scene");
  return name + what;
}

// Export: GET /api/export/N?what=svg|png[&at=t] the bytes `pita render SCENE
// [--at t] -o OUT.svg|.png` writes, what=animation those of `pita animate
// SCENE -o OUT.svg`; as a download (Content-Disposition: attachment).
void get_export(Site& site, const httplib::Request& req, httplib::Response& res) {
  const auto i = scene_index(req.matches[1], site.state.size());
  if (!i) return send_error(res, 404, "no such scene");
  const std::string what = req.has_param("what") ? req.get_param_value("what") : "";
  if (what != "svg" && what != "png" && what != "animation") {
    return send_error(res, 400, "what: svg, png or animation, please");
  }
  std::optional<double> at;
  try {
    at = figure_time(req);
  } catch (const std::exception&) {
    return send_error(res, 400, "at: a finite number, please");
  }
  if (what == "animation" && at) return send_error(res, 400, "at: not with what=animation (it has every frame)");
  try {
    const auto bytes = what == "animation" ? site.state.animation(*i)
                                           : site.state.export_figure(
                                                 *i, at, what == "png" ? render::Format::png : render::Format::svg);
    if (!bytes) return send_error(res, 409, "the scene has no good figure yet: see its error");
    const std::string suffix = what == "animation" ? "-animation.svg"
                               : at                ? fmt::format("-at-{}.{}", *at, what)
                                                   : "." + what;
    res.set_header("Cache-Control", "no-store");
    res.set_header("Content-Disposition",
                   fmt::format("attachment; filename=\"{}\"", download_name(site.settings.scenes[*i], suffix)));
    res.set_header("X-Content-Type-Options", "nosniff");
    // Downloads are sent as bytes (never compressed, never shown inline).
    res.set_content(*bytes, what == "png" ? "image/png" : "application/octet-stream");
  } catch (const animate::AnimationError& e) {
    send_error(res, 409, e.what());
  } catch (...) {
    send_failure(res, site.settings.scenes[*i].string());
  }
}

void get_measures(Site& site, const httplib::Request& req, httplib::Response& res) {
  const auto i = scene_index(req.matches[1], site.state.size());
  if (!i) return send_error(res, 404, "no such scene");
  try {
    const auto text = site.state.measures(*i);
    if (!text) return send_error(res, 409, "the scene has no good figure yet: see its error");
    send_json_text(res, 200, *text);
  } catch (...) {
    send_failure(res, site.settings.scenes[*i].string());
  }
}

// Server-sent events: one per render of a scene, and a comment every 5 s
// that keeps proxies and the browser patient. The stream ends when the
// server stops or a newer stream takes its place (kEventStreams).
void get_events(Site& site, const httplib::Request&, httplib::Response& res) {
  res.set_header("Cache-Control", "no-store");
  LiveScenes& state = site.state;
  auto seen = std::make_shared<std::vector<std::uint64_t>>(state.versions_after({}, std::chrono::milliseconds(0)));
  auto place = std::make_shared<Place>(site.streams);
  auto quiet = std::make_shared<int>(0);  // seconds without an event
  res.set_chunked_content_provider(
      "text/event-stream", [&state, seen, place, quiet](std::size_t, httplib::DataSink& sink) {
        const std::vector<std::uint64_t> now = state.versions_after(*seen, std::chrono::seconds(1));
        if (state.stopping() || place->told_to_leave()) {
          sink.done();
          return true;
        }
        std::string events;
        for (std::size_t i = 0; i < now.size(); ++i) {
          if (now[i] != (*seen)[i]) events += fmt::format("data: {{\"scene\": {}, \"version\": {}}}\n\n", i, now[i]);
        }
        if (events.empty()) {
          if (++*quiet < 5) return true;
          events = ": still here\n\n";
        }
        *quiet = 0;
        *seen = now;
        return sink.write(events.data(), events.size());
      });
}

// The scene and the JSON body of an edit or a preview; nullopt when editing
// is off, there is no such scene or the body is not JSON (answered already).
std::optional<std::pair<std::size_t, Json>> edit_body(Site& site, const httplib::Request& req, httplib::Response& res) {
  if (!site.settings.edit) {
    send_error(res, 403, "editing is off: start pita serve with --edit");
    return std::nullopt;
  }
  const auto i = scene_index(req.matches[1], site.state.size());
  if (!i) {
    send_error(res, 404, "no such scene");
    return std::nullopt;
  }
  try {
    return std::pair{*i, Json::parse(req.body)};
  } catch (const std::exception&) {
    send_error(res, 400, "the request is not JSON");
    return std::nullopt;
  }
}

void post_edit(Site& site, const httplib::Request& req, httplib::Response& res) {
  const auto given = edit_body(site, req, res);
  if (!given) return;
  const std::size_t i = given->first;
  const Json& request = given->second;
  const std::string path = site.settings.scenes[i].string();
  // A refusal carries the digest of the file it was refused against: the
  // page clears it when a good state of another text arrives.
  const auto refuse = [&](int status, Json body) {
    body["digest"] = site.state.file_digest(i);
    send_json(res, status, body);
  };
  try {
    const Json answer = site.state.edit(i, request);
    std::vector<std::string> pointers;
    for (const Json& change : answer.at("previous")) pointers.push_back(change.at("pointer").get<std::string>());
    site.state.say(fmt::format("{}: edited {}", path, fmt::join(pointers, ", ")));
    send_json(res, 200, answer);
  } catch (const nlohmann::json::exception& e) {
    site.state.say(fmt::format("{}: edit refused: the request lacks a field", path));
    refuse(400, Json{{"error", std::string("the request lacks a field: ") + e.what()}});
  } catch (const std::invalid_argument& e) {
    site.state.say(fmt::format("{}: edit refused: {}", path, e.what()));
    refuse(400, Json{{"error", e.what()}});
  } catch (...) {
    // The edit would make the scene bad: refused, with the reason; the file is as it was.
    const std::exception_ptr thrown = std::current_exception();
    const Json error = error_json(thrown, path);
    const std::string pointer = error.at("pointer").get<std::string>();
    site.state.say(fmt::format("{}: edit refused: {}{}", path, pointer.empty() ? "" : pointer + ": ",
                               error.at("reason").get<std::string>()));
    refuse(error_status(thrown), Json{{"refused", error}});
  }
}

// POST /api/preview/N: the figure with a drag made in memory (nothing is
// written), in the views the page holds while it edits; the page shows it
// while the button is held. A drag the edit would refuse answers why, as an
// edit's refusal does, and is not logged (the release's edit is).
void post_preview(Site& site, const httplib::Request& req, httplib::Response& res) {
  const auto given = edit_body(site, req, res);
  if (!given) return;
  const std::size_t i = given->first;
  const Json& request = given->second;
  try {
    const auto answer = site.state.preview(i, request);
    if (!answer) return send_error(res, 409, "the scene has no good figure yet: see its error");
    send_json(res, 200, *answer);
  } catch (const nlohmann::json::exception& e) {
    send_error(res, 400, std::string("the request lacks a field: ") + e.what());
  } catch (const std::invalid_argument& e) {
    send_error(res, 400, e.what());
  } catch (...) {
    send_failure(res, site.settings.scenes[i].string(), "refused");
  }
}

// The routes (server.hpp lists them): nothing else is served.
enum class Verb { get, post };
struct Route {
  Verb verb;
  const char* pattern;
  void (*handle)(Site&, const httplib::Request&, httplib::Response&);
};
constexpr std::array kRoutes{
    Route{Verb::get, "/", get_page},
    Route{Verb::get, "/api/scenes", get_scenes},
    Route{Verb::get, R"(/api/figure/(\d+))", get_figure},
    Route{Verb::get, R"(/api/measures/(\d+))", get_measures},
    Route{Verb::get, R"(/api/animation/(\d+))", get_animation},
    Route{Verb::get, R"(/api/export/(\d+))", get_export},
    Route{Verb::get, "/api/events", get_events},
    Route{Verb::post, R"(/api/edit/(\d+))", post_edit},
    Route{Verb::post, R"(/api/preview/(\d+))", post_preview},
};

}  // namespace

void set_up(httplib::Server& http, Site& site) {
  // HttpFront receives each request within its bounds first. The workers:
  // kEventStreams streams, kReceiving requests being received, and room for
  // the requests being answered.
  http.new_task_queue = [] { return new httplib::ThreadPool(64); };
  // SO_REUSEADDR only: a restart may bind while the old connections wait out
  // TIME_WAIT, but a port another server listens on is refused (cpp-httplib's
  // default adds SO_REUSEPORT, with which a second pita serve on a busy port
  // shared it silently and each took half of the page's requests).
  http.set_socket_options([](socket_t sock) {
    const int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof(yes));
  });
  // Every request carries the token (as Jupyter's): a page of another site
  // cannot guess it, so it can neither read nor drive this server.
  http.set_pre_routing_handler([&site](const httplib::Request& req, httplib::Response& res) {
    const std::string given =
        req.has_param("token") ? req.get_param_value("token") : req.get_header_value("X-Pita-Token");
    if (!token_matches(given, site.settings.token)) {
      send_error(res, 403, "a token is needed: use the address pita serve printed");
      return httplib::Server::HandlerResponse::Handled;
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });
  // An answer with an error status always says why, also when it comes from
  // the library (no such route, a malformed request) or from an exception.
  http.set_error_handler(httplib::Server::HandlerWithResponse([](const httplib::Request&, httplib::Response& res) {
    if (!res.body.empty()) return httplib::Server::HandlerResponse::Unhandled;
    send_error(res, res.status,
               res.status == 404   ? "no such page: pita serve answers / and the /api/ routes of its page"
               : res.status == 400 ? "a malformed request"
                                   : fmt::format("the request cannot be answered (HTTP {})", res.status));
    return httplib::Server::HandlerResponse::Handled;
  }));
  http.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr thrown) {
    std::string what = "an unknown exception";
    try {
      std::rethrow_exception(thrown);
    } catch (const std::exception& e) {
      what = e.what();
    } catch (...) {
    }
    send_error(res, 500, "internal error, a bug in pita (please report it): " + what);
  });
  for (const Route& route : kRoutes) {
    auto handler = [&site, handle = route.handle](const httplib::Request& req, httplib::Response& res) {
      handle(site, req, res);
    };
    if (route.verb == Verb::get) {
      http.Get(route.pattern, handler);
    } else {
      http.Post(route.pattern, handler);
    }
  }
}

}  // namespace pita::serve
