// PITA Fig. 10 as the paper prints it, for P1-P8, and our reading of each row
// (docs/paper-notes.md N8, N36): `pita audit` sets its measurements beside it
// and lists where they disagree, with the reason.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "analysis/audit.hpp"

namespace pita::analysis {

struct PrintedRow {
  Property property;
  std::vector<Method> printed;  // the PITAs the paper says have it (of P1-P8)
  std::string_view source;      // where: "Fig. 10 row H", "Sec. 4.3 text"
  // Why a measurement may differ from the print: the reading notes'
  // correction, or what the measurement shows.
  std::string_view reason;
  // Reasons that concern one method only (they replace `reason` for it).
  std::vector<std::pair<Method, std::string_view>> method_reasons = {};
};

// One row per property (the order of all_properties()).
const std::vector<PrintedRow>& printed_table();

// Whether the paper says `method` has `property`; nullopt for methods the
// table does not list (P5S, P9, P10, the independent combinations).
std::optional<bool> printed(Method method, Property property);

struct Disagreement {
  Method method;
  Property property;
  bool printed = false;
  bool measured = false;
  std::string reason;
};

// The cells of the report where the measurement disagrees with the print.
std::vector<Disagreement> disagreements(const AuditReport& report);

}  // namespace pita::analysis
