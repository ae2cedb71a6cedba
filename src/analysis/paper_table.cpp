#include "analysis/paper_table.hpp"

#include <algorithm>

namespace pita::analysis {

namespace {
const std::vector<Method> kPrintedPitas{Method::P1, Method::P2, Method::P3, Method::P4,
                                        Method::P5, Method::P6, Method::P7, Method::P8};
}  // namespace

const std::vector<PrintedRow>& printed_table() {
  static const std::vector<PrintedRow> rows{
      {Property::exists, kPrintedPitas, "Sec. 4.1 (all chosen PITAs)",
       "the paper excepts isolated singular cases; so do we (branch cuts are measured by pop-free only)"},
      {Property::smooth,
       kPrintedPitas,
       "Sec. 4.2 (all chosen PITAs are infinitely differentiable)",
       "measured: the second derivative jumps at a time inside (a, c)",
       {{Method::P4, "P4 joins two Bezier halves at b, C1 but not C2 there (PITA Eq. 27-29, notes N3)"},
        {Method::P7,
         "with uneven knots the knot warp that P7 needs (the construction assumes even knots) is only C1 at b "
         "(notes N17)"},
        {Method::P8,
         "with uneven knots the knot warp that P8 needs (the construction assumes even knots) is only C1 at b "
         "(notes N17)"}}},
      {Property::similarity_invariant, kPrintedPitas, "Sec. 4.3 (all chosen PITAs)",
       "P5 built as appendix C says is translation-invariant only: the blend of matrix logs does not commute with "
       "rotations or dilations (notes N7); P5S is the similarity-invariant variant"},
      {Property::symmetric, kPrintedPitas, "Sec. 4.4 (all chosen PITAs)", ""},
      {Property::handle_invariant,
       {Method::P1, Method::P2, Method::P6, Method::P7, Method::P8},
       "Fig. 10 row H: 12678",
       "row H contradicts Sec. 4.5 (all except P2, P3, P5) and the table's own per-PITA column, which give "
       "1 4 6 7 8 (reading notes item 8, notes N8)"},
      {Property::winding_aware,
       {Method::P2, Method::P3, Method::P6},
       "Fig. 10 row W: 236",
       "P4 is made of winding-aware steady morphs and Sec. 5 says it makes BiSAM winding-aware; row W omits it "
       "(notes N8)"},
      {Property::pop_free,
       {Method::P1, Method::P3, Method::P4, Method::P6},
       "Fig. 10 row P: 1346 (Sec. 4.7 text says \"except P278\")",
       "the text's \"except P278\" omits P5, whose principal logs pop as Fig. 12 shows; the row is right (notes N8)"},
      {Property::knot_controlled, {Method::P1, Method::P3, Method::P5, Method::P6}, "Fig. 10 row K: 1356", ""},
      {Property::order_independent, {Method::P1, Method::P3, Method::P5}, "Fig. 10 row O: 135", ""},
      {Property::affine_invariant,
       {Method::P1, Method::P8},
       "Fig. 10 row A: 18",
       "P8 is affine-invariant only when the affinity also moves the tips of its key triangles (Sec. 4.10); on "
       "arrows, as measured here, it is not (notes N8)"},
      {Property::globally_perseverant, {Method::P1}, "Sec. 3.3 text (P1 is globally perseverant)", ""},
      {Property::radially_perseverant,
       {Method::P7},
       "Sec. 3.3 text (P7 is radially perseverant)",
       "P1 is radially perseverant too: global perseverance is the radial kind with the fixed point at infinity "
       "(Sec. 4.11; the least-squares fit finds K = 0)"},
      {Property::locally_perseverant,
       {Method::P1, Method::P8},
       "Fig. 10 row L: 18",
       "row L lumps the three kinds of Sec. 3.3 together: P1 is globally perseverant, P8 locally (notes N8)"},
  };
  return rows;
}

std::optional<bool> printed(Method method, Property property) {
  if (std::find(kPrintedPitas.begin(), kPrintedPitas.end(), method) == kPrintedPitas.end()) return std::nullopt;
  for (const PrintedRow& row : printed_table()) {
    if (row.property == property) {
      return std::find(row.printed.begin(), row.printed.end(), method) != row.printed.end();
    }
  }
  return std::nullopt;
}

std::vector<Disagreement> disagreements(const AuditReport& report) {
  std::vector<Disagreement> out;
  for (const AuditCell& cell : report.cells) {
    const std::optional<bool> said = printed(cell.method, cell.property);
    if (!said || *said == cell.holds) continue;
    std::string reason;
    for (const PrintedRow& row : printed_table()) {
      if (row.property != cell.property) continue;
      reason = row.reason;
      for (const auto& [method, why] : row.method_reasons) {
        if (method == cell.method) reason = why;
      }
    }
    if (reason.empty()) reason = "not explained by the reading notes: see the counterexample";
    out.push_back({cell.method, cell.property, *said, cell.holds, reason});
  }
  return out;
}

}  // namespace pita::analysis
