// Fornberg's finite-difference weights (src/core/finite_difference.cpp):
// the classical centred stencils, and exactness on polynomials of degree
// below the node count on uneven nodes (derivatives taken by hand); and the
// stencils written out in core/finite_difference.hpp.
#include <cmath>
#include <complex>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "core/finite_difference.hpp"

namespace pita {
namespace {

TEST(FiniteDifference, CentredFivePointStencilsAreTheClassicalOnes) {
  const double h = 0.5;
  const std::vector<std::vector<double>> w = fornberg_weights(1.0, {0.0, 0.5, 1.0, 1.5, 2.0}, 2);
  const std::vector<double> first = {1.0, -8.0, 0.0, 8.0, -1.0};
  const std::vector<double> second = {-1.0, 16.0, -30.0, 16.0, -1.0};
  for (std::size_t j = 0; j < 5; ++j) {
    EXPECT_NEAR(w[0][j], j == 2 ? 1.0 : 0.0, 1e-15) << j;
    EXPECT_NEAR(w[1][j], first[j] / (12.0 * h), 1e-14) << j;
    EXPECT_NEAR(w[2][j], second[j] / (12.0 * h * h), 1e-13) << j;
  }
}

TEST(FiniteDifference, ExactOnPolynomialsOfDegreeBelowTheNodeCount) {
  // f(x) = 2 - x + 3 x^2 - 0.5 x^3 + 0.25 x^4 - 0.1 x^5 on six uneven nodes.
  const auto f = [](double x) {
    return 2.0 - x + 3.0 * x * x - 0.5 * x * x * x + 0.25 * std::pow(x, 4) - 0.1 * std::pow(x, 5);
  };
  const auto df = [](double x) { return -1.0 + 6.0 * x - 1.5 * x * x + std::pow(x, 3) - 0.5 * std::pow(x, 4); };
  const auto ddf = [](double x) { return 6.0 - 3.0 * x + 3.0 * x * x - 2.0 * std::pow(x, 3); };
  const std::vector<double> nodes = {-0.3, 0.1, 0.25, 0.7, 0.8, 1.3};
  for (const double x0 : {-0.3, 0.0, 0.4, 1.3, 2.0}) {
    const auto w = fornberg_weights(x0, nodes, 2);
    double d0 = 0.0, d1 = 0.0, d2 = 0.0;
    for (std::size_t j = 0; j < nodes.size(); ++j) {
      d0 += w[0][j] * f(nodes[j]);
      d1 += w[1][j] * f(nodes[j]);
      d2 += w[2][j] * f(nodes[j]);
    }
    EXPECT_NEAR(d0, f(x0), 1e-11) << x0;
    EXPECT_NEAR(d1, df(x0), 1e-10) << x0;
    EXPECT_NEAR(d2, ddf(x0), 1e-9) << x0;
  }
}

TEST(FiniteDifference, OneSidedSixNodesKeepFourthOrder) {
  // Halving h divides the error of f'' by about 2^4 for f = sin.
  const auto error = [](double h) {
    std::vector<double> nodes;
    for (int j = 0; j <= 5; ++j) nodes.push_back(0.3 + j * h);
    const auto w = fornberg_weights(0.3, nodes, 2);
    double d2 = 0.0;
    for (std::size_t j = 0; j < nodes.size(); ++j) d2 += w[2][j] * std::sin(nodes[j]);
    return std::abs(d2 + std::sin(0.3));
  };
  const double ratio = error(0.02) / error(0.01);
  EXPECT_GT(ratio, 12.0);
  EXPECT_LT(ratio, 40.0);
}

// The written-out stencils: exact on the polynomials their order covers, for
// every value type a caller gives them, and from either side.
TEST(Stencils, AreExactOnPolynomialsOfTheirOrder) {
  const auto cubic = [](double x) { return 1.0 - 2.0 * x + 0.5 * x * x + 0.25 * x * x * x; };
  const auto d_cubic = [](double x) { return -2.0 + x + 0.75 * x * x; };
  const auto dd_cubic = [](double x) { return 1.0 + 1.5 * x; };
  const auto quadratic = [](double x) { return 3.0 - x + 2.0 * x * x; };
  const auto septic = [](double x) { return std::pow(x, 7) - 3.0 * x; };
  const auto d_septic = [](double x) { return 7.0 * std::pow(x, 6) - 3.0; };
  const double x = 0.7, h = 0.125;
  EXPECT_NEAR(central_derivative(quadratic, x, h), -1.0 + 4.0 * x, 1e-13);
  EXPECT_NEAR(central_derivative4(cubic, x, h), d_cubic(x), 1e-13);
  EXPECT_NEAR(central_derivative8(septic, x, h), d_septic(x), 1e-11);
  for (const double side : {1.0, -1.0}) {
    EXPECT_NEAR(one_sided_derivative4(cubic, x, side * h), d_cubic(x), 1e-12) << side;
    EXPECT_NEAR(one_sided_second_derivative(quadratic, x, side * h), 4.0, 1e-11) << side;
  }
  EXPECT_NEAR(central_second_derivative4(cubic, x, h), dd_cubic(x), 1e-12);
}

TEST(Stencils, TakeComplexAndVectorValues) {
  const auto spiral = [](double t) { return std::polar(std::exp(0.1 * t), t); };
  const auto curve = [](double t) { return Eigen::Vector2d(t * t, std::sin(t)); };
  const double t = 0.4, h = 1e-3;
  const std::complex<double> velocity = spiral(t) * std::complex<double>(0.1, 1.0);
  EXPECT_LT(std::abs(central_derivative4(spiral, t, h) - velocity), 1e-11);
  EXPECT_LT((central_derivative(curve, t, h) - Eigen::Vector2d(2.0 * t, std::cos(t))).norm(), 1e-6);
  // The same bits as the formula written at the call site.
  const Eigen::Vector2d by_hand =
      (curve(t - 2 * h) - 8.0 * curve(t - h) + 8.0 * curve(t + h) - curve(t + 2 * h)) / (12.0 * h);
  EXPECT_EQ(central_derivative4(curve, t, h), by_hand);
}

}  // namespace
}  // namespace pita
