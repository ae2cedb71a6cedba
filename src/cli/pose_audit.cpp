#include "cli/pose_audit.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <stdexcept>

#include <fmt/format.h>

#include "analysis/pose_audit.hpp"
#include "analysis/pose_audit_report.hpp"
#include "animate/progress.hpp"
#include "cli/audit.hpp"
#include "cli/environment.hpp"
#include "cli/failure.hpp"
#include "cli/usage_error.hpp"
#include "core/methods.hpp"
#include "io/output_file.hpp"
#include "render/figure.hpp"
#include "render/pose_audit_table.hpp"
#include "text/list.hpp"

namespace pita::cli {

namespace pose_audit_cli {

// --methods among the pose methods (the registry's names), each of both
// dimensions and through three poses.
std::vector<PoseMethod> parse_pose_methods(const std::string& list) {
  std::vector<PoseMethod> out;
  text::for_each_item(list, [&](std::string_view item) {
    std::string name(item);
    while (!name.empty() && name.front() == ' ') name.erase(name.begin());
    while (!name.empty() && name.back() == ' ') name.pop_back();
    if (name.empty()) {
      throw UsageError("--methods: an empty name (give comma-separated pose methods, e.g. P6,polySAM)");
    }
    const PoseMethod* method = find_method_of<PoseMethod>(name);
    if (method == nullptr) throw UsageError("--methods: " + unknown_method_reason(name, is_method_of<PoseMethod>));
    if (!analysis::pose_auditable(*method)) {
      throw UsageError(fmt::format(
          "--methods: {} is not measured: the pose audit takes the methods of both dimensions through three poses "
          "({})",
          method_label(entry_of(*method)), [] {
            std::string ids;
            for (const PoseMethodInfo& m : all_pose_methods()) {
              if (analysis::pose_auditable(m.method)) ids += (ids.empty() ? "" : ", ") + std::string(m.id);
            }
            return ids;
          }()));
    }
    if (std::find(out.begin(), out.end(), *method) == out.end()) out.push_back(*method);
  });
  return out;
}

analysis::PoseAuditOptions options_of(const PoseAuditCliOptions& options) {
  analysis::PoseAuditOptions audit;
  if (options.methods) audit.methods = parse_pose_methods(*options.methods);
  if (options.dimension) audit.dimensions = {*options.dimension};
  if (options.configs < 1 || options.configs > analysis::kMaxAuditConfigs) {
    throw UsageError(
        fmt::format("--configs: must be between 1 and {} (got {})", analysis::kMaxAuditConfigs, options.configs));
  }
  audit.configs = options.configs;
  try {
    audit.seed = parse_audit_seed(options.seed);
  } catch (const std::invalid_argument& error) {
    throw UsageError(error.what());
  }
  audit.jobs = options.jobs > 0 ? options.jobs : threads_from_environment();
  return audit;
}

constexpr const char* kPoseAuditFooter = R"(
What of the PITA paper's Fig. 10 carries over to affine poses: for each pose method
through three poses (default: polySAM, bezier-SAM, biarc-SAM, four-point-SAM, P4, P5,
P6, P9) in the plane and in space, over crafted triples and N random ones per dimension
(tame, wild and near-singular in turn, every pose with a positive determinant) drawn
from the seed: interpolation, symmetry under time reversal, left and right affine
invariance (G o A; A o H, a change of handle), knot control, steadiness (the SAM paper's
ARA: the median over the triples) and existence (the share of random triples with a
real motion over [a, c]). The output is the same for the same seed, whatever --jobs.
docs/reference/audit.md says what each number measures and why the other rows of
Fig. 10 (windings, pops, order) do not apply to poses.

Examples:
  pita audit poses
  pita audit poses --dimension 3 --methods P6,polySAM --configs 30
  pita audit poses --format json -o pose-audit.svg

Exit codes: 0 success, 2 bad usage (unknown or unmeasured method, --configs outside
1..1000000, a bad --seed, -o with another extension), 3 an output could not be written.)";

}  // namespace pose_audit_cli

std::shared_ptr<PoseAuditCliOptions> setup_pose_audit(CLI::App& audit) {
  auto options = std::make_shared<PoseAuditCliOptions>();
  CLI::App* command =
      audit.add_subcommand("poses", "What of Fig. 10 carries over to affine poses: the pose methods measured");
  options->command = command;
  command->footer(pose_audit_cli::kPoseAuditFooter);
  command
      ->add_option_function<int>(
          "--dimension", [options](int d) { options->dimension = d; }, "Only the plane (2) or space (3); default both")
      ->check(CLI::IsMember({2, 3}))
      ->type_name("D");
  command
      ->add_option_function<std::string>(
          "--methods", [options](const std::string& list) { options->methods = list; },
          "Comma-separated pose methods (default: those of both dimensions through three poses but linear)")
      ->type_name("LIST");
  command->add_option("--configs", options->configs, "Random triples per dimension (1 to 1000000)")
      ->type_name("N")
      ->capture_default_str();
  command->add_option("--seed", options->seed, "Seed of the random triples (an integer, 0 to 2^64 - 1)")
      ->type_name("S")
      ->capture_default_str();
  command->add_option("--jobs", options->jobs, "Threads (default: PITA_THREADS, else the number of cores)")
      ->type_name("J")
      ->check(CLI::Range(1, 1024));
  command->add_option("--format", options->format, "Format of the table on standard output")
      ->check(CLI::IsMember({"md", "csv", "json"}))
      ->type_name("FORMAT")
      ->capture_default_str();
  command
      ->add_option_function<std::string>(
          "-o,--output", [options](const std::string& path) { options->output = path; },
          "Draw the table as a figure (.svg, .png or .pdf)")
      ->type_name("TABLE");
  command->add_flag("-q,--quiet", options->quiet, "No progress bar");
  return options;
}

ExitCode run_pose_audit_command(const PoseAuditCliOptions& options) {
  namespace fs = std::filesystem;
  try {
    analysis::PoseAuditOptions audit = pose_audit_cli::options_of(options);
    std::optional<render::Format> table_format;
    if (options.output) {
      const std::string extension = fs::path(*options.output).extension().string();
      table_format = render::format_from_name(extension.empty() ? "" : extension.substr(1));
      if (!table_format) {
        throw UsageError(fmt::format("-o: {}: the table is drawn as .svg, .png or .pdf", *options.output));
      }
      const fs::path folder = fs::path(*options.output).parent_path();
      std::error_code error;
      if (!folder.empty() && !fs::is_directory(folder, error)) {
        std::cerr << "pita: -o: " << *options.output << ": the folder " << folder.string() << " does not exist\n";
        return ExitCode::failure;
      }
    }
    const analysis::AuditFormat format = options.format == "csv"    ? analysis::AuditFormat::csv
                                         : options.format == "json" ? analysis::AuditFormat::json
                                                                    : analysis::AuditFormat::md;
    const std::size_t cells =
        (options.dimension ? 1 : 2) *
        (audit.methods.empty() ? analysis::default_pose_audit_methods().size() : audit.methods.size()) *
        analysis::all_pose_properties().size();
    animate::Progress progress("audit poses", static_cast<int>(cells), progress_allowed(options.quiet));
    std::mutex progress_lock;
    audit.progress = [&](int done, int /*total*/) {
      const std::lock_guard<std::mutex> lock(progress_lock);
      progress.update(done);
    };
    const analysis::PoseAuditReport report = analysis::run_pose_audit(audit);
    if (table_format) {
      io::write_file_atomically(*options.output, render::render_pose_property_table(report, *table_format));
    }
    const std::string text = analysis::format_pose_audit(report, format);
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0) {
      std::cerr << "pita: cannot write the audit to standard output (" << std::strerror(errno) << ")\n";
      return ExitCode::failure;
    }
    return ExitCode::success;
  } catch (const UsageError& error) {
    std::cerr << "pita: audit poses: " << error.what() << '\n';
    return ExitCode::bad_input;
  } catch (...) {
    const Failure failure = current_failure("pita audit poses");
    std::cerr << "pita: " << failure.message << '\n';
    return failure.code;
  }
}

}  // namespace pita::cli
