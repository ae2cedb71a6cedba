// pita eval SCENE.json [--method M] [--samples N | --t T1,T2,...] [--format json|csv] [-o FILE]
// pita eval --batch FILE
//
// Evaluates the motion through the keyframes of a scene at sample times and
// prints the frames (JSON or CSV) on stdout or into FILE, streamed in memory
// that does not grow with the number of frames; with --batch, many such
// evaluations in one process (cli/eval_batch.cpp).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "cli/exit_code.hpp"

namespace CLI {
class App;
}

namespace pita::cli {

struct EvalOptions {
  std::string scene_path;
  std::optional<std::string> method;   // --method, as typed
  std::optional<std::string> samples;  // --samples, as typed
  std::optional<std::string> times;    // --t, as typed: "0,0.25,1.5"
  std::string format = "json";         // --format: json or csv
  bool format_given = false;           // --format was given (else -o's extension may choose it)
  std::optional<int> panel;            // --panel: the motion of this panel (0-based)
  std::optional<std::string> batch;    // --batch: a file of requests, "-" for stdin
  std::optional<std::string> output;   // -o: the frames go into this file, written atomically
};

// What one evaluation prints: the frames (stdout) and the messages (stderr,
// each line "pita: ..."), and the work it cost (frames of the method).
struct EvalOutcome {
  ExitCode code = ExitCode::success;
  std::string out;
  std::string err;
  double work = 0.0;
};

// Declares the eval subcommand on `app`; app.parse() fills the returned options.
std::shared_ptr<EvalOptions> setup_eval(CLI::App& app);

// Does the work of one evaluation (options.batch is ignored) without printing.
EvalOutcome evaluate(const EvalOptions& options);

// Does the work. Prints the frames on stdout (or writes them into
// options.output), or a message on stderr and nothing on stdout (and no
// file); with options.batch, runs the batch.
ExitCode run_eval(const EvalOptions& options);

// pita eval --batch FILE: each request line evaluated as `pita eval ARGS...`
// would, its outcome printed as one JSON line (cli/eval_batch.cpp).
ExitCode run_eval_batch(const std::string& path);

}  // namespace pita::cli
