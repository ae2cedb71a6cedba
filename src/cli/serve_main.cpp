// pita-serve: the server of `pita serve` (cli/serve.hpp), a program of its
// own so that only it loads the HTTP library.
#include <atomic>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <thread>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <pthread.h>
#include <signal.h>

#include "cli/exit_code.hpp"
#include "cli/serve.hpp"
#include "io/interrupt.hpp"
#include "serve/server.hpp"
#include "serve/token.hpp"

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
  // Stopped within a second whatever the server is doing: when it has not
  // returned a second after the signal (a render or an answer still
  // running), the process ends as any pita does on a signal (the temporary
  // files of an edit in flight removed, exit 128 + the signal).
  static std::atomic<int> received{0};  // static: the waiter may outlive this call
  static std::atomic<bool> returned{false};
  std::thread waiter([stopping] {
    int sig = 0;
    if (sigwait(&stopping, &sig) != 0) return;
    received = sig;
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(1);
    while (std::chrono::steady_clock::now() < end) {
      if (returned) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    if (!returned) io::exit_interrupted(sig);
  });
  waiter.detach();

  serve::Settings settings;
  for (const std::string& path : options.scene_paths) settings.scenes.emplace_back(path);
  settings.host = options.host;
  settings.port = options.port;
  if (!options.token.empty()) {
    if (const auto problem = serve::token_problem(options.token)) {
      std::cerr << "pita: --token: " << *problem << '\n';
      return to_int(ExitCode::bad_input);
    }
    settings.token = options.token;
  } else if (options.keep_token) {
    try {
      settings.token = serve::kept_token(std::filesystem::current_path(), options.new_token);
    } catch (const std::exception& error) {
      std::cerr << "pita: --keep-token: cannot keep the token (" << error.what() << "); a new one is drawn\n";
      settings.token = serve::random_token();
    }
  } else {
    settings.token = serve::random_token();
  }
  settings.open = options.open;
  settings.allow_absolute_paths = options.allow_absolute_paths;
  settings.edit = options.edit;
  const int code = serve::serve(settings, std::cerr, [] { return received.load() != 0; });
  returned = true;
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
