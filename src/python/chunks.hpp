// Long loops of the module run without the GIL, in chunks: between two, the
// GIL is taken back for a moment to see whether Ctrl-C was pressed
// (KeyboardInterrupt is then raised, and nothing is returned). A long call
// that has no chunks (a figure, an animation) is watched the same way.
#pragma once

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

#include <pybind11/pybind11.h>

namespace pita::python {

inline constexpr std::size_t kChunk = std::size_t{1} << 16;

// Calls step(begin, end) over [0, n) in chunks of kChunk, without the GIL;
// stops early when step returns false. Throws py::error_already_set on a
// pending signal (KeyboardInterrupt); exceptions of step pass through.
template <class Step>
void for_each_chunk(std::size_t n, Step&& step) {
  for (std::size_t begin = 0; begin < n; begin += kChunk) {
    const std::size_t end = std::min(n, begin + kChunk);
    bool go_on = true;
    {
      pybind11::gil_scoped_release unlocked;
      go_on = step(begin, end);
    }
    if (!go_on) return;
    if (PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
  }
}

// ------------------------------------------------------------ one long call

// Whether Ctrl-C was pressed: takes the GIL for a moment (from a thread that
// released it) and runs Python's signal handlers. True when one raised
// (KeyboardInterrupt is then set: throw py::error_already_set once the GIL
// is back). Call it only on the thread that released the GIL.
inline bool interrupted_from_released() {
  pybind11::gil_scoped_acquire held;
  return PyErr_CheckSignals() != 0;
}

// The threads of run_interruptible still working (their caller may have
// raised KeyboardInterrupt already). Never destroyed: a thread may end after
// the interpreter.
struct BackgroundWork {
  std::mutex mutex;
  std::condition_variable idle;
  int running = 0;
};
inline BackgroundWork& background_work() {
  static BackgroundWork* const work = new BackgroundWork;
  return *work;
}

// Waits, without the GIL, until no such thread works: registered with atexit
// (module.cpp), so that a drawing dropped by Ctrl-C is not still running
// while the process tears down what it uses.
inline void wait_for_background_work() {
  pybind11::gil_scoped_release unlocked;
  BackgroundWork& work = background_work();
  std::unique_lock lock(work.mutex);
  work.idle.wait(lock, [&] { return work.running == 0; });
}

// Runs `work()` (one call that cannot be cut into chunks: a figure drawn by
// cairo, a text of frames) on a thread of its own, without the GIL, while
// this thread sees Ctrl-C every 50 ms: on one, KeyboardInterrupt is raised
// at once and the work's result, when it comes, is dropped. `work` must own
// what it uses (copies, shared_ptr): it may outlive the call. Exceptions of
// work pass through.
template <class Work>
auto run_interruptible(Work work) -> decltype(work()) {
  using Result = decltype(work());
  struct Shared {
    std::mutex mutex;
    std::condition_variable done_changed;
    bool done = false;
    std::optional<Result> result;
    std::exception_ptr failure;
  };
  auto shared = std::make_shared<Shared>();
  BackgroundWork& background = background_work();
  {
    const std::lock_guard lock(background.mutex);
    ++background.running;
  }
  const auto not_running = [&background] {
    const std::lock_guard lock(background.mutex);
    --background.running;
    background.idle.notify_all();
  };
  std::thread thread;
  try {
    thread = std::thread([shared, not_running, owned = std::optional<Work>(std::move(work))]() mutable {
      std::optional<Result> result;
      std::exception_ptr failure;
      try {
        result.emplace((*owned)());
      } catch (...) {
        failure = std::current_exception();
      }
      {
        const std::lock_guard lock(shared->mutex);
        shared->result = std::move(result);
        shared->failure = failure;
        shared->done = true;
        shared->done_changed.notify_all();
      }
      owned.reset();  // what it held (a scene), released before the thread counts as done
      not_running();
    });
  } catch (...) {  // no thread could be started (std::system_error: RuntimeError)
    not_running();
    throw;
  }
  thread.detach();
  for (;;) {
    bool done = false;
    {
      pybind11::gil_scoped_release unlocked;
      std::unique_lock lock(shared->mutex);
      done = shared->done_changed.wait_for(lock, std::chrono::milliseconds(50), [&] { return shared->done; });
    }
    if (done) break;
    if (PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
  }
  if (shared->failure) std::rethrow_exception(shared->failure);
  return std::move(*shared->result);
}

}  // namespace pita::python
