// A progress bar for long work (README "Animation"): drawn on stderr only
// when stderr is a terminal, not silenced (--quiet) and not in CI (the
// environment variable CI set), so that CI logs and pipes stay clean.
#pragma once

#include <chrono>
#include <string>

namespace pita::animate {

class Progress {
 public:
  // `enabled`: the caller's choice (not --quiet); the bar shows only if stderr
  // is also a terminal.
  Progress(std::string label, int total, bool enabled);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // `done` of the total are finished; redrawn at most 10 times a second.
  void update(int done);
  bool shown() const { return shown_; }

 private:
  void draw(int done);
  std::string label_;
  int total_;
  bool shown_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_{};
};

// Whether stderr is a terminal.
bool stderr_is_terminal();

}  // namespace pita::animate
