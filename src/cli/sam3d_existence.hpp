// pita audit sam3d-existence: the SAM paper's Sec. 5.2 experiment in 3D
// (analysis/sam3d_existence.hpp); a thin front end over the analysis.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/exit_code.hpp"

namespace pita::cli {

struct Sam3dExistenceCliOptions {
  CLI::App* command = nullptr;  // parsed() tells whether it was given
  int subdivisions = 2;
  int angles = 17;
  std::optional<std::string> theta;  // as typed: "pi/2", "2pi/3", "1.2"
  std::optional<double> p;
  double step = 0.01;
  std::optional<int> curve;  // the figure's curve at k pi / curve instead
  int jobs = 0;
  double budget = 1.0;  // times analysis::kExistenceWorkBudget
  bool quiet = false;
};

// Adds the subcommand under `audit`.
std::shared_ptr<Sam3dExistenceCliOptions> setup_sam3d_existence(CLI::App& audit);
ExitCode run_sam3d_existence(const Sam3dExistenceCliOptions& options);

// "pi/2", "2pi/3", "pi", "-pi/4", "1.25": an angle in radians. Throws
// std::invalid_argument naming what is wrong.
double parse_angle(const std::string& text);

}  // namespace pita::cli
