// pita eval --batch FILE: many evaluations in one process.
//
// Each line of FILE (or of standard input, "-") is one request: the arguments
// of one `pita eval`, as a JSON array of strings, for example
//   ["scenes/fig01-eight-pitas.json", "--t=0,0.5", "--method", "P8"]
// Each request is parsed by the same CLI11 declaration as the command line
// (setup_eval) and evaluated by the same function (evaluate), so its answer
// is, byte for byte, what a separate process would print. The answer is one
// line of JSON, printed and flushed as soon as the request is done:
//   {"exit": 0, "stdout": "{\"method\": ...}", "stderr": ""}
// A bad request is answered with its exit code and message, and the batch
// goes on; the batch's own exit code is the worst of its requests'. A batch
// saves the start of a process per evaluation: about 15 ms in a Release
// build, 100 ms under the sanitizers (the oracles of tests/oracle use it).
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/eval.hpp"
#include "io/input_file.hpp"
#include "scene/batch_request.hpp"
#include "scene/limits.hpp"
#include "scene/scene.hpp"

namespace pita::cli {

namespace {

struct FileCloser {
  void operator()(std::FILE* file) const {
    if (file != nullptr && file != stdin) std::fclose(file);
  }
};
using BatchFile = std::unique_ptr<std::FILE, FileCloser>;

// One request, as `pita eval ARGUMENTS...` would answer it.
EvalOutcome answer(const std::vector<std::string>& arguments, const std::string& where) {
  CLI::App app{"", "pita"};
  const std::shared_ptr<EvalOptions> options = setup_eval(app);
  std::vector<std::string> reversed(arguments.rbegin(), arguments.rend());  // CLI11 parses from the back
  reversed.push_back("eval");
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError& error) {
    if (error.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) {
      return {ExitCode::bad_input, {}, fmt::format("pita: {}: --help and --version are not requests\n", where), 0.0};
    }
    return {ExitCode::bad_input, {}, fmt::format("pita: {}\nRun 'pita --help' for usage.\n", error.what()), 0.0};
  }
  if (options->batch) {
    return {ExitCode::bad_input, {}, fmt::format("pita: {}: a request cannot hold --batch\n", where), 0.0};
  }
  if (options->output) {
    return {ExitCode::bad_input,
            {},
            fmt::format("pita: {}: a request cannot hold -o: its frames are its answer's \"stdout\"\n", where),
            0.0};
  }
  if (options->scene_path.empty()) {
    return {ExitCode::bad_input, {}, fmt::format("pita: {}: SCENE is required\n", where), 0.0};
  }
  return evaluate(*options);
}

std::string answer_line(const EvalOutcome& outcome) {
  const nlohmann::ordered_json line = {
      {"exit", to_int(outcome.code)}, {"stdout", outcome.out}, {"stderr", outcome.err}};
  // A path or an argument echoed in a message may not be UTF-8: replaced, not refused.
  return line.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + '\n';
}

EvalOutcome refused(const std::string& message) { return {ExitCode::bad_input, {}, "pita: " + message + '\n', 0.0}; }

}  // namespace

ExitCode run_eval_batch(const std::string& path) {
  const bool from_stdin = path == "-";
  // A file or a pipe (<(...)), never a device or a directory: /dev/zero, one
  // endless line, was never answered.
  if (const std::optional<std::string> what = from_stdin ? std::nullopt : io::neither_file_nor_pipe(path)) {
    std::cerr << "pita: " << path << ": cannot read the batch file: " << *what << "\n";
    return ExitCode::bad_input;
  }
  const BatchFile file(from_stdin ? stdin : std::fopen(path.c_str(), "r"));
  if (file == nullptr) {
    std::cerr << "pita: " << path << ": cannot open the batch file (" << std::strerror(errno) << ")\n";
    return ExitCode::bad_input;
  }
  const std::string name = from_stdin ? "standard input" : path;
  ExitCode worst = ExitCode::success;
  double work = 0.0;
  scene::BatchLine line;
  for (std::size_t number = 1; scene::next_batch_line(file.get(), line); ++number) {
    const std::string where = fmt::format("{}:{}", name, number);
    EvalOutcome outcome;
    if (number > scene::kMaxBatchRequests) {
      outcome =
          refused(fmt::format("{}: a batch holds at most {} requests: split it", where, scene::kMaxBatchRequests));
    } else if (line.too_long) {
      outcome = refused(
          fmt::format("{}: the request is longer than the limit of {} MiB", where, scene::kMaxBatchLineBytes >> 20));
    } else if (work > scene::kMaxBatchWork) {
      outcome =
          refused(fmt::format("{}: the batch has done about {:.3g} frames of its methods, above the limit "
                              "of {:.0g}: split it",
                              where, work, scene::kMaxBatchWork));
    } else {
      try {
        outcome = answer(scene::batch_request_arguments(line.text, where), where);
      } catch (const scene::SceneError& error) {
        outcome = refused(error.what());
      }
    }
    work += outcome.work;
    worst = worse(worst, outcome.code);
    const std::string text = answer_line(outcome);
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0) {
      std::cerr << "pita: cannot write the answers to standard output (" << std::strerror(errno) << ")\n";
      return ExitCode::failure;
    }
  }
  if (std::ferror(file.get())) {
    std::cerr << "pita: " << name << ": cannot read the batch (" << std::strerror(errno) << ")\n";
    return worse(worst, ExitCode::bad_input);
  }
  return worst;
}

}  // namespace pita::cli
