#include "animate/progress.hpp"

#include <cstdio>
#include <cstdlib>

#include <fmt/format.h>
#include <unistd.h>

namespace pita::animate {

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

Progress::Progress(std::string label, int total, bool enabled, bool plain_lines, std::chrono::milliseconds interval)
    : label_(std::move(label)),
      total_(total),
      mode_(!enabled               ? Mode::off
            : stderr_is_terminal() ? Mode::bar
            : plain_lines          ? Mode::lines
                                   : Mode::off),
      interval_(interval),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

Progress::~Progress() {
  if (drawn_ && mode_ == Mode::bar) std::fputs("\n", stderr);
}

std::string Progress::counts(int done) const {
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::string text = fmt::format("{}/{} ({}%)", done, total_, total_ > 0 ? 100LL * done / total_ : 100);
  if (done > 0 && seconds > 0) {
    const double rate = done / seconds;
    text += fmt::format(", {:.3g}/s", rate);
    if (done < total_) text += fmt::format(", ETA {:.0f} s", (total_ - done) / rate);
  }
  return text;
}

void Progress::update(int done) {
  if (mode_ == Mode::off) return;
  const auto now = std::chrono::steady_clock::now();
  if (mode_ == Mode::lines) {
    if (now - last_ < interval_) return;
    last_ = now;
    std::fputs(fmt::format("{}: {}\n", label_, counts(done)).c_str(), stderr);
    std::fflush(stderr);
    drawn_ = true;
    return;
  }
  if (done < total_ && drawn_ && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  draw(done);
}

void Progress::draw(int done) {
  constexpr int kWidth = 30;
  const int filled = total_ > 0 ? static_cast<int>(static_cast<long long>(kWidth) * done / total_) : kWidth;
  const std::string bar =
      std::string(static_cast<std::size_t>(filled), '#') + std::string(static_cast<std::size_t>(kWidth - filled), '.');
  // Trailing spaces clear the end of a longer previous line.
  std::fputs(fmt::format("\r{} [{}] {}   ", label_, bar, counts(done)).c_str(), stderr);
  std::fflush(stderr);
  drawn_ = true;
}

}  // namespace pita::animate
