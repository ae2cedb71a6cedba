// The options of `pita sweep` in the command line's words: --format and
// --shard parsed, and the errors of src/sweep, which name what they are about
// (sweep::About) but no option, told with the option's flag.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "sweep/folder.hpp"
#include "sweep/grid.hpp"
#include "sweep/sweep.hpp"

namespace pita::cli {

// --format "svg,png,csv" -> kinds, each once; throws sweep::SweepUsageError naming --format.
std::vector<sweep::OutputKind> parse_output_kinds(const std::string& text);

// --shard "K/N" -> (K, N), 0 <= K < N; throws sweep::SweepUsageError naming --shard.
std::pair<int, int> parse_shard(const std::string& text);

// "--vary ARGUMENT: REASON" (or "--vary: REASON"), then the option that would
// let it pass ("..., or give --wait to wait for it"); what() alone when the
// error is about no input.
std::string sweep_error_message(const sweep::SweepUsageError& error);
std::string sweep_error_message(const sweep::SweepOutputError& error);

}  // namespace pita::cli
