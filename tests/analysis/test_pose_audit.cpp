// pita audit poses' verdicts (analysis/pose_audit.hpp): the table the docs
// print (docs/reference/audit.md "What carries over to affine poses"), written out here from what
// the constructions promise (docs/paper-notes.md N73-N81), for two seeds;
// the same output whatever the threads; configuration i depends only on
// (seed, i); the methods come from the registry.
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "analysis/pose_audit.hpp"
#include "analysis/pose_audit_report.hpp"
#include "support/sanitizers.hpp"

namespace pita::analysis {
namespace {

using M = PoseMethod;
using P = PoseProperty;
using Set = std::set<PoseMethod>;

const std::map<PoseProperty, Set>& expected_holders() {
  static const Set all{M::poly_sam, M::bezier_sam, M::biarc_sam, M::four_point, M::p4, M::p5, M::p6, M::p9};
  static const std::map<PoseProperty, Set> sets{
      // Wild triples turn neighbours by more than pi: no SAM (N74).
      {P::exists, {}},
      // The Bezier SAM approximates its middle pose (SAM Sec. 5.3).
      {P::interpolates, {M::poly_sam, M::biarc_sam, M::four_point, M::p4, M::p5, M::p6, M::p9}},
      {P::symmetric, all},
      // P5 takes logs about the centroid of the translations (N78).
      {P::left_affine_invariant, {M::poly_sam, M::bezier_sam, M::biarc_sam, M::four_point, M::p4, M::p6, M::p9}},
      {P::right_affine_invariant, {M::poly_sam, M::bezier_sam, M::biarc_sam, M::four_point, M::p4, M::p6, M::p9}},
      // Fig. 13: the SAM family and P4 trace the same poses whatever b.
      {P::knot_controlled, {M::p5, M::p6, M::p9}},
      // A SAM per span: the polySAM and the four-point scheme's polySAM.
      {P::steady, {M::poly_sam, M::four_point}},
  };
  return sets;
}

TEST(PoseAudit, EveryCellMatchesTheExpectedTableInBothDimensions) {
  // The table's verdicts are numbers: the Release suite checks them; under
  // the sanitizers the audit itself runs in SameOutputWhateverTheThreads.
  if (test::kUnderSanitizers) GTEST_SKIP() << "a table of numbers: checked by the Release suite";
  for (std::uint64_t seed : {1u, 2u}) {
    PoseAuditOptions options;
    options.seed = seed;
    options.configs = 45;
    const PoseAuditReport report = run_pose_audit(options);
    ASSERT_EQ(report.cells.size(), 2 * default_pose_audit_methods().size() * all_pose_properties().size());
    for (const PoseAuditCell& cell : report.cells) {
      const bool expected = expected_holders().at(cell.property).count(cell.method) > 0;
      EXPECT_EQ(cell.holds, expected) << "seed " << seed << ", " << cell.dimension << "D " << info(cell.method).id
                                      << " " << info(cell.property).id << " measured " << cell.value;
    }
  }
}

TEST(PoseAudit, TameTriplesAlmostAlwaysHaveAMotion) {
  if (test::kUnderSanitizers) GTEST_SKIP() << "a share of random triples: checked by the Release suite";
  PoseAuditOptions options;
  options.configs = 60;
  options.methods = {M::poly_sam, M::p6};
  const PoseAuditReport report = run_pose_audit(options);
  for (int d : {2, 3}) {
    for (M m : options.methods) {
      const PoseAuditCell& c = report.cell(d, m, P::exists);
      EXPECT_GE(c.share_by_mix[0], 0.9) << d << "D " << info(m).id;
      EXPECT_LT(c.share_by_mix[1], c.share_by_mix[0]) << d << "D " << info(m).id;  // wild ones lose some
    }
  }
}

TEST(PoseAudit, SameOutputWhateverTheThreads) {
  PoseAuditOptions options;
  options.configs = test::sample_size(9, 4);
  options.seed = 5;
  options.methods = {M::p6, M::biarc_sam};
  options.jobs = 1;
  const std::string one = format_pose_audit(run_pose_audit(options), AuditFormat::json);
  options.jobs = 2;
  EXPECT_EQ(one, format_pose_audit(run_pose_audit(options), AuditFormat::json));
}

TEST(PoseAudit, ConfigurationDependsOnlyOnSeedAndIndex) {
  const auto few = pose_audit_configs<Affine3>(3, 10), many = pose_audit_configs<Affine3>(3, 40);
  for (std::size_t i = 0; i < few.size(); ++i) {
    EXPECT_EQ(few[i].name, many[i].name);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(few[i].poses[k].t, many[i].poses[k].t);
      EXPECT_EQ(few[i].poses[k].pose.L, many[i].poses[k].pose.L);
      EXPECT_EQ(few[i].poses[k].pose.b, many[i].poses[k].pose.b);
    }
  }
  for (const auto& c : many) {
    for (const auto& p : c.poses) EXPECT_GT(p.pose.L.determinant(), 0.0) << c.name;
  }
  EXPECT_NE(pose_audit_configs<Affine3>(4, 1).back().poses[0].pose.b,
            few[crafted_pose_configs<Affine3>().size()].poses[0].pose.b);
}

TEST(PoseAudit, DefaultMethodsAreTheRegistrysThreePoseMethodsOfBothDimensionsButLinear) {
  std::vector<M> expected;
  for (const PoseMethodInfo& m : all_pose_methods()) {
    if (m.in_space && m.min_poses <= 3 && m.max_poses >= 3 && m.method != M::linear) expected.push_back(m.method);
  }
  EXPECT_EQ(default_pose_audit_methods(), expected);
  EXPECT_EQ(expected.size(), 8u);
  EXPECT_TRUE(pose_auditable(M::linear));
  EXPECT_FALSE(pose_auditable(M::sam));    // two poses
  EXPECT_FALSE(pose_auditable(M::rarap));  // the plane's only
}

TEST(PoseAudit, RefusesWhatItCannotMeasure) {
  PoseAuditOptions options;
  options.configs = 1;
  options.methods = {M::tsb};
  EXPECT_THROW(run_pose_audit(options), std::invalid_argument);
  options.methods = {};
  options.dimensions = {4};
  EXPECT_THROW(run_pose_audit(options), std::invalid_argument);
  options.dimensions = {};
  options.configs = 0;
  EXPECT_THROW(run_pose_audit(options), std::invalid_argument);
}

}  // namespace
}  // namespace pita::analysis
