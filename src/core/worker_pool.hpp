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
  int threads = 1;                      // worker threads (at least one; never more than the tasks)
  std::int64_t window = 0;              // results produced ahead of the consumer, at most; 0: no bound
  std::chrono::milliseconds tick{100};  // `tick` runs at least this often while the caller waits
};

namespace detail {

// What run_ordered's workers and its caller share: the next index to
// produce and to consume, the results produced ahead (at most `window`), and
// the first failure.
template <class Result>
class OrderedResults {
 public:
  OrderedResults(std::int64_t count, std::int64_t window) : count_(count), window_(window) {}

  // A worker: takes the next index within the window, produces it and keeps
  // its result, until every index is taken or the work stops; a failure
  // stops it.
  template <class Produce>
  void work(Produce& produce) {
    while (true) {
      std::int64_t i = 0;
      {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] {
          return stopping_.load() || next_to_produce_ >= count_ || next_to_produce_ < next_to_consume_ + window_;
        });
        if (stopping_.load() || next_to_produce_ >= count_) return;
        i = next_to_produce_++;
      }
      try {
        Result result = produce(i, std::as_const(stopping_));
        const std::lock_guard lock(mutex_);
        ready_.emplace(i, std::move(result));
      } catch (...) {
        const std::lock_guard lock(mutex_);
        if (!failure_) failure_ = std::current_exception();
        stopping_ = true;
      }
      changed_.notify_all();
    }
  }

  // Whether results remain to consume (the caller's thread only).
  bool more() const { return next_to_consume_ < count_; }

  // The caller: waits at most `tick` for the next result in order, into
  // `result` (its index into `index`) if it came. False once a worker failed.
  bool wait_next(std::chrono::milliseconds tick, std::optional<Result>& result, std::int64_t& index) {
    {
      std::unique_lock lock(mutex_);
      changed_.wait_for(lock, tick, [&] { return failure_ || ready_.count(next_to_consume_) > 0; });
      if (failure_) return false;
      const auto found = ready_.find(next_to_consume_);
      if (found == ready_.end()) return true;
      result.emplace(std::move(found->second));
      ready_.erase(found);
      index = next_to_consume_++;
    }
    changed_.notify_all();  // a worker waiting on the window may go on
    return true;
  }

  // Stops the workers: they end after the task they are running.
  void stop() {
    {
      const std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    changed_.notify_all();
  }

  // Once the workers have ended: rethrows the first failure, if any.
  void rethrow_failure() const {
    if (failure_) std::rethrow_exception(failure_);
  }

 private:
  const std::int64_t count_;
  const std::int64_t window_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::map<std::int64_t, Result> ready_;  // produced, not yet consumed (at most `window`)
  std::int64_t next_to_produce_ = 0;
  std::int64_t next_to_consume_ = 0;
  std::atomic<bool> stopping_{false};
  std::exception_ptr failure_;
};

// Starts min(threads, count) threads running `worker`, or as many as the
// system allows; throws std::system_error when it allows none.
template <class Worker>
std::vector<std::thread> start_workers(int threads, std::int64_t count, const Worker& worker) {
  std::vector<std::thread> pool;
  const auto wanted = static_cast<std::int64_t>(std::max(threads, 1));
  for (std::int64_t t = 0; t < std::min(wanted, count); ++t) {
    try {
      pool.emplace_back(worker);
    } catch (const std::system_error&) {
      if (pool.empty()) throw;
      break;  // fewer threads than asked
    }
  }
  return pool;
}

}  // namespace detail

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
  detail::OrderedResults<Result> results(count, options.window > 0 ? options.window : count);
  std::vector<std::thread> pool = detail::start_workers(options.threads, count, [&] { results.work(produce); });
  const auto finish = [&] {
    results.stop();
    for (std::thread& thread : pool) thread.join();
  };
  std::int64_t consumed = 0;
  try {
    while (results.more()) {
      std::optional<Result> result;
      std::int64_t index = 0;
      if (!results.wait_next(options.tick, result, index)) break;
      if (result) {
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
  results.rethrow_failure();
  return consumed;
}

}  // namespace pita
