#include "animate/frame_runner.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>

#include "core/worker_pool.hpp"
#include "io/interrupt.hpp"

namespace pita::animate {

int pending_stop(const std::function<bool()>& cancelled) {
  if (const int sig = io::pending_interrupt()) return sig;
  return cancelled && cancelled() ? kCancelled : 0;
}

void stop_interrupted(int signal) {
  if (signal == kCancelled) throw Cancelled{};
  io::exit_interrupted(signal);
}

void run_frames(int count, int threads, const std::function<std::string(int)>& render,
                const std::function<void(int, std::string&&)>& consume, const std::function<bool()>& cancelled) {
  PoolOptions options;
  options.threads = std::max(threads, 1);
  options.window = 2 * options.threads;
  options.tick = std::chrono::milliseconds(50);  // how soon a signal is seen
  const auto interrupted = [&] {
    if (const int sig = pending_stop(cancelled)) throw Interrupted{sig};
    return true;
  };
  run_ordered(
      count, options, [&](std::int64_t k, const std::atomic<bool>&) { return render(static_cast<int>(k)); },
      [&](std::int64_t k, std::string&& bytes) {
        consume(static_cast<int>(k), std::move(bytes));
        return interrupted();
      },
      interrupted);
  interrupted();
}

}  // namespace pita::animate
