#include "analysis/sam3d_existence_report.hpp"

#include <cmath>
#include <cstddef>

#include <fmt/format.h>

namespace pita::analysis {

namespace {

std::string existence_matrix_text(const Eigen::Matrix3d& M) {
  return fmt::format("[[{:g}, {:g}, {:g}], [{:g}, {:g}, {:g}], [{:g}, {:g}, {:g}]]", M(0, 0), M(0, 1), M(0, 2), M(1, 0),
                     M(1, 1), M(1, 2), M(2, 0), M(2, 1), M(2, 2));
}

std::string no_sam_text(const NoSamConfiguration& c) {
  return fmt::format("axis [{:.4f}, {:.4f}, {:.4f}], angle {:.4f}, p {:g}, signs {}", c.axis.x(), c.axis.y(),
                     c.axis.z(), c.angle, c.p, existence_matrix_text(c.signs));
}

// Decimals of a p on the grid of `step`.
int safe_p_decimals(double step) { return step >= 0.01 ? 2 : 4; }

void tell_progress(const std::function<void(int)>& progress, double done) {
  if (progress) progress(static_cast<int>(done));
}

std::string existence_curve_table(const Sam3dExistenceReportRequest& r, std::size_t axes,
                                  const std::function<void(int)>& progress) {
  std::string text = fmt::format(
      "SAM existence in 3D (SAM paper Sec. 5.2): {} axes (icosahedron subdivided {} times), rotations by j pi/{}, "
      "3^9 perturbations each; for each theta, every angle up to it\n\n| theta | largest safe p |\n|---|---|\n",
      axes, r.search.subdivisions, *r.curve);
  const SafeCurve curve = largest_safe_perturbation_curve(
      *r.curve, r.search, [&](double fraction) { tell_progress(progress, 100.0 * fraction); });
  for (std::size_t k = 0; k < curve.thetas.size(); ++k) {
    text += fmt::format("| {}pi/{} ({:.4f}) | {:.{}f} |\n", k, *r.curve, curve.thetas[k], curve.largest_p[k],
                        safe_p_decimals(r.search.p_step));
  }
  return text;
}

std::string existence_single_p_table(const Sam3dExistenceReportRequest& r) {
  std::string text = "| theta | p | every configuration has a SAM | a configuration without one |\n|---|---|---|---|\n";
  for (std::size_t i = 0; i < r.thetas.size(); ++i) {
    const auto failure = find_no_sam(r.thetas[i], *r.p, r.search);
    text += fmt::format("| {} ({:.4f}) | {:g} | {} | {} |\n", r.theta_texts[i], r.thetas[i], *r.p,
                        failure ? "no" : "yes", failure ? no_sam_text(*failure) : "");
  }
  return text;
}

// The largest safe p at each theta, against the paper's bound where it states one.
std::string existence_bounds_table(const Sam3dExistenceReportRequest& r, const std::function<void(int)>& progress) {
  std::string text =
      "| theta | largest safe p (ours) | paper's bound | | fails one step above at |\n|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < r.thetas.size(); ++i) {
    const SafePerturbation safe = largest_safe_perturbation(r.thetas[i], r.search, [&](double fraction) {
      tell_progress(progress, 100.0 * (static_cast<double>(i) + fraction));
    });
    std::string paper = "(none stated)", verdict;
    for (const PaperExistenceBound& bound : paper_existence_bounds()) {
      if (std::abs(bound.theta - r.thetas[i]) > 1e-12) continue;
      paper = fmt::format("{:.2f}", bound.p);
      verdict =
          std::abs(bound.p - safe.largest_p) <= r.search.p_step + 1e-12 ? "agrees" : "differs: we keep our measurement";
    }
    text += fmt::format("| {} ({:.4f}) | {:.{}f} | {} | {} | {} |\n", r.theta_texts[i], r.thetas[i], safe.largest_p,
                        safe_p_decimals(r.search.p_step), paper, verdict,
                        safe.at_next ? no_sam_text(*safe.at_next) : "(none up to p = 1)");
  }
  return text;
}

}  // namespace

int sam3d_existence_report_units(const Sam3dExistenceReportRequest& request) {
  if (request.curve) return 100;
  return request.p ? 0 : static_cast<int>(request.thetas.size() * 100);
}

std::string sam3d_existence_report(const Sam3dExistenceReportRequest& request,
                                   const std::function<void(int done)>& progress) {
  const std::size_t axes = icosphere_axes(request.search.subdivisions).size();
  if (request.curve) return existence_curve_table(request, axes, progress);
  const std::string header = fmt::format(
      "SAM existence in 3D (SAM paper Sec. 5.2): {} axes (icosahedron subdivided {} times), {} angles over "
      "[-theta, theta], 3^9 perturbations each: {} matrices per (theta, p)\n\n",
      axes, request.search.subdivisions, request.search.angles,
      axes * static_cast<std::size_t>(request.search.angles) * 19683);
  return header + (request.p ? existence_single_p_table(request) : existence_bounds_table(request, progress));
}

}  // namespace pita::analysis
