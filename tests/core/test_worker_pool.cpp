// The one worker pool (src/core/worker_pool.hpp): results consumed in index
// order whatever the order they finish in, at most `window` ahead, and every
// way of stopping early (consume, tick, an exception) ends every worker.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/worker_pool.hpp"

namespace pita {
namespace {

PoolOptions threads_and_window(int threads, std::int64_t window) {
  PoolOptions options;
  options.threads = threads;
  options.window = window;
  options.tick = std::chrono::milliseconds(1);
  return options;
}

TEST(WorkerPool, ConsumesInIndexOrderWhateverTheOrderOfFinishing) {
  std::vector<std::int64_t> order;
  const std::int64_t consumed = run_ordered(
      200, threads_and_window(4, 0),
      [](std::int64_t i, const std::atomic<bool>&) {
        // Later indices first: a task sleeps longer the smaller its index mod 7.
        std::this_thread::sleep_for(std::chrono::microseconds(50 * (7 - i % 7)));
        return i * i;
      },
      [&](std::int64_t i, std::int64_t&& square) {
        EXPECT_EQ(square, i * i);
        order.push_back(i);
        return true;
      },
      [] { return true; });
  EXPECT_EQ(consumed, 200);
  ASSERT_EQ(order.size(), 200U);
  for (std::size_t k = 0; k < order.size(); ++k) EXPECT_EQ(order[k], static_cast<std::int64_t>(k));
}

TEST(WorkerPool, ProducesAtMostTheWindowAheadOfTheConsumer) {
  constexpr std::int64_t kWindow = 3;
  std::atomic<std::int64_t> consumed{0};
  std::atomic<std::int64_t> farthest{0};
  run_ordered(
      100, threads_and_window(4, kWindow),
      [&](std::int64_t i, const std::atomic<bool>&) {
        // Taken only while i < next consumed + window; `consumed` counts the
        // consume calls, which follow one step behind.
        const std::int64_t ahead = i - consumed.load();
        std::int64_t seen = farthest.load();
        while (ahead > seen && !farthest.compare_exchange_weak(seen, ahead)) {
        }
        return i;
      },
      [&](std::int64_t, std::int64_t&&) {
        std::this_thread::sleep_for(std::chrono::microseconds(200));  // a slow consumer
        ++consumed;
        return true;
      },
      [] { return true; });
  EXPECT_EQ(consumed.load(), 100);
  EXPECT_LE(farthest.load(), kWindow);
  EXPECT_GE(farthest.load(), 1);  // the workers did run ahead
}

TEST(WorkerPool, ConsumeReturningFalseStopsTheRest) {
  std::atomic<std::int64_t> produced{0};
  const std::int64_t consumed = run_ordered(
      100000, threads_and_window(2, 4),
      [&](std::int64_t i, const std::atomic<bool>&) {
        ++produced;
        return i;
      },
      [](std::int64_t i, std::int64_t&&) { return i < 9; }, [] { return true; });
  EXPECT_EQ(consumed, 10);
  EXPECT_LT(produced.load(), 10 + 4 + 2 + 1);  // the window and the tasks in flight, no more
}

TEST(WorkerPool, TickReturningFalseStopsAndTheStopIsVisibleToTasks) {
  std::atomic<int> started{0};
  std::atomic<bool> saw_stop{false};
  const std::int64_t consumed = run_ordered(
      4, threads_and_window(2, 0),
      [&](std::int64_t, const std::atomic<bool>& stopping) {
        ++started;
        // Each task waits for the stop (or gives up after 5 s).
        for (int k = 0; k < 5000 && !stopping.load(); ++k) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        saw_stop = saw_stop || stopping.load();
        return 0;
      },
      [](std::int64_t, int&&) { return true; }, [&] { return started.load() == 0; });  // stop once a task runs
  EXPECT_EQ(consumed, 0);
  EXPECT_GE(started.load(), 1);
  EXPECT_LE(started.load(), 2);  // the two workers' first tasks; no other began after the stop
  EXPECT_TRUE(saw_stop.load());
}

TEST(WorkerPool, TheFirstExceptionIsRethrownAfterEveryWorkerEnded) {
  std::atomic<int> running{0};
  const auto run = [&] {
    run_ordered(
        1000, threads_and_window(3, 0),
        [&](std::int64_t i, const std::atomic<bool>&) {
          ++running;
          if (i == 17) {
            --running;
            throw std::runtime_error("task 17");
          }
          std::this_thread::sleep_for(std::chrono::microseconds(100));
          --running;
          return i;
        },
        [](std::int64_t, std::int64_t&&) { return true; }, [] { return true; });
  };
  EXPECT_THROW(run(), std::runtime_error);
  EXPECT_EQ(running.load(), 0);  // joined: nothing still runs
  // An exception of the consumer or of tick goes out the same way.
  EXPECT_THROW(run_ordered(
                   10, threads_and_window(2, 0), [](std::int64_t i, const std::atomic<bool>&) { return i; },
                   [](std::int64_t i, std::int64_t&&) -> bool { throw std::logic_error(std::to_string(i)); },
                   [] { return true; }),
               std::logic_error);
  EXPECT_THROW(
      run_ordered(
          10, threads_and_window(2, 0), [](std::int64_t i, const std::atomic<bool>&) { return i; },
          [](std::int64_t, std::int64_t&&) { return true; }, []() -> bool { throw std::out_of_range("tick"); }),
      std::out_of_range);
}

TEST(WorkerPool, NoTasksNoCallsAndMoreThreadsThanTasks) {
  int calls = 0;
  EXPECT_EQ(run_ordered(
                0, threads_and_window(8, 0),
                [&](std::int64_t, const std::atomic<bool>&) {
                  ++calls;
                  return 0;
                },
                [&](std::int64_t, int&&) { return ++calls > 0; }, [&] { return ++calls > 0; }),
            0);
  EXPECT_EQ(calls, 0);
  EXPECT_EQ(run_ordered(
                2, threads_and_window(64, 0), [](std::int64_t i, const std::atomic<bool>&) { return i; },
                [](std::int64_t, std::int64_t&&) { return true; }, [] { return true; }),
            2);
}

}  // namespace
}  // namespace pita
