// Commands that work on many scenes (render, check, update-goldens) spread
// them over threads with --jobs, and still print and write in the order the
// scenes were given: each scene is worked on a worker thread, into a value
// that holds everything it will print or write, and that value is consumed on
// the calling thread, scene after scene (core/worker_pool.hpp).
#pragma once

#include <cstdint>
#include <optional>
#include <utility>

#include "core/worker_pool.hpp"

namespace CLI {
class App;
}

namespace pita::cli {

// Declares --jobs,-j J on `command`: scenes worked on at once (default: the
// PITA_THREADS environment variable, else the number of cores).
void add_scene_jobs_option(CLI::App& command, std::optional<int>& jobs);

// The threads --jobs asks for, or the default.
int scene_jobs(const std::optional<int>& jobs);

// produce(i) on worker threads, for every scene index i in [0, count);
// consume(i, result) on the calling thread, in increasing i. At most
// kResultsPerJob results per thread wait to be consumed, so memory stays that
// of a few figures per thread whatever the number of scenes, and a slow scene
// (fig10-property-table takes a quarter of `pita check`) does not hold the
// other threads back while they work on the scenes after it. produce must catch what a scene can
// throw and put it in its result: an exception that leaves it ends the run.
inline constexpr int kResultsPerJob = 8;

template <class Produce, class Consume>
void for_each_scene(std::size_t count, int jobs, Produce&& produce, Consume&& consume) {
  PoolOptions pool;
  pool.threads = jobs;
  pool.window = kResultsPerJob * static_cast<std::int64_t>(jobs);
  run_ordered(
      static_cast<std::int64_t>(count), pool,
      [&](std::int64_t i, const auto&) { return produce(static_cast<std::size_t>(i)); },
      [&](std::int64_t i, auto&& result) {
        consume(static_cast<std::size_t>(i), std::forward<decltype(result)>(result));
        return true;
      },
      [] { return true; });
}

}  // namespace pita::cli
