// ARA (core/steadiness.hpp): 0 for a SAM and for each span of a polySAM,
// clearly positive for the unsteady motions (SAM paper Sec. 2.4).
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "core/steadiness.hpp"
#include "pose_test_support.hpp"

namespace pita {
namespace {

using test::distance;
using test::pose;

// The poses of scenes/sam-fig02-linear-and-sam.json (triangles mapped from
// the unit triangle) and a middle pose for the three-pose motions.
const Affine2 kSamFig2B = pose(2.2, 0.6, 0.3, 1.6, 0.0, 0.0);
const Affine2 kSamFig2C = pose(0.7, -1.6, 2.4, 1.1, 6.5, 0.5);
const Affine2 kMiddle = pose(1.4, -0.9, 1.6, 1.2, 3.5, 1.5);
const std::vector<Eigen::Vector2d> kTriangle = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {0.3, 0.3}};

// The points ARA averages over (Sec. 2.4): a regular grid spanning the box
// of the vertices, corners included.
TEST(Steadiness, AraGridSpansTheBoxOfTheVertices) {
  const std::vector<Eigen::Vector2d> vertices = {{0.0, 1.0}, {2.0, -1.0}, {1.0, 3.0}};
  const std::vector<Eigen::Vector2d> grid = ara_grid(vertices, 3);
  ASSERT_EQ(grid.size(), 9u);
  EXPECT_EQ(grid.front(), Eigen::Vector2d(0.0, -1.0));
  EXPECT_EQ(grid[4], Eigen::Vector2d(1.0, 1.0));  // the centre
  EXPECT_EQ(grid.back(), Eigen::Vector2d(2.0, 3.0));
  EXPECT_EQ(ara_grid(vertices).size(), static_cast<std::size_t>(kDefaultAraGrid * kDefaultAraGrid));
}

TEST(Steadiness, SamIsSteadyOthersAreNot) {
  const double sam =
      average_relative_acceleration(PoseMotion(PoseMethod::sam, {{0.0, kSamFig2B}, {1.0, kSamFig2C}}), kTriangle);
  const double linear =
      average_relative_acceleration(PoseMotion(PoseMethod::linear, {{0.0, kSamFig2B}, {1.0, kSamFig2C}}), kTriangle);
  const std::vector<TimedPose> three = {{0.0, kSamFig2B}, {0.5, kMiddle}, {1.0, kSamFig2C}};
  const double poly = average_relative_acceleration(PoseMotion(PoseMethod::poly_sam, three), kTriangle);
  const double bezier = average_relative_acceleration(PoseMotion(PoseMethod::bezier_sam, three), kTriangle);
  const double biarc = average_relative_acceleration(PoseMotion(PoseMethod::biarc_sam, three), kTriangle);
  EXPECT_LT(sam, 1e-6);
  EXPECT_LT(poly, 1e-6);  // steady on each span; the jumps at the knots are not sampled
  EXPECT_GT(linear, 0.1);
  EXPECT_GT(bezier, 0.01);
  EXPECT_GT(biarc, 0.01);
  // Not a matter of the time unit: the same motion over [0, 10].
  const double linear_slow =
      average_relative_acceleration(PoseMotion(PoseMethod::linear, {{0.0, kSamFig2B}, {10.0, kSamFig2C}}), kTriangle);
  EXPECT_NEAR(linear_slow, linear, 1e-6 * linear);
}

// Fig. 2 (Sec. 2.4): SAM's ARA is 0 and each of the four morphs it is compared
// with is unsteady, on the scene's poses and on another generic pair. (The
// paper's poses are not published; its numbers are not expected here.)
TEST(Steadiness, Fig2SamIsTheOnlySteadyMorph) {
  const Affine2 other_from = pose(1.0, 0.4, -0.2, 0.8, -1.0, 2.0);
  const Affine2 other_to = pose(-0.9, -1.3, 1.7, -0.4, 3.0, -2.5);
  for (const auto& [from, to] : {std::pair{kSamFig2B, kSamFig2C}, std::pair{other_from, other_to}}) {
    const std::vector<TimedPose> two = {{0.0, from}, {1.0, to}};
    const double sam = average_relative_acceleration(PoseMotion(PoseMethod::sam, two), kTriangle);
    EXPECT_LT(sam, 1e-6);
    for (const PoseMethod method : {PoseMethod::linear, PoseMethod::rarap, PoseMethod::asap, PoseMethod::tsb}) {
      SCOPED_TRACE(info(method).id);
      EXPECT_GT(average_relative_acceleration(PoseMotion(method, two), kTriangle), 1e-3);
    }
  }
}

// The same measure in space (one template for both dimensions). Checked
// against the plane: poses of the plane embedded in space (z kept) move the
// points of z = 0 exactly as in the plane, so both measures agree; and a SAM
// of space is steady while the linear blend of the same poses is not.
TEST(Steadiness, SpaceMeasureAgreesWithThePlaneAndFindsTheSamSteady) {
  const auto embedded = [](const Affine2& A) {
    Affine3 E;
    E.L.topLeftCorner<2, 2>() = A.L;
    E.b.head<2>() = A.b;
    return E;
  };
  std::vector<Eigen::Vector3d> flat;
  for (const Eigen::Vector2d& p : kTriangle) flat.emplace_back(p.x(), p.y(), 0.0);
  for (const PoseMethod method : {PoseMethod::linear, PoseMethod::sam}) {
    const double plane =
        average_relative_acceleration(PoseMotion(method, {{0.0, kSamFig2B}, {1.0, kSamFig2C}}), kTriangle);
    const double space = average_relative_acceleration(
        SamFamilyMotion<Affine3>(method, {{0.0, embedded(kSamFig2B)}, {1.0, embedded(kSamFig2C)}}, 0), flat);
    EXPECT_NEAR(space, plane, 1e-6 * (1.0 + plane)) << info(method).id;
  }
  // A turn about a tilted axis with a scaling, in space proper.
  const Affine3 from;
  const Affine3 to{1.5 * Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, 2, 2).normalized()).toRotationMatrix(),
                   Eigen::Vector3d(3, -1, 2)};
  const std::vector<Eigen::Vector3d> tetrahedron = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const double sam = average_relative_acceleration(
      SamFamilyMotion<Affine3>(PoseMethod::sam, {{0.0, from}, {1.0, to}}, 0), tetrahedron);
  const double linear = average_relative_acceleration(
      SamFamilyMotion<Affine3>(PoseMethod::linear, {{0.0, from}, {1.0, to}}, 0), tetrahedron);
  EXPECT_LT(sam, 1e-6);
  EXPECT_GT(linear, 0.5);
}

}  // namespace
}  // namespace pita
