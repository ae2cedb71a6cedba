#include <gtest/gtest.h>

#include "analysis/paper_table.hpp"

namespace pita::analysis {
namespace {

TEST(PaperTable, RowsAsFigureTenPrintsThem) {
  // PITA Fig. 10: H 12678, W 236, P 1346, K 1356, O 135, A 18, L 18.
  EXPECT_TRUE(*printed(Method::P2, Property::handle_invariant));
  EXPECT_FALSE(*printed(Method::P4, Property::handle_invariant));
  EXPECT_FALSE(*printed(Method::P4, Property::winding_aware));
  EXPECT_TRUE(*printed(Method::P4, Property::pop_free));
  EXPECT_TRUE(*printed(Method::P5, Property::knot_controlled));
  EXPECT_FALSE(*printed(Method::P6, Property::order_independent));
  EXPECT_TRUE(*printed(Method::P8, Property::affine_invariant));
  EXPECT_TRUE(*printed(Method::P1, Property::locally_perseverant));
  EXPECT_FALSE(printed(Method::P9, Property::pop_free).has_value());  // not in the table
  EXPECT_EQ(printed_table().size(), all_properties().size());
}

TEST(PaperTable, DisagreementsCarryAReason) {
  AuditReport report;
  report.methods = {Method::P4};
  report.properties = {Property::winding_aware, Property::pop_free};
  AuditCell aware;
  aware.method = Method::P4, aware.property = Property::winding_aware, aware.holds = true;
  AuditCell pops;
  pops.method = Method::P4, pops.property = Property::pop_free, pops.holds = true;
  report.cells = {aware, pops};
  const auto d = disagreements(report);
  ASSERT_EQ(d.size(), 1u);  // P4 pop-free agrees with the print
  EXPECT_EQ(d[0].property, Property::winding_aware);
  EXPECT_FALSE(d[0].printed);
  EXPECT_TRUE(d[0].measured);
  EXPECT_NE(d[0].reason.find("BiSAM"), std::string::npos);
}

}  // namespace
}  // namespace pita::analysis
