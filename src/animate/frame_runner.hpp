// Frames rendered in parallel, consumed in order (docs/reference/animate.md "Animation"): worker
// threads render frames ahead of the consumer, at most `window` ahead, so
// that memory stays bounded whatever the number of frames (frames are
// streamed, never all held).
#pragma once

#include <functional>
#include <string>

namespace pita::animate {

// Thrown when SIGINT, SIGTERM or SIGHUP arrived (io/interrupt.hpp's
// deferred mode): the caller removes what it wrote and exits.
struct Interrupted {
  int signal = 0;
};

// Renders frames 0 .. count - 1 with `render` on `threads` threads (>= 1) and
// hands each result to `consume` in order of k, on the calling thread. The
// first exception of either stops the others and is rethrown here; a pending
// interrupt (checked between frames) throws Interrupted.
void run_frames(int count, int threads, const std::function<std::string(int)>& render,
                const std::function<void(int, std::string&&)>& consume);

}  // namespace pita::animate
