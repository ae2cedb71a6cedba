#include "cli/audit.hpp"

#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <system_error>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "analysis/audit.hpp"
#include "analysis/audit_report.hpp"
#include "animate/progress.hpp"
#include "cli/environment.hpp"
#include "cli/failure.hpp"
#include "cli/usage_error.hpp"
#include "core/methods.hpp"
#include "io/output_file.hpp"
#include "render/audit_table.hpp"
#include "render/figure.hpp"
#include "scene/scene.hpp"
#include "text/list.hpp"

namespace pita::cli {

namespace {

std::vector<Method> parse_methods(const std::string& list) {
  std::vector<Method> out;
  text::for_each_item(list, [&](std::string_view item) {
    std::string name(item);
    while (!name.empty() && name.front() == ' ') name.erase(name.begin());
    while (!name.empty() && name.back() == ' ') name.pop_back();
    if (name.empty()) throw UsageError("--methods: an empty name (give comma-separated methods, e.g. P1,P6,P8)");
    const MethodEntry* entry = find_method_entry(name, is_method_of<Method>);
    if (entry == nullptr) throw UsageError("--methods: " + unknown_method_reason(name, is_method_of<Method>));
    if (entry->min_count != 3) {
      throw UsageError(
          fmt::format("--methods: {} takes {} keyframes; the properties of Sec. 4 are defined for the "
                      "methods through three",
                      method_label(*entry), entry->min_count));
    }
    const Method method = std::get<Method>(entry->method);  // the filter kept arrow methods only
    if (std::find(out.begin(), out.end(), method) == out.end()) out.push_back(method);
  });
  return out;
}

constexpr const char* kAuditFooter = R"(
Measures, for each method and each property of the PITA paper's Sec. 4 (its Fig. 10),
the worst value over the crafted edge cases and N random configurations (tame, wild and
near-singular in turn) drawn from the seed, and says whether the property holds. The
output is the same for the same seed, whatever --jobs. docs/reference/audit.md says
what each number measures.

--counterexamples DIR writes, for each cell that fails, DIR/<method>-<property>.json, a
scene whose panel 0 is the configuration and panel 1 its transformed, swapped or tweaked
counterpart (replay: pita eval FILE --t T and pita eval FILE --panel 1 --t T), and
DIR/<method>-<property>.svg, the two drawn side by side.
-o TABLE.svg|png|pdf draws the table in the layout of Fig. 10.

Examples:
  pita audit
  pita audit --methods P1,P6,P8 --configs 50 --format json
  pita audit --seed 7 --counterexamples cx -o fig10.svg

Exit codes: 0 success, 2 bad usage (unknown method, --configs outside 1..1000000, a
folder that cannot be created), 3 an output could not be written.
)";

}  // namespace

std::uint64_t parse_audit_seed(const std::string& text) {
  std::uint64_t seed = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), seed);
  if (text.empty() || error != std::errc{} || end != text.data() + text.size()) {
    throw std::invalid_argument(fmt::format("--seed: must be an integer from 0 to {} (got \"{}\")",
                                            std::numeric_limits<std::uint64_t>::max(), text));
  }
  return seed;
}

std::shared_ptr<AuditCliOptions> setup_audit(CLI::App& app) {
  auto options = std::make_shared<AuditCliOptions>();
  CLI::App* audit = app.add_subcommand("audit", "Measure the properties of Sec. 4 (Fig. 10) for every method");
  audit->footer(kAuditFooter);
  audit
      ->add_option_function<std::string>(
          "--methods", [options](const std::string& list) { options->methods = list; },
          "Comma-separated methods (default: every arrow method through three keyframes)")
      ->type_name("LIST");
  audit->add_option("--configs", options->configs, "Random configurations per cell (1 to 1000000)")
      ->type_name("N")
      ->capture_default_str();
  audit->add_option("--seed", options->seed, "Seed of the random configurations (an integer, 0 to 2^64 - 1)")
      ->type_name("S")
      ->capture_default_str();
  audit->add_option("--jobs", options->jobs, "Threads (default: PITA_THREADS, else the number of cores)")
      ->type_name("J")
      ->check(CLI::Range(1, 1024));
  audit->add_option("--format", options->format, "Format of the table on standard output")
      ->check(CLI::IsMember({"md", "csv", "json"}))
      ->type_name("FORMAT")
      ->capture_default_str();
  audit
      ->add_option_function<std::string>(
          "--counterexamples", [options](const std::string& dir) { options->counterexamples = dir; },
          "Write a scene and a figure for each cell that fails into this folder")
      ->type_name("DIR");
  audit
      ->add_option_function<std::string>(
          "-o,--output", [options](const std::string& path) { options->output = path; },
          "Draw the table as a figure (.svg, .png or .pdf)")
      ->type_name("TABLE");
  audit->add_flag("-q,--quiet", options->quiet, "No progress bar");
  return options;
}

namespace {

// --seed: an unsigned 64-bit integer. Throws UsageError.
std::uint64_t parse_seed(const std::string& text) {
  try {
    return parse_audit_seed(text);
  } catch (const std::invalid_argument& error) {
    throw UsageError(error.what());
  }
}

// --counterexamples: each failed cell's scene and its figure into `folder`,
// as a pair (both or neither); the scene's path per cell ("" for none).
std::vector<std::string> write_counterexamples(const analysis::AuditReport& report, const std::string& folder) {
  namespace fs = std::filesystem;
  std::vector<std::string> files(report.cells.size());
  for (std::size_t i = 0; i < report.cells.size(); ++i) {
    const std::string scene = analysis::counterexample_scene(report, report.cells[i]);
    if (scene.empty()) continue;
    const fs::path json = fs::path(folder) / analysis::counterexample_name(report.cells[i]);
    files[i] = json.string();
    // The scene must read back as a scene: the figure is drawn from it.
    const scene::Scene parsed = scene::parse_scene(scene, json.string());
    const render::Figure figure = render::build_figure(parsed);
    fs::path svg = json;
    svg.replace_extension(".svg");
    const std::vector<std::pair<fs::path, std::string>> pair = {
        {json, scene}, {svg, render::render_figure(parsed, figure, render::Format::svg)}};
    io::write_files_atomically(pair);
  }
  return files;
}

// The audit the options ask for: its methods, configurations, seed and threads.
analysis::AuditOptions audit_options_of(const AuditCliOptions& options) {
  analysis::AuditOptions audit;
  if (options.methods) audit.methods = parse_methods(*options.methods);
  if (options.configs < 1 || options.configs > analysis::kMaxAuditConfigs) {
    throw UsageError(
        fmt::format("--configs: must be between 1 and {} (got {})", analysis::kMaxAuditConfigs, options.configs));
  }
  audit.configs = options.configs;
  audit.seed = parse_seed(options.seed);
  audit.jobs = options.jobs > 0 ? options.jobs : threads_from_environment();
  return audit;
}

// The folder of --counterexamples, made (UsageError when it cannot be, or
// when -o names it: the table is a file, the counterexamples a folder; -o
// inside it is fine).
void make_counterexample_folder(const AuditCliOptions& options) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (options.output &&
      (fs::path(*options.output).lexically_normal() == fs::path(*options.counterexamples).lexically_normal() ||
       fs::equivalent(*options.output, *options.counterexamples, error))) {
    throw UsageError(
        fmt::format("-o {} and --counterexamples {} name the same path: the table is a file, the "
                    "counterexamples a folder; give two different paths",
                    *options.output, *options.counterexamples));
  }
  fs::create_directories(*options.counterexamples, error);
  if (error || !fs::is_directory(*options.counterexamples)) {
    throw UsageError(fmt::format("--counterexamples: cannot create the folder {} ({})", *options.counterexamples,
                                 error ? error.message() : "a file is in the way"));
  }
}

}  // namespace

ExitCode run_audit_command(const AuditCliOptions& options) {
  namespace fs = std::filesystem;
  try {
    analysis::AuditOptions audit = audit_options_of(options);
    std::optional<render::Format> table_format;
    if (options.output) {
      const std::string extension = fs::path(*options.output).extension().string();
      table_format = render::format_from_name(extension.empty() ? "" : extension.substr(1));
      if (!table_format) {
        throw UsageError(fmt::format("-o: {}: the table is drawn as .svg, .png or .pdf", *options.output));
      }
    }
    // Where the table goes must exist before the work starts (exit 3 else).
    if (options.output) {
      const fs::path folder = fs::path(*options.output).parent_path();
      std::error_code error;
      if (!folder.empty() && !fs::is_directory(folder, error)) {
        std::cerr << "pita: -o: " << *options.output << ": the folder " << folder.string() << " does not exist\n";
        return ExitCode::failure;
      }
    }
    // The counterexample folder is made before the work, so that a folder
    // that cannot be made costs nothing (and nothing is written).
    if (options.counterexamples) make_counterexample_folder(options);
    const analysis::AuditFormat format = options.format == "csv"    ? analysis::AuditFormat::csv
                                         : options.format == "json" ? analysis::AuditFormat::json
                                                                    : analysis::AuditFormat::md;
    const std::size_t methods = audit.methods.empty() ? analysis::default_audit_methods().size() : audit.methods.size();
    animate::Progress progress("audit", static_cast<int>(methods * analysis::all_properties().size()), !options.quiet);
    std::mutex progress_lock;
    audit.progress = [&](int done, int /*total*/) {
      const std::lock_guard<std::mutex> lock(progress_lock);
      progress.update(done);
    };
    const analysis::AuditReport report = analysis::run_audit(audit);

    if (table_format) {
      io::write_file_atomically(*options.output, render::render_property_table(report, *table_format));
    }
    const std::vector<std::string> files = options.counterexamples
                                               ? write_counterexamples(report, *options.counterexamples)
                                               : std::vector<std::string>(report.cells.size());
    const std::string text = analysis::format_audit(report, format, files);
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0) {
      std::cerr << "pita: cannot write the audit to standard output (" << std::strerror(errno) << ")\n";
      return ExitCode::failure;
    }
    return ExitCode::success;
  } catch (const UsageError& error) {
    std::cerr << "pita: " << error.what() << '\n';
    return ExitCode::bad_input;
  } catch (...) {
    const Failure failure = current_failure("pita audit");
    std::cerr << "pita: " << failure.message << '\n';
    return failure.code;
  }
}

}  // namespace pita::cli
