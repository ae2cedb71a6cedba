// The table of `pita audit sam3d-existence` (src/analysis/sam3d_existence_report.cpp),
// on the smallest experiment: the icosahedron's 6 axes, one angle. The
// command's options and output end to end: tests/cli/test_sam3d_existence.cpp.
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "analysis/sam3d_existence_report.hpp"

namespace pita::analysis {
namespace {

Sam3dExistenceReportRequest small_request() {
  Sam3dExistenceReportRequest request;
  request.search.subdivisions = 0;
  request.search.angles = 1;
  request.search.p_step = 0.05;
  return request;
}

TEST(Sam3dExistenceReport, OnePIsCheckedAtEachTheta) {
  Sam3dExistenceReportRequest request = small_request();
  request.thetas = {0.0};
  request.theta_texts = {"0"};
  request.p = 0.1;
  EXPECT_EQ(sam3d_existence_report_units(request), 0);
  const std::string text = sam3d_existence_report(request);
  EXPECT_EQ(text,
            "SAM existence in 3D (SAM paper Sec. 5.2): 6 axes (icosahedron subdivided 0 times), 1 angles over "
            "[-theta, theta], 3^9 perturbations each: 118098 matrices per (theta, p)\n\n"
            "| theta | p | every configuration has a SAM | a configuration without one |\n|---|---|---|---|\n"
            "| 0 (0.0000) | 0.1 | yes |  |\n");
}

// At the paper's angles the table gives its bound beside ours, and the
// progress counts 100 units per theta.
TEST(Sam3dExistenceReport, LargestSafePBesideThePapersBound) {
  Sam3dExistenceReportRequest request = small_request();
  request.thetas = {std::numbers::pi / 4, 1.0};
  request.theta_texts = {"pi/4", "1"};
  EXPECT_EQ(sam3d_existence_report_units(request), 200);
  std::vector<int> told;
  const std::string text = sam3d_existence_report(request, [&](int done) { told.push_back(done); });
  EXPECT_NE(text.find("| theta | largest safe p (ours) | paper's bound | | fails one step above at |"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("| pi/4 (0.7854) | "), std::string::npos) << text;
  EXPECT_NE(text.find(" | 0.50 | "), std::string::npos) << text;
  EXPECT_NE(text.find("| 1 (1.0000) | "), std::string::npos) << text;
  EXPECT_NE(text.find("(none stated)"), std::string::npos) << text;
  ASSERT_FALSE(told.empty());
  for (const int done : told) {
    EXPECT_GE(done, 0);
    EXPECT_LE(done, 200);
  }
}

TEST(Sam3dExistenceReport, TheCurveOneRowPerAngle) {
  Sam3dExistenceReportRequest request = small_request();
  request.curve = 2;
  EXPECT_EQ(sam3d_existence_report_units(request), 100);
  const std::string text = sam3d_existence_report(request);
  EXPECT_NE(text.find("rotations by j pi/2"), std::string::npos) << text;
  EXPECT_NE(text.find("| 0pi/2 (0.0000) | "), std::string::npos) << text;
  EXPECT_NE(text.find("| 1pi/2 (1.5708) | "), std::string::npos) << text;
  EXPECT_NE(text.find("| 2pi/2 (3.1416) | "), std::string::npos) << text;
}

}  // namespace
}  // namespace pita::analysis
