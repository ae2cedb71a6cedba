#include "cli/scene_jobs.hpp"

#include <CLI/CLI.hpp>

#include "cli/environment.hpp"

namespace pita::cli {

void add_scene_jobs_option(CLI::App& command, std::optional<int>& jobs) {
  command
      .add_option_function<int>(
          "--jobs,-j", [&jobs](int j) { jobs = j; },
          "Scenes worked on at once (default: PITA_THREADS, else the number of cores); the output keeps the "
          "order of the scenes")
      ->type_name("J")
      ->check(CLI::Range(1, 64));
}

int scene_jobs(const std::optional<int>& jobs) { return jobs.value_or(threads_from_environment()); }

}  // namespace pita::cli
