// The one worker pool of pita: every parallel loop (sweep variants, animation
// frames, the audit's cells, the 3D existence search) runs its tasks by index
// on worker threads and consumes their results in index order on the calling
// thread. No I/O here: callers do theirs in `consume` and `tick`, and say how
// many threads (src/cli/environment.cpp chooses the default, PITA_THREADS).
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <map>
#include <mutex>
#include <optional>
#include <system_error>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace pita {

struct PoolOptions {
  int threads = 1;          // worker threads (at least one; never more than the tasks)
  std::int64_t window = 0;  // results produced ahead of the consumer, at most; 0: no bound
  std::chrono::milliseconds tick{100};  // `tick` runs at least this often while the caller waits
};

// Runs produce(i, stopping) for every i in [0, count) on worker threads and
// hands each result to consume(i, std::move(result)) on the calling thread, in
// increasing i. The work stops early when consume or tick returns false, or
// when produce, consume or tick throws; produce may watch `stopping` to cut a
// long task short (a result produced after the stop is dropped). Every worker
// has ended when run_ordered returns or rethrows the first exception. When the
// system refuses to start a thread, the pool runs with those it has, and
// throws std::system_error if it has none. Returns the number of results
// consumed.
template <class Produce, class Consume, class Tick>
std::int64_t run_ordered(std::int64_t count, const PoolOptions& options, Produce&& produce, Consume&& consume,
                         Tick&& tick) {
  using Result = std::invoke_result_t<Produce&, std::int64_t, const std::atomic<bool>&>;
  if (count <= 0) return 0;
  const std::int64_t window = options.window > 0 ? options.window : count;
  std::mutex mutex;
  std::condition_variable changed;
  std::map<std::int64_t, Result> ready;  // produced, not yet consumed (at most `window`)
  std::int64_t next_to_produce = 0;
  std::int64_t next_to_consume = 0;
  std::atomic<bool> stopping{false};
  std::exception_ptr failure;

  const auto worker = [&] {
    while (true) {
      std::int64_t i = 0;
      {
        std::unique_lock lock(mutex);
        changed.wait(lock, [&] {
          return stopping.load() || next_to_produce >= count || next_to_produce < next_to_consume + window;
        });
        if (stopping.load() || next_to_produce >= count) return;
        i = next_to_produce++;
      }
      try {
        Result result = produce(i, std::as_const(stopping));
        const std::lock_guard lock(mutex);
        ready.emplace(i, std::move(result));
      } catch (...) {
        const std::lock_guard lock(mutex);
        if (!failure) failure = std::current_exception();
        stopping = true;
      }
      changed.notify_all();
    }
  };

  std::vector<std::thread> pool;
  const auto finish = [&] {
    {
      const std::lock_guard lock(mutex);
      stopping = true;
    }
    changed.notify_all();
    for (std::thread& thread : pool) thread.join();
  };
  const auto threads = static_cast<std::int64_t>(std::max(options.threads, 1));
  for (std::int64_t t = 0; t < std::min(threads, count); ++t) {
    try {
      pool.emplace_back(worker);
    } catch (const std::system_error&) {
      if (pool.empty()) throw;
      break;  // fewer threads than asked
    }
  }

  std::int64_t consumed = 0;
  try {
    while (next_to_consume < count) {
      std::optional<Result> result;
      std::int64_t index = 0;
      {
        std::unique_lock lock(mutex);
        changed.wait_for(lock, options.tick, [&] { return failure || ready.count(next_to_consume) > 0; });
        if (failure) break;
        const auto found = ready.find(next_to_consume);
        if (found != ready.end()) {
          result.emplace(std::move(found->second));
          ready.erase(found);
          index = next_to_consume++;
        }
      }
      if (result) {
        changed.notify_all();  // a worker waiting on the window may go on
        ++consumed;
        if (!consume(index, std::move(*result))) break;
      }
      if (!tick()) break;
    }
  } catch (...) {
    finish();
    throw;
  }
  finish();
  if (failure) std::rethrow_exception(failure);
  return consumed;
}

}  // namespace pita
