#include "cli/serve.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <unistd.h>

namespace pita::cli {

namespace {

namespace fs = std::filesystem;

// pita-serve beside this pita (the build folder), else where it is installed.
std::optional<fs::path> helper_path() {
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  if (error) return std::nullopt;
  const std::vector<fs::path> candidates{self.parent_path() / "pita-serve",
                                         self.parent_path().parent_path() / "libexec" / "pita" / "pita-serve"};
  for (const fs::path& candidate : candidates) {
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return std::nullopt;
}

}  // namespace

void add_serve_options(CLI::App& command, ServeOptions& options) {
  command.add_option("SCENE", options.scene_paths, "Scene files (JSON)")->required();
  command.add_option("--port", options.port, "Port to listen on (0: any free port)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str()
      ->type_name("N");
  command
      .add_option("--host", options.host,
                  "Address to listen on; another than 127.0.0.1 or ::1 lets other machines connect, and is warned "
                  "about")
      ->capture_default_str()
      ->type_name("ADDRESS");
  command.add_flag("--allow-absolute-paths", options.allow_absolute_paths, "Allow images given by absolute paths");
  command.add_flag("--edit", options.edit,
                   "Let the page drag keyframe arrows (tail, tip) and pose corners, and save turned 3D views, "
                   "writing them into the scene files (atomically, keeping the rest of each file as it is)");
  command
      .add_option("--token", options.token,
                  "The token every request must give (16 to 128 letters, digits, - or _), instead of a new random "
                  "one: open tabs reconnect after a restart with it")
      ->type_name("T");
  auto* keep = command.add_flag("--keep-token", options.keep_token,
                                "Keep the token for this folder (in ~/.local/state/pita/serve-tokens/, readable by "
                                "you only): a restart here reconnects the open tabs");
  command.add_flag("--new-token", options.new_token, "With --keep-token: draw a new token and keep it instead")
      ->needs(keep);
  keep->excludes(command.get_option("--token"));
  command.add_flag("--open", options.open, "Open the page in the browser (xdg-open) once it is served");
}

std::shared_ptr<ServeOptions> setup_serve(CLI::App& app) {
  auto options = std::make_shared<ServeOptions>();
  CLI::App* serve = app.add_subcommand("serve", "Show scenes live in a local page, re-rendered on every save");
  serve->footer(R"(
Serves a page that shows each scene's figure and renders it again each time the scene, or an
image it uses, is saved: the page updates without reloading. A bad save shows its error (file,
line:column or JSON Pointer) above the last good figure. A scene with a motion or an animation
has a time slider and a play button (the frames `pita render --at T` draws); the claims of the
scene's caption show as held or failed, and the measures of `pita measure` of the panel under
the pointer.

It listens on 127.0.0.1 only, unless --host says otherwise. The address it prints carries a
random token that every request must give: another page of the browser cannot read or drive
the server. Only the scenes named are served. Ctrl-C stops it.

With --edit, the tails and tips of the keyframe arrows and the corners of the poses can be dragged
in the page; each drag is written into the scene file (atomically; the rest of the file, its
order, spacing and numbers, as it was), unless it would make the scene bad: then the page shows
why and the file stays. The timeline's markers move the keyframes' times the same way.
Ctrl+Z undoes an edit and Ctrl+Shift+Z redoes it, byte for byte. A drag on a 3D scene's
figure turns its camera (in the page only; with --edit, "Save view" writes it into the file).

Examples:
  pita serve scenes/fig01-eight-pitas.json
  pita serve scenes/fig0*.json --port 9000

Exit codes: 2 bad input or usage (pita-serve missing included); 3 the port cannot be used;
128 + N when signal N stops it.
)");
  add_serve_options(*serve, *options);
  return options;
}

ExitCode run_serve(const ServeOptions& options) {
  const auto helper = helper_path();
  if (!helper) {
    std::cerr << "pita: serve needs pita-serve beside pita (or in ../libexec/pita/); build it with "
                 "`cmake --build build --target pita-serve`\n";
    return ExitCode::bad_input;
  }
  std::vector<std::string> args{helper->string(), "--port", std::to_string(options.port), "--host", options.host};
  if (options.allow_absolute_paths) args.emplace_back("--allow-absolute-paths");
  if (options.edit) args.emplace_back("--edit");
  if (!options.token.empty()) args.insert(args.end(), {"--token", options.token});
  if (options.keep_token) args.emplace_back("--keep-token");
  if (options.new_token) args.emplace_back("--new-token");
  if (options.open) args.emplace_back("--open");
  args.emplace_back("--");
  args.insert(args.end(), options.scene_paths.begin(), options.scene_paths.end());
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  ::execv(helper->c_str(), argv.data());
  std::cerr << fmt::format("pita: cannot start {} ({})\n", helper->string(), std::strerror(errno));
  return ExitCode::bad_input;
}

}  // namespace pita::cli
