#include "cli/sweep.hpp"

#include <iostream>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli/environment.hpp"
#include "cli/failure.hpp"
#include "cli/sweep_options.hpp"
#include "io/output_file.hpp"
#include "scene/scene.hpp"
#include "sweep/grid.hpp"
#include "sweep/sweep.hpp"

namespace pita::cli {

namespace {

// Failed variants listed one per line on stderr, at most this many (the
// manifest has them all).
constexpr std::size_t kMaxListed = 50;

std::string sweep_footer() {
  return R"(
SPEC is a:b:n (n values from a to b, both included), log:a:b:n (geometric), or a
list v1,v2,... of numbers or strings. Several --vary make every combination (the
last varies fastest); --zip pairs them value by value instead. A pointer may name
a field the scene does not have yet inside objects (/timing/ease), not a missing
array element.

Each variant is the scene with those values set, checked as a scene file is;
its title shows the values a "{/pointer}" of the title does not: "A house
carried by {/method}" reads "A house carried by P3", other values follow in
parentheses. An axis every value of which is refused (an option the method does
not read) is bad usage, and so is /method when every panel sets its own (unless
csv or json frames are asked for). DIR receives, for variant i:
<scene>-<i>.scene.json (the variant itself) and <scene>-<i>.<format> for each
--format (svg, png, pdf: the figure; csv, json: the frames pita eval prints;
metrics alone: no file per variant, for millions of variants), then manifest.csv
(a row per variant: the values, status, outputs, content hash and metrics of pita
measure for the figure's first panel), index.html (every variant in a paged
table, sortable by any column, its data in index/) and contact.svg / contact.png
(every figure on one picture, rows and columns for two parameters; above 256
variants, 256 of them evenly spaced).

Resumable: a variant whose outputs exist and whose manifest row has the same
content hash is skipped (--force redoes it). SIGINT or SIGTERM lets the running
variants finish, writes the manifest of what finished and exits 128 + signal.

DIR must be new, empty or a sweep's own folder (it has a .pita-sweep marker):
nothing of yours is replaced. One run at a time writes each manifest in DIR; a
second is refused (exit 2, naming the first one's PID) unless given --wait.

--shard K/N runs the variants i with i mod N = K and writes manifest.K-of-N.csv;
pita sweep --merge DIR joins the parts (in any order) and says which variants are
missing.
Recipes for Slurm and GNU parallel: docs/guide/cluster-sweeps.md.

Examples:
  pita sweep scenes/fig02-windings.json --vary /keyframes/1/t=0.1:0.9:9 -o sweep
  pita sweep scenes/fig02-windings.json --vary /method=P1,P4,P6 \
             --vary /keyframes/2/w=0:6:7 -o out --format svg,png
  pita sweep scene.json --vary /keyframes/1/m=log:0.1:10:50 --format csv -o m --jobs 2

Exit codes: 0 every variant written, 1 some variants failed (listed on stderr,
every other variant still written) or --merge found variants missing, 2 bad usage
or a bad base scene (nothing written), or another run writing DIR, 3 an output
could not be written or DIR holds files a sweep did not write.)";
}

// The run's notes, then how its shard joins the others.
void print_sweep_notes(const sweep::SweepSummary& summary, const sweep::SweepOptions& options) {
  for (const std::string& note : summary.notes) std::cerr << "pita: " << note << '\n';
  if (options.shard) {
    std::cerr << fmt::format("pita: shard {}/{}: join the shards with pita sweep --merge {}\n", options.shard->first,
                             options.shard->second, options.output);
  }
}

}  // namespace

std::shared_ptr<SweepCommand> setup_sweep(CLI::App& app) {
  auto command = std::make_shared<SweepCommand>();
  CLI::App* sweep = app.add_subcommand("sweep",
                                       "Run many variants of a scene: figures, frames, a manifest of metrics "
                                       "and a contact sheet");
  sweep->footer(sweep_footer());
  sweep
      ->add_option_function<std::string>(
          "SCENE", [command](const std::string& s) { command->scene_path = s; }, "The base scene file (JSON)")
      ->type_name("SCENE");
  sweep->add_option("--vary", command->vary, "POINTER=SPEC: the values to set at a JSON Pointer (repeatable)")
      ->type_name("POINTER=SPEC")
      ->allow_extra_args(false);
  sweep->add_flag("--zip", command->zip, "Pair the --vary lists value by value instead of every combination");
  sweep
      ->add_option_function<std::string>(
          "-o,--output", [command](const std::string& s) { command->output = s; },
          "The output folder DIR (created if needed)")
      ->type_name("DIR");
  sweep
      ->add_option("--format", command->formats,
                   "Outputs per variant, comma-separated: svg, png, pdf, csv, json; metrics: none, the manifest's "
                   "row only")
      ->type_name("LIST")
      ->capture_default_str();
  sweep
      ->add_option_function<int>(
          "--jobs,-j", [command](int j) { command->jobs = j; },
          "Variants run at once (default: PITA_THREADS, else the number of cores)")
      ->type_name("J");
  sweep
      ->add_option_function<std::string>(
          "--shard", [command](const std::string& s) { command->shard = s; },
          "Run only the variants i with i mod N = K; writes manifest.K-of-N.csv")
      ->type_name("K/N");
  sweep
      ->add_option_function<std::string>(
          "--merge", [command](const std::string& s) { command->merge = s; },
          "Join the shards' manifests in DIR into manifest.csv, index.html, contact.*")
      ->type_name("DIR");
  sweep->add_flag("--force", command->force, "Redo variants that a previous run finished");
  sweep->add_flag("--wait", command->wait,
                  "When another sweep is writing the same manifest in DIR, wait for it instead of exiting 2");
  sweep->add_flag("-q,--quiet", command->quiet, "No progress");
  return command;
}

ExitCode run_sweep_command(const SweepCommand& command) {
  try {
    if (command.merge) {
      if (command.scene_path || !command.vary.empty() || command.output || command.shard || command.zip ||
          command.jobs || command.force || command.formats != "svg") {
        throw sweep::SweepUsageError(
            "--merge DIR takes no scene, --vary, --zip, -o, --format, --jobs, --shard or "
            "--force: the shards' folder holds the sweep's definition");
      }
      const sweep::MergeSummary merged = sweep::merge_sweep(*command.merge, command.wait);
      if (!command.quiet) {
        for (const std::string& note : merged.notes) std::cerr << "pita: " << note << '\n';
      }
      std::cout << fmt::format("merged {} ({} rows of {} variants, {} failed) into {}/manifest.csv\n",
                               fmt::join(merged.parts, ", "), merged.rows, merged.variants, merged.failed,
                               *command.merge);
      if (merged.missing_count > 0) {
        std::cerr << fmt::format(
            "pita: {} variant{} missing: {}{} (run their shards again)\n", merged.missing_count,
            merged.missing_count == 1 ? "" : "s", sweep::index_ranges(merged.missing),
            merged.missing.size() < static_cast<std::size_t>(merged.missing_count) && merged.missing.size() >= 1000
                ? ", ..."
                : "");
        if (!merged.missing_shards.empty()) {
          std::string shards;
          for (const auto& [k, count] : merged.missing_shards) {
            const std::int64_t of = (merged.variants - k + merged.shards - 1) / merged.shards;
            shards += fmt::format("{}shard {}/{} ({} of {})", shards.empty() ? "" : ", ", k, merged.shards, count, of);
          }
          std::cerr << fmt::format("pita: the shards with variants missing: {}{}\n", shards,
                                   merged.missing_shards.size() >= 1000 ? ", ..." : "");
        }
        return ExitCode::golden_mismatch;
      }
      return merged.failed > 0 ? ExitCode::golden_mismatch : ExitCode::success;
    }
    if (!command.scene_path) throw sweep::SweepUsageError("a base SCENE is required (or --merge DIR)");
    if (command.vary.empty()) throw sweep::SweepUsageError("give at least one --vary POINTER=SPEC");
    if (!command.output) throw sweep::SweepUsageError("-o DIR is required: the folder that receives the variants");
    sweep::SweepOptions options;
    options.scene_path = *command.scene_path;
    options.vary = command.vary;
    options.zip = command.zip;
    options.output = *command.output;
    options.formats = parse_output_kinds(command.formats);
    options.jobs = command.jobs.value_or(threads_from_environment());
    if (command.shard) options.shard = parse_shard(*command.shard);
    options.force = command.force;
    options.wait = command.wait;
    options.progress = progress_allowed(command.quiet);
    options.version = PITA_VERSION;
    const sweep::SweepSummary summary = sweep::run_sweep(options);
    for (std::size_t i = 0; i < summary.failures.size() && i < kMaxListed; ++i) {
      std::cerr << "pita: " << printable_text(summary.failures[i]) << '\n';
    }
    if (summary.failed > static_cast<std::int64_t>(kMaxListed)) {
      std::cerr << fmt::format("pita: ... and {} more failed variants (manifest.csv lists them all)\n",
                               summary.failed - static_cast<std::int64_t>(kMaxListed));
    }
    if (!command.quiet) print_sweep_notes(summary, options);
    std::cout << fmt::format("{} variants: {} written, {} resumed, {} failed; see {}/{}\n", summary.variants,
                             summary.ok, summary.skipped, summary.failed, options.output,
                             options.shard
                                 ? fmt::format("manifest.{}-of-{}.csv", options.shard->first, options.shard->second)
                                 : "manifest.csv");
    if (summary.write_failed) return ExitCode::failure;
    return summary.failed > 0 ? ExitCode::golden_mismatch : ExitCode::success;
  } catch (const sweep::SweepUsageError& error) {
    std::cerr << "pita: " << printable_text(sweep_error_message(error)) << '\n';
    return ExitCode::bad_input;
  } catch (const sweep::SweepOutputError& error) {
    std::cerr << "pita: " << printable_text(sweep_error_message(error)) << '\n';
    return ExitCode::failure;
  } catch (...) {
    const Failure failure = current_failure(command.merge.value_or(command.scene_path.value_or("sweep")));
    std::cerr << "pita: " << failure.message << '\n';
    return failure.code;
  }
}

}  // namespace pita::cli
