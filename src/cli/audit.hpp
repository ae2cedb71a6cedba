// pita audit [--methods LIST] [--configs N] [--seed S] [--jobs J] [--format md|csv|json]
//            [--counterexamples DIR] [-o TABLE.svg|png|pdf] [--quiet]
//
// PITA Fig. 10 measured (docs/reference/audit.md "pita audit"): analysis/audit.hpp does the
// work, analysis/audit_report.hpp the text, render/audit_table.hpp the figure.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "cli/exit_code.hpp"

namespace CLI {
class App;
}

namespace pita::cli {

struct AuditCliOptions {
  std::optional<std::string> methods;  // comma-separated names, as typed
  int configs = 200;
  std::string seed = "1";  // as typed; 0 to 2^64 - 1
  int jobs = 0;
  std::string format = "md";
  std::optional<std::string> counterexamples;
  std::optional<std::string> output;
  bool quiet = false;
};

std::shared_ptr<AuditCliOptions> setup_audit(CLI::App& app);
ExitCode run_audit_command(const AuditCliOptions& options);

// --seed of the audits: an integer from 0 to 2^64 - 1. Throws
// std::invalid_argument ("--seed: must be an integer ...").
std::uint64_t parse_audit_seed(const std::string& text);

}  // namespace pita::cli
