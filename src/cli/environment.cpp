#include "cli/environment.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <thread>

namespace pita::cli {

int threads_from_environment() {
  if (const char* given = std::getenv("PITA_THREADS")) {
    const int n = std::atoi(given);
    if (n >= 1 && n <= 64) return n;
  }
  return static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 64u));
}

bool progress_allowed(bool quiet) {
  const char* ci = std::getenv("CI");
  return !quiet && (ci == nullptr || *ci == '\0');
}

}  // namespace pita::cli
