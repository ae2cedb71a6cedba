#include "cli/environment.hpp"

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <string_view>
#include <thread>

#include <unistd.h>

#include "animate/video.hpp"

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

std::string ffmpeg_from_environment() {
  const auto value = [](const char* name) -> std::optional<std::string_view> {
    const char* set = std::getenv(name);
    return set ? std::optional<std::string_view>(set) : std::nullopt;
  };
  return animate::find_ffmpeg(value("PITA_FFMPEG"), value("PATH"));
}

}  // namespace pita::cli
