// Exit codes of pita, by name (habit copied from ninja). main() maps every
// failure to one of them.
#pragma once

namespace pita::cli {

enum class ExitCode : int {
  success = 0,
  golden_mismatch = 1,  // pita check: a figure differs from its golden, or has none
  bad_input = 2,        // bad usage, a bad scene, or a motion that does not exist for it
  failure = 3,          // anything else: the output could not be written, or a bug
};

inline int to_int(ExitCode code) { return static_cast<int>(code); }

}  // namespace pita::cli
