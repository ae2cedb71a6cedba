// Exit codes of pita, by name (habit copied from ninja). main() maps every
// failure to one of them.
#pragma once

namespace pita::cli {

enum class ExitCode : int {
  success = 0,
  golden_mismatch = 1,  // pita check: a figure differs from its golden, or has none
  bad_input = 2,        // bad usage, a bad scene or golden, a motion that does not exist
                        // for it, or work beyond the budget or the memory available
  failure = 3,          // an output could not be written (a file, standard output)
  internal_error = 4,   // a bug in pita: an exception nothing expected (please report it)
};

// The more serious of two outcomes of a run over several scenes.
inline ExitCode worse(ExitCode a, ExitCode b) {
  const auto rank = [](ExitCode c) {
    switch (c) {
      case ExitCode::success:
        return 0;
      case ExitCode::golden_mismatch:
        return 1;
      case ExitCode::failure:
        return 2;
      case ExitCode::bad_input:
        return 3;
      case ExitCode::internal_error:
        return 4;
    }
    return 4;
  };
  return rank(a) >= rank(b) ? a : b;
}

inline int to_int(ExitCode code) { return static_cast<int>(code); }

}  // namespace pita::cli
