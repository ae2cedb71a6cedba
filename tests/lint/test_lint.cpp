// The lint of a scene (src/lint/lint.cpp): a scene accepts a finding with its
// reason, by check and pointer (a panel's entry covers its layers), and an
// entry that accepts nothing is reported.
#include <gtest/gtest.h>

#include "lint/lint.hpp"
#include "lint_support.hpp"

namespace pita::lint {
namespace {

using test::arrow_scene;
using test::lint_text;

const std::string kOver = R"("layers": [{"type": "pattern"},
    {"type": "label", "text": "over the frames", "at": [2.5, 1.5], "size": 16}])";

TEST(Lint, AFindingAcceptedWithItsReason) {
  const Report report = lint_text(arrow_scene(kOver + R"(, "lint": {"allow": [
      {"check": "text-over-data", "pointer": "/layers/1", "reason": "the label names the frames it lies on"}]})"));
  ASSERT_EQ(report.findings.size(), 1u);
  EXPECT_EQ(report.findings[0].reason, "the label names the frames it lies on");
  EXPECT_EQ(report.findings[0].allowed_at, "/lint/allow/0");
  EXPECT_TRUE(report.clean());
  EXPECT_EQ(report.accepted(), 1u);
  EXPECT_TRUE(report.unused_allows.empty());
  EXPECT_NE(describe(report.findings[0]).find("(accepted by /lint/allow/0: the label names"), std::string::npos);
}

TEST(Lint, AnotherPointerOrCheckDoesNotAccept) {
  for (const std::string allow : {R"({"check": "text-over-data", "pointer": "/layers/0", "reason": "r"})",
                                  R"({"check": "text-overlap", "pointer": "/layers/1", "reason": "r"})",
                                  R"({"check": "text-over-data", "pointer": "/layers/10", "reason": "r"})"}) {
    const Report report = lint_text(arrow_scene(kOver + R"(, "lint": {"allow": [)" + allow + "]}"));
    EXPECT_FALSE(report.clean()) << allow;
    EXPECT_EQ(report.unused_allows, std::vector<std::string>{"/lint/allow/0"}) << allow;
  }
}

TEST(Lint, AnEntryWithoutPointerAcceptsTheCheckEverywhere) {
  const Report report = lint_text(
      arrow_scene(kOver + R"(, "lint": {"allow": [{"check": "text-over-data", "reason": "labels on frames"}]})"));
  EXPECT_TRUE(report.clean());
}

TEST(Lint, DescribeNamesPointerCheckMessageAndFix) {
  EXPECT_EQ(describe({"outside", "/layers/2", "cut off", "widen the view", "", ""}),
            "/layers/2: outside: cut off; fix: widen the view");
  EXPECT_EQ(describe({"small-content", "", "small", "zoom in", "", ""}),
            "(the scene): small-content: small; fix: zoom in");
}

}  // namespace
}  // namespace pita::lint
