// The options of pita sweep in the command line's words (src/cli/sweep_options.cpp):
// --shard and --format parsed, and the errors of src/sweep, which name no
// option, told with its flag. Compiled into test_cli with that file.
#include <string>

#include <gtest/gtest.h>

#include "cli/sweep_options.hpp"

namespace pita::cli {
namespace {

TEST(SweepOptions, Shards) {
  EXPECT_EQ(parse_shard("2/5"), (std::pair{2, 5}));
  EXPECT_EQ(parse_shard("0/1"), (std::pair{0, 1}));
  for (const char* bad : {"5/5", "-1/3", "1", "1/0", "a/b", "1/2x", "1//2", " 1/2", "+1/2", "1/ 2", "/2", "1/"}) {
    EXPECT_THROW((void)parse_shard(bad), sweep::SweepUsageError) << bad;
  }
  try {
    (void)parse_shard("3/3");
    ADD_FAILURE() << "3/3 was accepted";
  } catch (const sweep::SweepUsageError& error) {
    EXPECT_EQ(sweep_error_message(error), "--shard 3/3: K must be in 0..N-1 and N >= 1 (got K = 3, N = 3)");
  }
}

TEST(SweepOptions, Formats) {
  EXPECT_EQ(parse_output_kinds("svg,csv,svg"), (std::vector{sweep::OutputKind::svg, sweep::OutputKind::csv}));
  EXPECT_EQ(parse_output_kinds("metrics"), (std::vector{sweep::OutputKind::metrics}));
  EXPECT_THROW((void)parse_output_kinds("svg,gif"), sweep::SweepUsageError);
  EXPECT_THROW((void)parse_output_kinds(""), sweep::SweepUsageError);
}

// src/sweep says what an error is about; the command line names the flag and
// the flag that would let it pass.
TEST(SweepOptions, ErrorsNameTheFlag) {
  const sweep::SweepUsageError vary(sweep::About{sweep::Input::vary, "/a=1:2"}, "SPEC must be a:b:n");
  EXPECT_EQ(std::string(vary.what()), "/a=1:2: SPEC must be a:b:n");
  EXPECT_EQ(sweep_error_message(vary), "--vary /a=1:2: SPEC must be a:b:n");
  EXPECT_EQ(sweep_error_message(sweep::SweepUsageError(sweep::About{sweep::Input::jobs}, "must be >= 1 (got 0)")),
            "--jobs: must be >= 1 (got 0)");
  EXPECT_EQ(sweep_error_message(
                sweep::SweepUsageError(sweep::About{sweep::Input::output, "out", sweep::Input::wait}, "busy")),
            "-o out: busy, or give --wait to wait for it");
  EXPECT_EQ(sweep_error_message(
                sweep::SweepUsageError(sweep::About{sweep::Input::output, "out", sweep::Input::force}, "stale")),
            "-o out: stale (or --force to start this sweep over there)");
  EXPECT_EQ(sweep_error_message(
                sweep::SweepUsageError(sweep::About{sweep::Input::merge, "dir", sweep::Input::shard}, "no parts")),
            "--merge dir: no parts (run the shards with --shard K/N -o dir first)");
  EXPECT_EQ(sweep_error_message(sweep::SweepUsageError("a base SCENE is required")), "a base SCENE is required");
  const sweep::SweepOutputError folder(sweep::About{sweep::Input::output, "mine"},
                                       "cannot write: not a sweep's folder");
  EXPECT_EQ(sweep_error_message(folder), "-o mine: cannot write: not a sweep's folder");
}

}  // namespace
}  // namespace pita::cli
