// The table of `pita audit sam3d-existence` (SAM Sec. 5.2; docs/paper-notes.md
// N59), as Markdown: the largest safe perturbation p for each theta beside the
// paper's stated bound, whether one p is safe, or the figure's curve. The
// command line resolves the options and prints it (cli/sam3d_existence.cpp).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "analysis/sam3d_existence.hpp"

namespace pita::analysis {

struct Sam3dExistenceReportRequest {
  Sam3dExistenceOptions search;
  // The angles theta, in radians and as the user wrote them ("2pi/3").
  std::vector<double> thetas;
  std::vector<std::string> theta_texts;
  std::optional<double> p;   // check only this p at each theta
  std::optional<int> curve;  // instead: the curve at theta = k pi/N, k = 0..N
};

// The units of progress the report counts (100 per theta searched, 100 for
// the curve); 0 when it reports none (a single p).
int sam3d_existence_report_units(const Sam3dExistenceReportRequest& request);

// The report: a header naming the experiment's size, then the table.
// `progress` is told the units done (of sam3d_existence_report_units).
std::string sam3d_existence_report(const Sam3dExistenceReportRequest& request,
                                   const std::function<void(int done)>& progress = {});

}  // namespace pita::analysis
