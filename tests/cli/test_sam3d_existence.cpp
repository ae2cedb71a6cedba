// pita audit sam3d-existence through the binary (src/cli/sam3d_existence.cpp):
// the table, --p, angles as multiples of pi, bad usage. The search itself:
// tests/analysis/test_sam3d_existence.cpp.
#include <string>

#include <gtest/gtest.h>

#include "run_pita.hpp"

namespace pita::test {
namespace {

// The subcommand reads no file: it runs in a scratch folder.
RunResult run_audit(const std::vector<std::string>& args) {
  const ScratchDir dir;
  std::vector<std::string> all = {"audit", "sam3d-existence"};
  all.insert(all.end(), args.begin(), args.end());
  return run_pita(all, dir.path());
}

TEST(Sam3dExistenceCli, ReportsTheBoundBesideThePapers) {
  const RunResult result = run_audit({"--theta", "pi/4", "--subdivisions", "0", "--angles", "5", "-q"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  // The identity perturbed by -0.34 everywhere has the eigenvalue 1 - 3(0.34) < 0: 0.33 at most.
  EXPECT_NE(result.out.find("| pi/4 (0.7854) | 0.33 | 0.50 | differs: we keep our measurement |"), std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("6 axes (icosahedron subdivided 0 times), 5 angles"), std::string::npos) << result.out;
  EXPECT_NE(result.err.find("took"), std::string::npos) << result.err;
}

TEST(Sam3dExistenceCli, ChecksOneP) {
  const RunResult yes = run_audit({"--theta", "2pi/3", "--p", "0.2", "--subdivisions", "0", "--angles", "5"});
  ASSERT_EQ(yes.exit_code, 0) << yes.err;
  EXPECT_NE(yes.out.find("| 2pi/3 (2.0944) | 0.2 | yes |"), std::string::npos) << yes.out;
  const RunResult no = run_audit({"--theta", "0.5", "--p", "0.5", "--subdivisions", "0", "--angles", "3"});
  ASSERT_EQ(no.exit_code, 0) << no.err;
  EXPECT_NE(no.out.find("| 0.5 (0.5000) | 0.5 | no | axis ["), std::string::npos) << no.out;
}

// --curve: one row per angle k pi/N; 1/3 at 0 (I - p J), 0 at pi.
TEST(Sam3dExistenceCli, PrintsTheFiguresCurve) {
  const RunResult result = run_audit({"--curve", "2", "--subdivisions", "0", "-q"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("| 0pi/2 (0.0000) | 0.33 |"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("| 1pi/2 (1.5708) | "), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("| 2pi/2 (3.1416) | 0.00 |"), std::string::npos) << result.out;
  for (const std::vector<std::string>& both : {std::vector<std::string>{"--curve", "2", "--theta", "pi/2"},
                                               {"--curve", "2", "--p", "0.1"},
                                               {"--curve", "0"}}) {
    const RunResult refused = run_audit(both);
    EXPECT_EQ(refused.exit_code, 2) << both[2];
    EXPECT_EQ(refused.out, "");
  }
}

TEST(Sam3dExistenceCli, BadUsageExitsTwo) {
  for (const char* theta : {"two", "pi/0", "4", "pi*2", "-pi/2"}) {
    const RunResult result = run_audit({"--theta", theta});
    EXPECT_EQ(result.exit_code, 2) << theta;
    EXPECT_NE(result.err.find("--theta"), std::string::npos) << result.err;
    EXPECT_EQ(result.out, "");
  }
  EXPECT_EQ(run_audit({"--subdivisions", "9"}).exit_code, 2);
  EXPECT_EQ(run_audit({"--angles", "0"}).exit_code, 2);
}

// Issue 37: within the documented ranges a run can take many minutes; its
// work is estimated and refused up front, naming --budget (which lets it run).
TEST(Sam3dExistenceCli, AnEstimateAboveTheBudgetIsRefusedAtOnce) {
  const RunResult result = run_audit({"--subdivisions", "4", "--angles", "1001"});
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_NE(result.err.find("would check up to"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("--budget F"), std::string::npos) << result.err;
  EXPECT_EQ(result.out, "");
  // The same flag lowers it: the default run is refused under a budget of 1e-3.
  const RunResult small = run_audit({"--budget", "0.001"});
  EXPECT_EQ(small.exit_code, 2) << small.err;
  EXPECT_NE(small.err.find("above the budget of 1e+08"), std::string::npos) << small.err;
}

}  // namespace
}  // namespace pita::test
