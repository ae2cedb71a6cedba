// pita audit's verdicts against Fig. 10 as docs/paper-notes.md N8 and N36
// read it. The expected sets are written out here, from the paper and from
// tests/core/test_fig10.cpp (an independent implementation of the same
// measurements), not from the audit's own output.
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "analysis/audit.hpp"
#include "support/sanitizers.hpp"

namespace pita::analysis {
namespace {

using M = Method;
using Set = std::set<Method>;

const std::map<Property, Set>& expected_holders() {
  static const Set all{M::P1, M::P2, M::P3, M::P4,  M::P5,   M::P5S,  M::P6,
                       M::P7, M::P8, M::P9, M::P10, M::PaPo, M::LSCa, M::LSLP};
  static const std::map<Property, Set> sets{
      {Property::exists, all},
      // Sec. 4.2 claims C-infinity; P4 joins Bezier halves C1 at b (N3), P7
      // and P8 need the C1 knot warp at uneven b (N17), P9's frames spike
      // faster than 1/5000 of the span near a singular steady morph (N36).
      {Property::smooth, {M::P1, M::P2, M::P3, M::P5, M::P5S, M::P6, M::P10, M::PaPo, M::LSCa, M::LSLP}},
      // Sec. 4.3 except P5 (N7) and P10 (principal logs).
      {Property::similarity_invariant,
       {M::P1, M::P2, M::P3, M::P4, M::P5S, M::P6, M::P7, M::P8, M::P9, M::PaPo, M::LSCa, M::LSLP}},
      {Property::symmetric, all},
      {Property::handle_invariant, {M::P1, M::P4, M::P5S, M::P6, M::P7, M::P8, M::P9}},
      {Property::winding_aware, {M::P2, M::P3, M::P4, M::P6, M::P9, M::PaPo, M::LSLP}},
      {Property::pop_free, {M::P1, M::P3, M::P4, M::P6, M::P9, M::PaPo}},
      {Property::knot_controlled, {M::P1, M::P3, M::P5, M::P5S, M::P6, M::P9, M::P10, M::PaPo}},
      {Property::order_independent, {M::P1, M::P3, M::P5, M::P10, M::PaPo}},
      {Property::affine_invariant, {M::P1}},
      {Property::globally_perseverant, {M::P1}},
      {Property::radially_perseverant, {M::P1, M::P7}},
      {Property::locally_perseverant, {M::P8}},
  };
  return sets;
}

void expect_table(const AuditReport& report, std::uint64_t seed) {
  for (const AuditCell& cell : report.cells) {
    const bool expected = expected_holders().at(cell.property).count(cell.method) > 0;
    EXPECT_EQ(cell.holds, expected) << "seed " << seed << ": " << info(cell.method).id << " " << info(cell.property).id
                                    << " measured " << cell.value;
  }
}

TEST(Audit, EveryCellMatchesTheCorrectedTableForSeedsOneToTen) {
  // The verdicts must not flip between seeds at the default number of
  // configurations (issue 14). Under the sanitizers seeds 1 and 2 (the
  // table's test is the same; the ten seeds took a minute of CPU there).
  const std::uint64_t seeds = test::sample_size(10, 2);
  for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
    AuditOptions options;
    options.seed = seed;
    const AuditReport report = run_audit(options);
    ASSERT_EQ(report.cells.size(), default_audit_methods().size() * all_properties().size());
    expect_table(report, seed);
  }
}

TEST(Audit, IsTheSameWhateverTheNumberOfThreads) {
  AuditOptions one;
  one.configs = 12;
  one.seed = 5;
  one.jobs = 1;
  one.methods = {M::P2, M::P6, M::P8};
  AuditOptions two = one;
  two.jobs = 2;
  const AuditReport a = run_audit(one), b = run_audit(two);
  ASSERT_EQ(a.cells.size(), b.cells.size());
  for (std::size_t i = 0; i < a.cells.size(); ++i) {
    EXPECT_EQ(a.cells[i].value, b.cells[i].value);  // bit for bit
    EXPECT_EQ(a.cells[i].worst_config, b.cells[i].worst_config);
  }
}

TEST(Audit, ReportsTheConfigurationWhereAFailingCellFailed) {
  AuditOptions options;
  options.configs = 30;
  options.methods = {M::P5};
  options.properties = {Property::similarity_invariant};
  const AuditReport report = run_audit(options);
  const AuditCell& cell = report.cell(M::P5, Property::similarity_invariant);
  ASSERT_FALSE(cell.holds);
  ASSERT_GE(cell.worst_config, 0);
  EXPECT_GT(cell.value, 1e-4);
  ASSERT_TRUE(cell.worst.counterpart.has_value());
  EXPECT_EQ(cell.worst.original.a.arrow.p,
            report.configs[static_cast<std::size_t>(cell.worst_config)].keyframes.a.arrow.p);
}

TEST(Audit, RefusesCountsOutOfRangeAndTwoKeyframeMethods) {
  AuditOptions options;
  options.configs = 0;
  EXPECT_THROW(run_audit(options), std::invalid_argument);
  options.configs = kMaxAuditConfigs + 1;
  EXPECT_THROW(run_audit(options), std::invalid_argument);
  options.configs = 1;
  options.methods = {M::SMA};
  EXPECT_THROW(run_audit(options), std::invalid_argument);
}

TEST(Audit, StopsWhenAskedTo) {
  std::atomic<bool> stop{true};
  AuditOptions options;
  options.stop = &stop;
  EXPECT_THROW(run_audit(options), AuditStopped);
}

}  // namespace
}  // namespace pita::analysis
