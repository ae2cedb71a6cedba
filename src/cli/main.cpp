// pita: the command-line front end. Each subcommand lives in its own file
// (an options struct, setup_<name>, run_<name>); main maps every failure to an
// ExitCode. CLI11's own parse errors would exit 100-127: they exit 2 here.
#include <algorithm>
#include <csignal>
#include <exception>
#include <iostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/animate.hpp"
#include "cli/audit.hpp"
#include "cli/eval.hpp"
#include "cli/exit_code.hpp"
#include "cli/failure.hpp"
#include "cli/generate.hpp"
#include "cli/golden.hpp"
#include "cli/lint.hpp"
#include "cli/measure.hpp"
#include "cli/pose_audit.hpp"
#include "cli/render.hpp"
#include "cli/sam3d_existence.hpp"
#include "cli/serve.hpp"
#include "cli/sweep.hpp"
#include "cli/watch.hpp"
#include "io/interrupt.hpp"
#include "scene/did_you_mean.hpp"

#ifndef PITA_VERSION
#error "PITA_VERSION is defined by src/CMakeLists.txt"
#endif

namespace {

constexpr const char* kDescription =
    "pita: planar interpolation of three arrows and steady affine morphs. Computes the motions "
    "(PITAs P1-P10 and the steady morph SMA) through timed keyframes, and the Steady Affine "
    "Morphs (SAM, polySAM, Bezier SAM, bi-arc) through timed affine poses, given as JSON scenes.";

// The version flag, the subcommand rule, and the examples and exit codes of --help.
void describe(CLI::App& app) {
  app.set_version_flag("--version", std::string("pita ") + PITA_VERSION);
  // Not app.require_subcommand(): CLI11 would then report "pita --frobnicate"
  // as a missing subcommand instead of naming the unknown option.
  app.require_subcommand(0, 1);
  app.footer(
      "\nExamples:\n"
      "  pita eval scenes/fig01-eight-pitas.json            print the frames as JSON\n"
      "  pita render scenes/fig01-eight-pitas.json -o fig01.png\n"
      "  pita render scenes/*.json -o out --format svg,png  every figure into out/\n"
      "  pita animate scenes/fig23-image-motion.json -o fig23.svg   an animated SVG\n"
      "  pita measure scenes/fig12-pops.json                discrepancy, overreaction, pops\n"
      "  pita lint scenes/*.json                            text over data, cut-off labels, tiny frames\n"
      "  pita check                                         every figure against golden/\n"
      "  pita audit -o fig10.svg                            Fig. 10's properties, measured\n"
      "  pita sweep SCENE --vary /keyframes/1/t=0.2:0.8:7 -o out   a parameter sweep\n\n"
      "Run 'pita eval --help' for the scene format and the methods, 'pita render --help'\n"
      "for figures.\n"
      "Exit codes: 0 success, 1 a figure differs from its golden (check), 2 bad input or\n"
      "usage (also work beyond the budget, or out of memory), 3 an output could not be\n"
      "written, 4 an internal error (a bug: please report it), 128+N interrupted by\n"
      "signal N (unfinished outputs removed).");
}

// CLI11 reports an unknown subcommand as "A subcommand is required": name it,
// and suggest the closest known one. True when refused (the message printed).
bool refuse_unknown_subcommand(const CLI::App& app, int argc, char** argv) {
  if (argc <= 1 || argv[1][0] == '-') return false;
  const std::string_view given = argv[1];
  std::vector<std::string_view> known;
  for (const CLI::App* subcommand : app.get_subcommands([](const CLI::App*) { return true; })) {
    known.push_back(subcommand->get_name());
  }
  if (std::find(known.begin(), known.end(), given) != known.end()) return false;
  std::cerr << "pita: unknown subcommand \"" << given << '"'
            << pita::scene::did_you_mean(pita::scene::closest_names(given, known))
            << "\nRun 'pita --help' for usage.\n";
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  using pita::cli::ExitCode;
  using pita::cli::to_int;

  // SIGINT, SIGTERM, SIGHUP: remove the temporary files in flight, exit 128 + signal.
  pita::io::install_interrupt_cleanup();
  // A closed pipe (pita eval ... | head) is a write error (EPIPE) that the code
  // reports with exit 3, not a silent death by SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);

  CLI::App app{kDescription, "pita"};
  describe(app);

  const auto eval_options = pita::cli::setup_eval(app);
  const auto render_options = pita::cli::setup_render(app);
  const auto animate_options = pita::cli::setup_animate(app);
  const auto check_options = pita::cli::setup_check(app);
  const auto update_options = pita::cli::setup_update_goldens(app);
  const auto audit_options = pita::cli::setup_audit(app);
  const auto sam3d_existence_options = pita::cli::setup_sam3d_existence(*app.get_subcommand("audit"));
  const auto pose_audit_options = pita::cli::setup_pose_audit(*app.get_subcommand("audit"));
  const auto measure_options = pita::cli::setup_measure(app);
  const auto lint_options = pita::cli::setup_lint(app);
  const auto sweep_options = pita::cli::setup_sweep(app);
  const auto watch_options = pita::cli::setup_watch(app);
  const auto serve_options = pita::cli::setup_serve(app);
  // Hidden: the man page and the shell completions, generated from this App at build time.
  const auto generate_options = pita::cli::setup_generate(app);

  if (refuse_unknown_subcommand(app, argc, argv)) return to_int(ExitCode::bad_input);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    if (error.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) {
      app.exit(error);  // --help or --version: printed on stdout
      return to_int(ExitCode::success);
    }
    std::cerr << "pita: " << pita::cli::printable_text(error.what()) << "\nRun 'pita --help' for usage.\n";
    return to_int(ExitCode::bad_input);
  }

  if (!generate_options->what.empty()) {
    return to_int(pita::cli::run_generate(app, *generate_options, PITA_VERSION));
  }

  try {
    if (app.got_subcommand("eval")) return to_int(pita::cli::run_eval(*eval_options));
    if (app.got_subcommand("render")) return to_int(pita::cli::run_render(*render_options));
    if (app.got_subcommand("animate")) return to_int(pita::cli::run_animate(*animate_options));
    if (sam3d_existence_options->command->parsed()) {
      return to_int(pita::cli::run_sam3d_existence(*sam3d_existence_options));
    }
    if (pose_audit_options->command->parsed()) return to_int(pita::cli::run_pose_audit_command(*pose_audit_options));
    if (app.got_subcommand("audit")) return to_int(pita::cli::run_audit_command(*audit_options));
    if (app.got_subcommand("check")) return to_int(pita::cli::run_check(*check_options));
    if (app.got_subcommand("measure")) return to_int(pita::cli::run_measure(*measure_options));
    if (app.got_subcommand("lint")) return to_int(pita::cli::run_lint(*lint_options));
    if (app.got_subcommand("sweep")) return to_int(pita::cli::run_sweep_command(*sweep_options));
    if (app.got_subcommand("watch")) return to_int(pita::cli::run_watch(*watch_options));
    if (app.got_subcommand("serve")) return to_int(pita::cli::run_serve(*serve_options));
    if (app.got_subcommand("update-goldens")) {
      return to_int(pita::cli::run_update_goldens(*update_options));
    }
  } catch (...) {  // each subcommand names its input; this is the last resort
    const pita::cli::Failure failure = pita::cli::current_failure(
        app.get_subcommands().empty() ? std::string("pita") : app.get_subcommands().front()->get_name());
    std::cerr << "pita: " << failure.message << '\n';
    return to_int(failure.code);
  }
  std::cerr << "pita: missing subcommand, for example: pita eval scenes/fig01-eight-pitas.json\n"
               "Run 'pita --help' for usage.\n";
  return to_int(ExitCode::bad_input);
}
