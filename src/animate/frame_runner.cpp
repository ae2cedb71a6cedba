#include "animate/frame_runner.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>

#include "core/worker_pool.hpp"
#include "io/interrupt.hpp"

namespace pita::animate {

void run_frames(int count, int threads, const std::function<std::string(int)>& render,
                const std::function<void(int, std::string&&)>& consume) {
  PoolOptions options;
  options.threads = std::max(threads, 1);
  options.window = 2 * options.threads;
  options.tick = std::chrono::milliseconds(50);  // how soon a signal is seen
  const auto interrupted = [] {
    if (const int sig = io::pending_interrupt()) throw Interrupted{sig};
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
