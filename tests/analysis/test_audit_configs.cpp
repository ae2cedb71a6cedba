#include <gtest/gtest.h>

#include "analysis/audit_configs.hpp"

namespace pita::analysis {
namespace {

TEST(AuditConfigs, SameSeedSameConfigurationsOtherSeedOthers) {
  const auto a = audit_configs(3, 40), b = audit_configs(3, 40), c = audit_configs(4, 40);
  ASSERT_EQ(a.size(), crafted_configs().size() + 40);
  bool differs = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].keyframes.b.arrow.p, b[i].keyframes.b.arrow.p);
    EXPECT_EQ(a[i].index, static_cast<int>(i));
    differs = differs || a[i].keyframes.b.arrow.p != c[i].keyframes.b.arrow.p;
  }
  EXPECT_TRUE(differs);
}

TEST(AuditConfigs, ConfigurationIDependsOnlyOnSeedAndI) {
  // More configurations do not move the first ones.
  const auto few = audit_configs(9, 10), many = audit_configs(9, 100);
  for (std::size_t i = 0; i < few.size(); ++i) EXPECT_EQ(few[i].keyframes.c.arrow.w, many[i].keyframes.c.arrow.w);
}

TEST(AuditConfigs, MixesAreInTurnAndKnotsIncrease) {
  const auto configs = audit_configs(1, 30);
  int tame = 0, wild = 0, near = 0;
  for (const AuditConfig& c : configs) {
    EXPECT_LT(c.keyframes.a.t, c.keyframes.b.t);
    EXPECT_LT(c.keyframes.b.t, c.keyframes.c.t);
    tame += c.mix == ConfigMix::tame, wild += c.mix == ConfigMix::wild, near += c.mix == ConfigMix::near_singular;
  }
  EXPECT_EQ(tame, 10);
  EXPECT_EQ(wild, 10);
  EXPECT_EQ(near, 10);
}

TEST(AuditConfigs, GeneratorIsUniformInItsRange) {
  AuditRandom r(42);
  double sum = 0;
  for (int i = 0; i < 10000; ++i) {
    const double u = r.uniform(2.0, 3.0);
    ASSERT_GE(u, 2.0);
    ASSERT_LT(u, 3.0);
    sum += u;
  }
  EXPECT_NEAR(sum / 10000, 2.5, 0.01);
}

TEST(AuditConfigs, ExtentIsTheLargestDistanceFromBsOrigin) {
  const KeyframeTriple k{{0.0, {{0, 0}, 1.0, 0.0}}, {0.5, {{3, 4}, 0.5, 0.0}}, {1.0, {{3, 4}, 2.0, 0.0}}};
  EXPECT_DOUBLE_EQ(extent(k), 5.0);  // |A.p - B.p| = 5
}

}  // namespace
}  // namespace pita::analysis
