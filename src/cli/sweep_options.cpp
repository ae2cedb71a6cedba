#include "cli/sweep_options.hpp"

#include <algorithm>
#include <optional>
#include <string_view>

#include <fmt/format.h>

#include "sweep/run_variant.hpp"
#include "text/list.hpp"

namespace pita::cli {

namespace {

std::string_view sweep_flag(sweep::Input input) {
  switch (input) {
    case sweep::Input::none:
      return "";
    case sweep::Input::vary:
      return "--vary";
    case sweep::Input::zip:
      return "--zip";
    case sweep::Input::output:
      return "-o";
    case sweep::Input::jobs:
      return "--jobs";
    case sweep::Input::merge:
      return "--merge";
    case sweep::Input::shard:
      return "--shard";
    case sweep::Input::wait:
      return "--wait";
    case sweep::Input::force:
      return "--force";
  }
  return "";
}

std::string named_sweep_error(const sweep::About& about, const std::string& reason, const char* what) {
  if (about.input == sweep::Input::none) return what;
  std::string text =
      fmt::format("{}{}: {}", sweep_flag(about.input), about.argument.empty() ? "" : " " + about.argument, reason);
  switch (about.remedy) {
    case sweep::Input::wait:
      return text + ", or give --wait to wait for it";
    case sweep::Input::force:
      return text + " (or --force to start this sweep over there)";
    case sweep::Input::shard:
      return text + fmt::format(" (run the shards with --shard K/N -o {} first)", about.argument);
    case sweep::Input::none:
    case sweep::Input::vary:
    case sweep::Input::zip:
    case sweep::Input::output:
    case sweep::Input::jobs:
    case sweep::Input::merge:
      return text;
  }
  return text;
}

}  // namespace

std::vector<sweep::OutputKind> parse_output_kinds(const std::string& text) {
  std::vector<sweep::OutputKind> kinds;
  text::for_each_item(text, [&](std::string_view item) {
    const std::optional<sweep::OutputKind> found = sweep::output_kind_named(item);
    if (!found) {
      throw sweep::SweepUsageError(
          fmt::format("--format: \"{}\" is not an output (use svg, png, pdf, csv, json or "
                      "metrics, comma-separated: --format svg,csv)",
                      item));
    }
    if (std::find(kinds.begin(), kinds.end(), *found) == kinds.end()) kinds.push_back(*found);
  });
  return kinds;
}

std::pair<int, int> parse_shard(const std::string& text) {
  const std::size_t slash = text.find('/');
  const auto digits = [](std::string_view t) {
    return !t.empty() && t.size() <= 9 && t.find_first_not_of("0123456789") == std::string_view::npos;
  };
  if (slash == std::string::npos || !digits(std::string_view(text).substr(0, slash)) ||
      !digits(std::string_view(text).substr(slash + 1))) {
    throw sweep::SweepUsageError(
        fmt::format("--shard: expected K/N with whole numbers 0 <= K < N, for example 0/4 "
                    "(got \"{}\")",
                    text));
  }
  const int k = std::stoi(text.substr(0, slash)), n = std::stoi(text.substr(slash + 1));
  if (n < 1 || k >= n) {
    throw sweep::SweepUsageError(
        fmt::format("--shard {}: K must be in 0..N-1 and N >= 1 (got K = {}, N = {})", text, k, n));
  }
  return {k, n};
}

std::string sweep_error_message(const sweep::SweepUsageError& error) {
  return named_sweep_error(error.about(), error.reason(), error.what());
}

std::string sweep_error_message(const sweep::SweepOutputError& error) {
  return named_sweep_error(error.about(), error.reason(), error.what());
}

}  // namespace pita::cli
