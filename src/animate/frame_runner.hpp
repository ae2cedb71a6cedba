// Frames rendered in parallel, consumed in order (docs/reference/animate.md "Animation"): worker
// threads render frames ahead of the consumer, at most `window` ahead, so
// that memory stays bounded whatever the number of frames (frames are
// streamed, never all held).
#pragma once

#include <exception>
#include <functional>
#include <string>

namespace pita::animate {

// Thrown when SIGINT, SIGTERM or SIGHUP arrived (io/interrupt.hpp's
// deferred mode): the caller removes what it wrote and exits.
struct Interrupted {
  int signal = 0;  // kCancelled when the caller's hook asked to stop
};

// Interrupted::signal when a caller's cancel hook (Request::cancelled, the
// Python module's Ctrl-C) asked to stop, not a signal pita handles.
inline constexpr int kCancelled = -1;

// What write_animation throws, in place of exiting, when its cancel hook
// asked to stop: its temporaries are removed and nothing was written.
struct Cancelled : std::exception {
  const char* what() const noexcept override { return "the animation was cancelled; nothing was written"; }
};

// The signal pending (io/interrupt.hpp's deferred mode), else kCancelled
// when `cancelled` is given and returns true, else 0. Call it on the thread
// that called write_animation.
int pending_stop(const std::function<bool()>& cancelled);

// Stops as `signal` (from pending_stop) says: throws Cancelled for
// kCancelled, else removes the registered temporaries and exits with 128 +
// signal (io::exit_interrupted).
[[noreturn]] void stop_interrupted(int signal);

// Renders frames 0 .. count - 1 with `render` on `threads` threads (>= 1) and
// hands each result to `consume` in order of k, on the calling thread. The
// first exception of either stops the others and is rethrown here; a pending
// interrupt, or `cancelled` returning true (both checked between frames, on
// the calling thread), throws Interrupted.
void run_frames(int count, int threads, const std::function<std::string(int)>& render,
                const std::function<void(int, std::string&&)>& consume, const std::function<bool()>& cancelled = {});

}  // namespace pita::animate
