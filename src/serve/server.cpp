#include "serve/server.hpp"

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <random>
#include <set>
#include <thread>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "analysis/claims.hpp"
#include "analysis/measure.hpp"
#include "analysis/measure_report.hpp"
#include "animate/frame.hpp"
#include "animate/timeline.hpp"
#include "io/output_file.hpp"
#include "motion/no_motion.hpp"
#include "motion/stage.hpp"
#include "render/figure.hpp"
#include "render/panel_drawing.hpp"
#include "scene/image_file.hpp"
#include "scene/json_text.hpp"
#include "scene/limits.hpp"
#include "scene/located_error.hpp"
#include "scene/scene.hpp"
#include "serve/file_watch.hpp"
#include "serve/json_edit.hpp"
#include "serve/page.hpp"
#include "serve/scene_edit.hpp"

// Last: it includes <resolv.h>, whose macro _res would rename a parameter of Eigen's.
#include <httplib.h>

namespace pita::serve {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// What the page shows of an error: where (file, line:column or JSON Pointer) and why.
Json error_json(const std::exception_ptr& thrown, const std::string& path) {
  Json error{{"file", path}, {"line", 0}, {"column", 0}, {"pointer", ""}, {"reason", ""}, {"message", ""}};
  try {
    std::rethrow_exception(thrown);
  } catch (const scene::LocatedError& e) {  // SceneError, NoMotion, RenderError
    error.update({{"file", e.file()},
                  {"line", e.line()},
                  {"column", e.column()},
                  {"pointer", e.pointer()},
                  {"reason", e.reason()},
                  {"message", e.what()}});
  } catch (const std::exception& e) {
    error.update({{"reason", e.what()}, {"message", path + ": " + e.what()}});
  }
  return error;
}

// The HTTP status of the answer to a request that met the error: its kind's
// row of scene::kLocatedAnswers for a located error, else 422 (the scene, as
// it is, cannot be drawn or measured).
int error_status(const std::exception_ptr& thrown) {
  try {
    std::rethrow_exception(thrown);
  } catch (const scene::LocatedError& e) {
    return scene::answer(e.kind()).http_status;
  } catch (...) {
    return 422;
  }
}

// One scene of the command line: its last good figure and what is wrong now.
struct SceneState {
  fs::path path;
  std::uint64_t version = 0;
  std::shared_ptr<const scene::Scene> scene;       // the last good one
  std::string svg;                                 // its figure
  std::optional<Json> error;                       // the last save's, when it could not be drawn
  std::vector<fs::path> files;                     // the scene and its images (what is watched)
  std::vector<render::PanelPlacement> placements;  // where the last good figure drew each panel
  Json claims = Json::array();                     // its caption's claims, measured (as pita check does)
  std::string text;                                // the file it was read from
};

class Server {
 public:
  explicit Server(const Settings& settings) : settings_(settings) {
    for (const fs::path& path : settings.scenes) {
      auto state = std::make_unique<SceneState>();
      state->path = path;
      state->files = {path};
      scenes_.push_back(std::move(state));
    }
  }

  // Renders scene i from its file; keeps the last good figure when it fails.
  void render(std::size_t i) {
    SceneState& state = *scenes_[i];
    std::shared_ptr<const scene::Scene> scene;
    std::string svg;
    std::optional<Json> error;
    render::Figure figure;
    Json claims = Json::array();
    std::string text;
    try {
      text = scene::read_input_file(state.path, scene::kMaxSceneFileBytes, "scene file");
      scene = std::make_shared<const scene::Scene>(
          scene::parse_scene(text, state.path.string(), {settings_.allow_absolute_paths}));
      const motion::Stage stage(*scene);
      figure = render::build_figure(stage);
      svg = render::render_figure(*scene, figure, render::Format::svg);
      for (const analysis::ClaimOutcome& claim : analysis::check_claims(stage)) {
        claims.push_back(
            {{"pointer", claim.pointer}, {"says", claim.says}, {"held", claim.held}, {"measured", claim.measured}});
      }
    } catch (...) {
      error = error_json(std::current_exception(), state.path.string());
    }
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!error) {
        state.scene = scene;
        state.svg = std::move(svg);
        state.placements = figure.placements;
        state.claims = std::move(claims);
        state.text = std::move(text);
        state.files = {state.path};
        for (const fs::path& image : scene::image_files(*scene)) state.files.push_back(image);
      }
      state.error = std::move(error);
      ++state.version;
    }
    changed_.notify_all();
  }

  std::vector<fs::path> watched() {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::vector<fs::path> files;
    for (const auto& state : scenes_) files.insert(files.end(), state->files.begin(), state->files.end());
    return files;
  }

  // The scenes whose files are among `saved`.
  std::vector<std::size_t> scenes_of(const std::set<fs::path>& saved) {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::size_t> which;
    for (std::size_t i = 0; i < scenes_.size(); ++i) {
      for (const fs::path& file : scenes_[i]->files) {
        if (saved.count(fs::absolute(file).lexically_normal()) != 0) {
          which.push_back(i);
          break;
        }
      }
    }
    return which;
  }

  Json scenes_json() {
    const std::lock_guard<std::mutex> lock(mutex_);
    Json all = Json::array();
    for (std::size_t i = 0; i < scenes_.size(); ++i) {
      const SceneState& state = *scenes_[i];
      Json entry{{"index", i},
                 {"name", state.path.stem().string()},
                 {"path", state.path.string()},
                 {"version", state.version},
                 {"title", state.scene ? state.scene->title : ""},
                 {"error", state.error ? *state.error : Json(nullptr)},
                 {"timeline", nullptr},
                 {"handles", Json::array()},
                 {"claims", state.claims},
                 {"panels", Json::array()}};
      // Where each panel is drawn (canvas pixels): the page shows the measures of the one under the pointer.
      for (const render::PanelPlacement& placement : state.placements) {
        entry["panels"].push_back({placement.cell.x, placement.cell.y, placement.cell.width, placement.cell.height});
      }
      if (settings_.edit && state.scene) {
        for (const Handle& handle : handles(state.text, *state.scene, state.placements)) {
          entry["handles"].push_back({{"panel", handle.panel},
                                      {"pointer", handle.pointer},
                                      {"part", handle.part},
                                      {"at", {handle.at.real(), handle.at.imag()}}});
        }
      }
      if (state.scene) {
        try {
          const animate::Timeline timeline = animate::make_timeline(*state.scene);
          entry["timeline"] = Json{{"first", timeline.first},
                                   {"last", timeline.last},
                                   {"frames", timeline.frames},
                                   {"fps", timeline.fps},
                                   {"what", timeline.what == scene::Animation::What::pattern ? "pattern" : "motion"}};
        } catch (const std::exception&) {
          // no motion to play (a figure without one)
        }
      }
      all.push_back(entry);
    }
    return all;
  }

  std::optional<std::string> figure(std::size_t i, std::optional<double> at) {
    std::shared_ptr<const scene::Scene> scene;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!at) return scenes_[i]->scene ? std::optional<std::string>(scenes_[i]->svg) : std::nullopt;
      scene = scenes_[i]->scene;
    }
    if (!scene) return std::nullopt;
    const animate::Timeline timeline = animate::make_timeline(*scene);
    const render::Figure figure =
        animate::frame_figure(*scene, timeline, *at, animate::animation_layout(*scene, timeline));
    return render::render_figure(*scene, figure, render::Format::svg);
  }

  std::optional<std::string> measures(std::size_t i) {
    std::shared_ptr<const scene::Scene> scene;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      scene = scenes_[i]->scene;
    }
    if (!scene) return std::nullopt;
    analysis::check_measure_work(*scene);
    return analysis::measures_json(scene->path, analysis::measure_scene(*scene));
  }

  // Waits (at most `wait`) for a render newer than `seen`; the versions now.
  std::vector<std::uint64_t> versions_after(const std::vector<std::uint64_t>& seen, std::chrono::milliseconds wait) {
    std::unique_lock<std::mutex> lock(mutex_);
    const auto now = [&] {
      std::vector<std::uint64_t> versions;
      for (const auto& state : scenes_) versions.push_back(state->version);
      return versions;
    };
    changed_.wait_for(lock, wait, [&] { return now() != seen || stopping_; });
    return now();
  }

  // Applies an edit to scene i's file: checks the result as a scene (and
  // draws it) before writing it atomically. Returns the changes that undo
  // it; throws what reading or drawing the result throws, and
  // std::invalid_argument for a request that names no handle or value.
  Json edit(std::size_t i, const Json& request) {
    const std::lock_guard<std::mutex> one_at_a_time(edit_mutex_);
    const fs::path path = scenes_[i]->path;
    const std::string text = scene::read_input_file(path, scene::kMaxSceneFileBytes, "scene file");
    std::vector<Change> changes;
    if (request.contains("drag")) {
      const Json& d = request.at("drag");
      // Where the page drew the handle is where the figure it showed put it.
      if (d.contains("version")) {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (d.at("version").get<std::uint64_t>() != scenes_[i]->version) {
          throw std::invalid_argument("the figure changed while dragging: drag again");
        }
      }
      const scene::Scene scene = scene::parse_scene(text, path.string(), {settings_.allow_absolute_paths});
      const motion::Stage stage(scene);
      const render::Figure figure = render::build_figure(stage);
      // An index of the figure's panels: 1e20 or -1 would be read as another panel.
      const Json& panel = d.at("panel");
      if (!panel.is_number_unsigned() || panel.get<std::uint64_t>() >= figure.placements.size()) {
        throw std::invalid_argument(
            fmt::format("\"panel\" must be the index of a panel of the figure, 0 to {} (got {})",
                        figure.placements.size() - 1, panel.dump(-1, ' ', false, Json::error_handler_t::replace)));
      }
      changes =
          drag(text, scene, figure.placements, panel.get<std::size_t>(), d.at("pointer").get<std::string>(),
               d.at("part").get<std::string>(), Point{d.at("to").at(0).get<double>(), d.at("to").at(1).get<double>()});
    } else {
      for (const Json& change : request.at("changes")) {
        changes.push_back({change.at("pointer").get<std::string>(), change.at("value").get<std::string>()});
        check_change(text, changes.back());
      }
    }
    std::string edited = text;
    Json previous = Json::array();
    for (const Change& change : changes) {
      const TextSpan span = value_span(edited, change.pointer);
      previous.push_back({{"pointer", change.pointer}, {"value", edited.substr(span.begin, span.end - span.begin)}});
      edited = replace_value(edited, change.pointer, change.value);
    }
    // Refused unless the result is a scene pita draws.
    const scene::Scene checked = scene::parse_scene(edited, path.string(), {settings_.allow_absolute_paths});
    const motion::Stage stage(checked);
    render::render_figure(checked, render::build_figure(stage), render::Format::svg);
    // The file itself (through a link, its target), with the permissions it had.
    const fs::path target = fs::canonical(path);
    const fs::perms permissions = fs::status(target).permissions();
    // Not over a save made since the edit read the file (an editor's, while
    // the edit was checked): the file is left as it is when it changed.
    if (!io::replace_file_if_unchanged(target, text, edited)) {
      throw std::invalid_argument(
          "the file changed while the edit was checked (saved by another program): it is kept as it is; drag again");
    }
    fs::permissions(target, permissions);
    return Json{{"previous", previous}};
  }

  void stop() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    changed_.notify_all();
  }
  bool stopping() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return stopping_;
  }
  std::size_t size() const { return scenes_.size(); }

 private:
  const Settings& settings_;
  std::vector<std::unique_ptr<SceneState>> scenes_;
  std::mutex mutex_;
  std::mutex edit_mutex_;  // one edit of the files at a time
  std::condition_variable changed_;
  bool stopping_ = false;
};

// The scene index of /api/.../N; nullopt for anything else.
std::optional<std::size_t> scene_index(const std::string& text, std::size_t count) {
  if (text.empty() || text.size() > 6 || text.find_first_not_of("0123456789") != std::string::npos) {
    return std::nullopt;
  }
  const std::size_t i = std::stoul(text);
  return i < count ? std::optional<std::size_t>(i) : std::nullopt;
}

// A body of JSON text as it is (pita measure's report).
void send_json_text(httplib::Response& res, int status, const std::string& text) {
  res.status = status;
  res.set_header("Cache-Control", "no-store");
  res.set_content(text, "application/json");
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
struct Site {
  Server& state;
  const Settings& settings;
};

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
    const auto svg = site.state.figure(*i, at);
    if (!svg) return send_error(res, 409, "the scene has no good figure yet: see its error");
    res.set_header("Cache-Control", "no-store");
    // With the charset, not the bare type: cpp-httplib compresses a bare
    // image/svg+xml with brotli at its slowest setting when the browser
    // accepts it (380 ms for Fig. 1's 150 kB; 7 ms to send it as it is).
    res.set_content(*svg, "image/svg+xml; charset=utf-8");
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
// that keeps proxies and the browser patient.
void get_events(Site& site, const httplib::Request&, httplib::Response& res) {
  res.set_header("Cache-Control", "no-store");
  Server& state = site.state;
  auto seen = std::make_shared<std::vector<std::uint64_t>>(state.versions_after({}, std::chrono::milliseconds(0)));
  res.set_chunked_content_provider("text/event-stream", [&state, seen](std::size_t, httplib::DataSink& sink) {
    const std::vector<std::uint64_t> now = state.versions_after(*seen, std::chrono::seconds(5));
    if (state.stopping()) return false;
    std::string events;
    for (std::size_t i = 0; i < now.size(); ++i) {
      if (now[i] != (*seen)[i]) events += fmt::format("data: {{\"scene\": {}, \"version\": {}}}\n\n", i, now[i]);
    }
    if (events.empty()) events = ": still here\n\n";
    *seen = now;
    return sink.write(events.data(), events.size());
  });
}

void post_edit(Site& site, const httplib::Request& req, httplib::Response& res) {
  if (!site.settings.edit) return send_error(res, 403, "editing is off: start pita serve with --edit");
  const auto i = scene_index(req.matches[1], site.state.size());
  if (!i) return send_error(res, 404, "no such scene");
  Json request;
  try {
    request = Json::parse(req.body);
  } catch (const std::exception&) {
    return send_error(res, 400, "the request is not JSON");
  }
  try {
    send_json(res, 200, site.state.edit(*i, request));
  } catch (const nlohmann::json::exception& e) {
    send_error(res, 400, std::string("the request lacks a field: ") + e.what());
  } catch (const std::invalid_argument& e) {
    send_error(res, 400, e.what());
  } catch (...) {
    // The edit would make the scene bad: refused, with the reason; the file is as it was.
    send_failure(res, site.settings.scenes[*i].string(), "refused");
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
    Route{Verb::get, "/api/events", get_events},
    Route{Verb::post, R"(/api/edit/(\d+))", post_edit},
};

// The HTTP server's limits, its token check and its routes.
void set_up(httplib::Server& http, Site& site) {
  http.set_payload_max_length(64 * 1024);  // no request of the page is larger: a larger one is refused (413)
  http.set_keep_alive_max_count(100);
  // Each page holds a worker for its event stream: room for many tabs, and
  // idle connections let go of theirs soon.
  http.new_task_queue = [] { return new httplib::ThreadPool(64); };
  http.set_keep_alive_timeout(1);
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

// Binds the settings' host and port (0: any free one); the port, or -1.
int bind_port(httplib::Server& http, const Settings& settings) {
  if (settings.port == 0) return http.bind_to_any_port(settings.host);
  return http.bind_to_port(settings.host, settings.port) ? settings.port : -1;
}

// Renders each saved scene again, until stopped; watches the files of the
// last good figures (`files` are those watched now). Returns 0 when
// stopped, 3 when watching fails.
int render_saves(Server& state, FileWatcher& watcher, std::vector<fs::path> files, std::ostream& log,
                 const std::function<bool()>& stopped) {
  try {
    std::vector<fs::path> now = state.watched();
    if (now != files) watcher.watch(files = std::move(now));  // the images of the first renders
    while (!stopped()) {
      const std::set<fs::path> saved = watcher.wait(std::chrono::milliseconds(100), std::chrono::milliseconds(20));
      if (saved.empty()) continue;
      for (const std::size_t i : state.scenes_of(saved)) state.render(i);
      now = state.watched();
      if (now != files) watcher.watch(files = std::move(now));
    }
  } catch (const std::exception& error) {
    log << "pita: stopped watching the scenes (" << error.what() << ")\n";
    return 3;
  }
  return 0;
}

}  // namespace

std::string random_token() {
  std::random_device source;
  std::string token;
  for (int i = 0; i < 4; ++i) token += fmt::format("{:08x}", source());
  return token;
}

int serve(const Settings& settings, std::ostream& log, const std::function<bool()>& stopped) {
  Server state(settings);
  // Watching starts before the first renders, so that no save is missed;
  // a watch that cannot be set up is said before anything is served.
  FileWatcher watcher;
  const std::vector<fs::path> files = state.watched();
  try {
    watcher.watch(files);
  } catch (const std::system_error& error) {
    log << "pita: cannot watch the scenes (" << error.what() << ")\n";
    return 2;
  }
  for (std::size_t i = 0; i < state.size(); ++i) state.render(i);

  httplib::Server http;
  Site site{state, settings};
  set_up(http, site);
  const int port = bind_port(http, settings);
  if (port < 0) {
    log << fmt::format("pita: cannot listen on {}:{} (in use, or not an address of this machine)\n", settings.host,
                       settings.port);
    return 3;
  }
  std::thread listener([&] { http.listen_after_bind(); });
  const std::string host = settings.host.find(':') != std::string::npos ? "[" + settings.host + "]" : settings.host;
  log << fmt::format("pita: serving {} scene{} at http://{}:{}/?token={}\n", state.size(), state.size() == 1 ? "" : "s",
                     host, port, settings.token)
      << std::flush;

  const int code = render_saves(state, watcher, files, log, stopped);
  state.stop();
  http.stop();
  listener.join();
  return code;
}

}  // namespace pita::serve
