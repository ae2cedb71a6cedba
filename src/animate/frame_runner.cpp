#include "animate/frame_runner.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdlib>
#include <exception>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

#include "render/interrupt.hpp"

namespace pita::animate {

void run_frames(int count, int threads, const std::function<std::string(int)>& render,
                const std::function<void(int, std::string&&)>& consume) {
  const int window = 2 * std::max(threads, 1);
  std::mutex mutex;
  std::condition_variable changed;
  std::map<int, std::string> ready;
  int next_to_consume = 0;
  int next_to_render = 0;
  bool stop = false;
  std::exception_ptr failure;

  const auto worker = [&] {
    while (true) {
      int k;
      {
        std::unique_lock lock(mutex);
        changed.wait(lock, [&] { return stop || next_to_render >= count || next_to_render < next_to_consume + window; });
        if (stop || next_to_render >= count) return;
        k = next_to_render++;
      }
      try {
        std::string bytes = render(k);
        std::lock_guard lock(mutex);
        ready.emplace(k, std::move(bytes));
      } catch (...) {
        std::lock_guard lock(mutex);
        if (!failure) failure = std::current_exception();
        stop = true;
      }
      changed.notify_all();
    }
  };

  std::vector<std::thread> pool;
  for (int i = 0; i < std::max(threads, 1); ++i) pool.emplace_back(worker);
  const auto finish = [&] {
    {
      std::lock_guard lock(mutex);
      stop = true;
    }
    changed.notify_all();
    for (std::thread& thread : pool) thread.join();
  };

  try {
    while (true) {
      std::string bytes;
      int k;
      {
        std::unique_lock lock(mutex);
        // Woken by workers; every 50 ms to look for a signal.
        changed.wait_for(lock, std::chrono::milliseconds(50),
                         [&] { return stop || ready.count(next_to_consume) > 0; });
        if (const int sig = render::pending_interrupt()) {
          lock.unlock();
          finish();
          throw Interrupted{sig};
        }
        if (failure) break;
        if (next_to_consume >= count) break;
        auto it = ready.find(next_to_consume);
        if (it == ready.end()) continue;
        bytes = std::move(it->second);
        ready.erase(it);
        k = next_to_consume++;
      }
      changed.notify_all();
      consume(k, std::move(bytes));
      if (k == count - 1) break;
    }
  } catch (const Interrupted&) {
    throw;
  } catch (...) {
    finish();
    throw;
  }
  finish();
  if (failure) std::rethrow_exception(failure);
  if (const int sig = render::pending_interrupt()) throw Interrupted{sig};
}

}  // namespace pita::animate
