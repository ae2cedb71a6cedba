#include "serve/server.hpp"

#include <chrono>
#include <memory>
#include <set>
#include <thread>

#include <fcntl.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "serve/file_watch.hpp"
#include "serve/live_scenes.hpp"
#include "serve/routes.hpp"

// Last: it includes cpp-httplib's <httplib.h>, whose <resolv.h> macro _res would rename a parameter of Eigen's.
#include "serve/http_front.hpp"

namespace pita::serve {

namespace {

// Binds the settings' host and port (0: any free one); the port, or -1.
int bind_port(httplib::Server& http, const Settings& settings) {
  if (settings.port == 0) return http.bind_to_any_port(settings.host);
  return http.bind_to_port(settings.host, settings.port) ? settings.port : -1;
}

// --open: the desktop's browser shows `url` (xdg-open, Debian's xdg-utils),
// waited for on a thread of its own; when it cannot be started, the log says so.
void open_in_browser(const std::string& url, std::ostream& log) {
  std::vector<char*> argv{const_cast<char*>("xdg-open"), const_cast<char*>(url.c_str()), nullptr};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int failed = ::posix_spawnp(&pid, "xdg-open", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (failed != 0) {
    log << "pita: --open: cannot start xdg-open (Debian xdg-utils): open the address above yourself\n";
    return;
  }
  std::thread([pid] {
    int status = 0;
    ::waitpid(pid, &status, 0);
  }).detach();
}

// Renders each saved scene again, until stopped; watches the files of the
// last good figures (`files` are those watched now). Returns 0 when
// stopped, 3 when watching fails.
int render_saves(LiveScenes& state, FileWatcher& watcher, std::vector<fs::path> files, std::ostream& log,
                 const std::function<bool()>& stopped) {
  try {
    std::vector<fs::path> now = state.watched();
    if (now != files) watcher.watch(files = std::move(now));  // the images of the first renders
    while (!stopped()) {
      const std::set<fs::path> saved = watcher.wait(std::chrono::milliseconds(100), std::chrono::milliseconds(20));
      if (saved.empty()) continue;
      for (const std::size_t i : state.scenes_of(saved)) state.render(i, true);
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

struct Service::Parts {
  explicit Parts(const Settings& given)
      : settings(given), state(settings), http(HttpLimits{}, allowed_hosts(settings.host)), site{state, settings} {
    set_up(http, site);
  }
  Settings settings;
  LiveScenes state;
  HttpFront http;
  Site site;
};

Service::Service(const Settings& settings) : parts_(std::make_unique<Parts>(settings)) {}
Service::~Service() = default;

void Service::render_all() {
  for (std::size_t i = 0; i < parts_->state.size(); ++i) parts_->state.render(i);
}

std::string Service::answer(std::string_view request) { return parts_->http.answer(request); }

int Service::run(std::ostream& log, const std::function<bool()>& stopped) {
  const Settings& settings = parts_->settings;
  LiveScenes& state = parts_->state;
  HttpFront& http = parts_->http;
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
  state.set_log(&log);
  render_all();

  const int port = bind_port(http, settings);
  if (port < 0) {
    log << fmt::format("pita: cannot listen on {}:{} (in use, or not an address of this machine)\n", settings.host,
                       settings.port);
    return 3;
  }
  std::thread listener([&] { http.listen_after_bind(); });
  const std::string host = settings.host.find(':') != std::string::npos ? "[" + settings.host + "]" : settings.host;
  const std::string url = fmt::format("http://{}:{}/?token={}", host, port, settings.token);
  log << fmt::format("pita: serving {} scene{} at {}\n", state.size(), state.size() == 1 ? "" : "s", url) << std::flush;
  if (settings.open) open_in_browser(url, log);

  const int code = render_saves(state, watcher, files, log, stopped);
  state.stop();
  http.stop_receiving();
  http.stop();
  listener.join();
  return code;
}

int serve(const Settings& settings, std::ostream& log, const std::function<bool()>& stopped) {
  Service service(settings);
  return service.run(log, stopped);
}

}  // namespace pita::serve
