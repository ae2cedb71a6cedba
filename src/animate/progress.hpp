// A progress bar for long work (docs/reference/animate.md "Animation", docs/reference/sweep.md "pita sweep"): drawn on
// stderr only when stderr is a terminal and the caller enables it (the CLI
// does unless --quiet or in CI: cli/environment.hpp), so that CI logs and
// pipes stay clean.
// Work that may run for hours off a terminal (a sweep under nohup or a batch
// scheduler) asks for plain lines instead: one every kPlainInterval when
// stderr is not a terminal (still none in CI or with --quiet).
#pragma once

#include <chrono>
#include <string>

namespace pita::animate {

inline constexpr std::chrono::seconds kPlainInterval{10};

class Progress {
 public:
  // `enabled`: the caller's choice (not --quiet); the bar shows only if stderr
  // is also a terminal. `plain_lines`: off a terminal, print a line every
  // `interval` instead of nothing.
  Progress(std::string label, int total, bool enabled, bool plain_lines = false,
           std::chrono::milliseconds interval = kPlainInterval);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // `done` of the total are finished; the bar is redrawn at most 10 times a
  // second, a plain line printed at most once per interval.
  void update(int done);
  bool shown() const { return mode_ != Mode::off; }

 private:
  enum class Mode { off, bar, lines };
  // "120/1000 (12%), 35.1/s, ETA 25 s"
  std::string counts(int done) const;
  void draw(int done);
  std::string label_;
  int total_;
  Mode mode_;
  bool drawn_ = false;
  std::chrono::milliseconds interval_;
  std::chrono::steady_clock::time_point start_, last_{};
};

// Whether stderr is a terminal.
bool stderr_is_terminal();

}  // namespace pita::animate
