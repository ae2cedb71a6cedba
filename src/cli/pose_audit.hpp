// pita audit poses [--dimension 2|3] [--methods LIST] [--configs N] [--seed S] [--jobs J]
//                  [--format md|csv|json] [-o TABLE.svg|png|pdf] [-q]
//
// What of Fig. 10 carries over to affine poses, measured (docs/reference/audit.md "What
// carries over to affine poses"): analysis/pose_audit.hpp does the work, analysis/pose_audit_report.hpp the text,
// render/pose_audit_table.hpp the figure.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/exit_code.hpp"

namespace pita::cli {

struct PoseAuditCliOptions {
  CLI::App* command = nullptr;         // parsed() tells whether it was given
  std::optional<int> dimension;        // 2 or 3; both when absent
  std::optional<std::string> methods;  // comma-separated names, as typed
  int configs = 200;
  std::string seed = "1";
  int jobs = 0;
  std::string format = "md";
  std::optional<std::string> output;
  bool quiet = false;
};

// Adds the subcommand under `audit`.
std::shared_ptr<PoseAuditCliOptions> setup_pose_audit(CLI::App& audit);
ExitCode run_pose_audit_command(const PoseAuditCliOptions& options);

}  // namespace pita::cli
