// A command line that asks for something pita cannot do (a bad option value,
// options that contradict each other): each command catches it and says
// "pita: MESSAGE" with exit 2 (exit_code.hpp).
#pragma once

#include <stdexcept>

namespace pita::cli {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace pita::cli
