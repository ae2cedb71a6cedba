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

std::string ffmpeg_from_environment() {
  if (const char* given = std::getenv("PITA_FFMPEG")) return ::access(given, X_OK) == 0 ? given : "";
  const char* path = std::getenv("PATH");
  const std::string dirs = path ? path : "/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = dirs.find(':', start);
    const std::string dir = dirs.substr(start, end == std::string::npos ? std::string::npos : end - start);
    const std::string candidate = (dir.empty() ? std::string(".") : dir) + "/ffmpeg";
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return "";
}

bool progress_allowed(bool quiet) {
  const char* ci = std::getenv("CI");
  return !quiet && (ci == nullptr || *ci == '\0');
}

}  // namespace pita::cli
