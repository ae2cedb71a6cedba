// Every way a subcommand can fail on one input, mapped to an exit code and a
// message that names the input, in one place: the catch blocks of eval,
// render, check and update-goldens all call current_failure().
#pragma once

#include <string>

#include "cli/exit_code.hpp"

namespace pita::cli {

struct Failure {
  ExitCode code = ExitCode::internal_error;
  std::string message;  // without the "pita: " prefix
};

// The exception being handled (call it inside a catch block):
//   SceneError, NoMotion, RenderError, GoldenError    -> bad_input, their what()
//   render::OutputError                                -> failure, its what()
//   std::bad_alloc                                     -> bad_input, "INPUT: out of memory ..."
//   anything else                                      -> internal_error, "INPUT: internal error ..."
// `input` is the scene (or golden) being worked on, for the last two.
Failure current_failure(const std::string& input);

}  // namespace pita::cli
