// Every way a subcommand can fail on one input, mapped to an exit code and a
// message that names the input, in one place: the catch blocks of eval,
// render, check and update-goldens all call current_failure().
#pragma once

#include <string>
#include <string_view>

#include "cli/exit_code.hpp"

namespace pita::cli {

struct Failure {
  ExitCode code = ExitCode::internal_error;
  std::string message;  // without the "pita: " prefix
};

// The exception being handled (call it inside a catch block):
//   a located error (SceneError, NoMotion, RenderError)
//                                                      -> its kind's exit code (scene::kLocatedAnswers:
//                                                         bad_input), its what()
//   AnimationError, GoldenError                        -> bad_input, their what()
//   render::ImageError                                 -> bad_input, "INPUT: " and its what()
//   io::OutputError                                    -> failure, its what()
//   std::bad_alloc                                     -> bad_input, "INPUT: out of memory ..."
//   anything else                                      -> internal_error, "INPUT: internal error ..."
// `input` is the scene (or golden) being worked on, for the last two.
// The message is printable (printable_text): a scene's name or value with
// an ESC or BEL in it cannot drive the terminal.
Failure current_failure(const std::string& input);

// `text` with its control characters (but line breaks and tabs) escaped as
// \xNN: what pita echoes of its input (file names, JSON values, arguments).
std::string printable_text(std::string_view text);

}  // namespace pita::cli
