#include "animate/progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

#include <fmt/format.h>

namespace pita::animate {

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

// A terminal inside CI (CI=true, as CI services set it) stays quiet too.
Progress::Progress(std::string label, int total, bool enabled)
    : label_(std::move(label)),
      total_(total),
      shown_(enabled && stderr_is_terminal() && (std::getenv("CI") == nullptr || *std::getenv("CI") == '\0')) {}

Progress::~Progress() {
  if (drawn_) std::fputs("\n", stderr);
}

void Progress::update(int done) {
  if (!shown_) return;
  const auto now = std::chrono::steady_clock::now();
  if (done < total_ && drawn_ && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  draw(done);
}

void Progress::draw(int done) {
  constexpr int kWidth = 30;
  const int filled = total_ > 0 ? kWidth * done / total_ : kWidth;
  const std::string bar = std::string(static_cast<std::size_t>(filled), '#') +
                          std::string(static_cast<std::size_t>(kWidth - filled), '.');
  std::fputs(fmt::format("\r{} [{}] {}/{} ({}%)", label_, bar, done, total_, total_ > 0 ? 100 * done / total_ : 100).c_str(),
             stderr);
  std::fflush(stderr);
  drawn_ = true;
}

}  // namespace pita::animate
