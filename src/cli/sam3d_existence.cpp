#include "cli/sam3d_existence.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "analysis/sam3d_existence.hpp"
#include "analysis/sam3d_existence_report.hpp"
#include "animate/progress.hpp"
#include "cli/environment.hpp"
#include "cli/failure.hpp"

namespace pita::cli {

namespace {

constexpr const char* kExistenceFooter = R"(
The SAM paper's Sec. 5.2 experiment: axes through the vertices of an icosahedron
subdivided --subdivisions times (one per antipodal pair: 81 for 2); for each, rotations
by --angles angles evenly spaced over [-theta, theta]; every entry of their matrix L
perturbed by -p, 0 or +p in all 3^9 combinations; does every such L have a real
logarithm (a SAM; Culver's condition)? For each theta, the largest p (on a grid of
--step) for which it does, found by bisection, beside the paper's stated bound, and one
configuration without a SAM one step above. Without --theta, the paper's three angles.
With --p, only that p is checked. With --curve N, the curve of the figure
scenes/sam-fig06-existence-3d.json instead: for theta = k pi/N, k = 0..N, the largest p
for which every rotation by j pi/N, |j| <= k, perturbed, has a SAM.

Examples:
  pita audit sam3d-existence
  pita audit sam3d-existence --theta 2pi/3 --angles 33
  pita audit sam3d-existence --theta pi/2 --p 0.3
  pita audit sam3d-existence --curve 12

Exit codes: 0 success (whatever the bounds are), 2 bad usage.)";

}  // namespace

double parse_angle(const std::string& text) {
  const auto fail = [&text]() -> double {
    throw std::invalid_argument(
        fmt::format("\"{}\" is not an angle (radians, or a multiple of pi such as 2pi/3)", text));
  };
  // The whole of `part` as a finite real.
  const auto real = [&fail](std::string_view part) {
    const std::string digits(part);
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(digits, &used);
    } catch (const std::exception&) {
      return fail();
    }
    return used == digits.size() && std::isfinite(value) ? value : fail();
  };
  std::string_view s = text;
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  if (s.empty()) return fail();
  const std::size_t pi = s.find("pi");
  if (pi == std::string_view::npos) return real(s);
  const std::string_view prefix = s.substr(0, pi), rest = s.substr(pi + 2);
  const double factor = prefix.empty() ? 1.0 : prefix == "-" ? -1.0 : real(prefix);
  double divisor = 1.0;
  if (!rest.empty()) {
    if (rest.front() != '/') return fail();
    divisor = real(rest.substr(1));
    if (!(divisor > 0.0)) return fail();
  }
  return factor * std::numbers::pi / divisor;
}

std::shared_ptr<Sam3dExistenceCliOptions> setup_sam3d_existence(CLI::App& audit) {
  auto options = std::make_shared<Sam3dExistenceCliOptions>();
  CLI::App* command = audit.add_subcommand(
      "sam3d-existence", "Where a SAM exists in 3D: the largest safe perturbation p against theta (SAM Sec. 5.2)");
  options->command = command;
  command->footer(kExistenceFooter);
  command->add_option("--subdivisions", options->subdivisions, "Subdivisions of the icosahedron")
      ->check(CLI::Range(0, analysis::kMaxExistenceSubdivisions))
      ->type_name("N")
      ->capture_default_str();
  command->add_option("--angles", options->angles, "Rotation angles per axis over [-theta, theta]")
      ->check(CLI::Range(1, analysis::kMaxExistenceAngles))
      ->type_name("N")
      ->capture_default_str();
  command
      ->add_option_function<std::string>(
          "--theta", [options](const std::string& text) { options->theta = text; },
          "The largest rotation angle (radians, or 2pi/3, pi/2, ...); default: the paper's three")
      ->type_name("T");
  command
      ->add_option_function<double>(
          "--p", [options](double p) { options->p = p; }, "Check only this perturbation")
      ->check(CLI::Range(0.0, 10.0))
      ->type_name("P");
  command->add_option("--step", options->step, "The grid of p searched")
      ->check(CLI::Range(1e-4, 1.0))
      ->type_name("S")
      ->capture_default_str();
  command
      ->add_option_function<int>(
          "--curve", [options](int steps) { options->curve = steps; },
          "The largest safe p at theta = k pi/N, k = 0..N (the figure's curve)")
      ->check(CLI::Range(1, analysis::kMaxExistenceCurveSteps))
      ->type_name("N")
      ->excludes("--theta")
      ->excludes("--p")
      ->excludes("--angles");
  command->add_option("--jobs", options->jobs, "Threads (default: PITA_THREADS, else the number of cores)")
      ->check(CLI::Range(1, 1024))
      ->type_name("J");
  command->add_option("--budget", options->budget, "Allow F times the default work (matrices checked)")
      ->check(CLI::Range(1e-3, 1e3))
      ->type_name("F")
      ->capture_default_str();
  command->add_flag("-q,--quiet", options->quiet, "No progress bar");
  return options;
}

ExitCode run_sam3d_existence(const Sam3dExistenceCliOptions& options) {
  std::vector<double> thetas;
  std::vector<std::string> theta_texts;
  if (options.theta) {
    double theta = 0.0;
    try {
      theta = parse_angle(*options.theta);
    } catch (const std::invalid_argument& error) {
      std::cerr << "pita: audit sam3d-existence: --theta: " << error.what() << '\n';
      return ExitCode::bad_input;
    }
    if (!(theta >= 0.0 && theta <= std::numbers::pi)) {
      std::cerr << "pita: audit sam3d-existence: --theta: must be between 0 and pi (got " << *options.theta << ")\n";
      return ExitCode::bad_input;
    }
    thetas.push_back(theta);
    theta_texts.push_back(*options.theta);
  } else {
    for (const analysis::PaperExistenceBound& bound : analysis::paper_existence_bounds()) {
      thetas.push_back(bound.theta);
      theta_texts.emplace_back(bound.theta_text);
    }
  }
  analysis::Sam3dExistenceOptions search;
  search.subdivisions = options.subdivisions;
  search.angles = options.angles;
  search.p_step = options.step;
  search.jobs = static_cast<unsigned>(options.jobs > 0 ? options.jobs : threads_from_environment());
  const std::size_t axes = analysis::icosphere_axes(search.subdivisions).size();
  // The work bound, refused before it starts: within the documented ranges
  // --subdivisions 4 --angles 1001 would run for many minutes.
  const double work =
      static_cast<double>(options.curve ? analysis::existence_curve_work(*options.curve, search)
                                        : analysis::existence_work(search, thetas.size(), options.p.has_value()));
  if (work > analysis::kExistenceWorkBudget * options.budget) {
    std::cerr << fmt::format(
        "pita: audit sam3d-existence: this run would check up to {:.3g} matrices ({} axes, {} "
        "angles, 3^9 perturbations, per test), above the budget of {:.3g}: lower "
        "--subdivisions, --angles or --curve, or raise the budget with --budget F\n",
        work, axes, options.curve ? 1 : search.angles, analysis::kExistenceWorkBudget * options.budget);
    return ExitCode::bad_input;
  }
  const auto start = std::chrono::steady_clock::now();
  analysis::Sam3dExistenceReportRequest request{search, thetas, theta_texts, options.p, options.curve};
  std::string text;
  {
    std::optional<animate::Progress> progress;
    if (const int units = analysis::sam3d_existence_report_units(request); units > 0) {
      progress.emplace("sam3d-existence", units, progress_allowed(options.quiet));
    }
    text = analysis::sam3d_existence_report(request, [&](int done) {
      if (progress) progress->update(done);
    });
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0) {
    std::cerr << "pita: cannot write the table to standard output\n";
    return ExitCode::failure;
  }
  std::cerr << fmt::format("pita: audit sam3d-existence took {:.1f} s\n", seconds);
  return ExitCode::success;
}

}  // namespace pita::cli
