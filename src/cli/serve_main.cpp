// pita-serve: the server of `pita serve` (cli/serve.hpp), a program of its
// own so that only it loads the HTTP library.
#include <atomic>
#include <filesystem>
#include <iostream>
#include <thread>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <pthread.h>
#include <signal.h>

#include "cli/exit_code.hpp"
#include "cli/serve.hpp"
#include "serve/server.hpp"

namespace pita::cli {
namespace {

// Serves until SIGINT, SIGTERM or SIGHUP (exit 128 + the signal); exit 2 for
// a scene that is not a file, 3 when the port cannot be bound.
int serve_main(const ServeOptions& options) {
  for (const std::string& path : options.scene_paths) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
      std::cerr << "pita: " << path << ": no such scene file\n";
      return to_int(ExitCode::bad_input);
    }
  }
  if (options.host != "127.0.0.1" && options.host != "::1" && options.host != "localhost") {
    std::cerr << fmt::format(
        "pita: warning: listening on {}: other machines can connect (each still needs the "
        "token)\n",
        options.host);
  }
  // SIGINT, SIGTERM and SIGHUP are taken by a thread of their own, which
  // stops the server: the page's requests in flight end, nothing is left.
  sigset_t stopping;
  sigemptyset(&stopping);
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&stopping, sig);
  pthread_sigmask(SIG_BLOCK, &stopping, nullptr);
  ::signal(SIGPIPE, SIG_IGN);
  std::atomic<int> received{0};
  std::thread waiter([&] {
    int sig = 0;
    if (sigwait(&stopping, &sig) == 0) received = sig;
  });
  waiter.detach();

  serve::Settings settings;
  for (const std::string& path : options.scene_paths) settings.scenes.emplace_back(path);
  settings.host = options.host;
  settings.port = options.port;
  settings.token = serve::random_token();
  settings.allow_absolute_paths = options.allow_absolute_paths;
  settings.edit = options.edit;
  const int code = serve::serve(settings, std::cerr, [&] { return received.load() != 0; });
  if (code != 0) return code;
  std::cerr << "pita: stopped\n";
  return 128 + received.load();
}

}  // namespace
}  // namespace pita::cli

int main(int argc, char** argv) {
  CLI::App app{"pita-serve: the server of `pita serve` (run `pita serve --help`)", "pita-serve"};
  pita::cli::ServeOptions options;
  pita::cli::add_serve_options(app, options);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : 2;
  }
  return pita::cli::serve_main(options);
}
