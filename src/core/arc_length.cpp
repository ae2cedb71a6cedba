#include "core/arc_length.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "core/finite_difference.hpp"
#include "core/limits.hpp"

namespace pita {

namespace {

// 8-point Gauss-Legendre nodes on [-1, 1], ascending, and their weights.
constexpr std::array<double, 8> kNodes{-0.96028985649753623168, -0.79666647741362673959, -0.52553240991632898582,
                                       -0.18343464249564980494, 0.18343464249564980494,  0.52553240991632898582,
                                       0.79666647741362673959,  0.96028985649753623168};
constexpr std::array<double, 8> kWeights{0.10122853629037625915, 0.22238103445337447054, 0.31370664587788728734,
                                         0.36268378337836198297, 0.36268378337836198297, 0.31370664587788728734,
                                         0.22238103445337447054, 0.10122853629037625915};

// The inverse of the Vandermonde matrix V_jk = x_j^k of the nodes: the
// coefficients of the polynomial of degree 7 through values at the nodes are
// V^-1 values (on [-1, 1] the monomials are well enough conditioned for 8
// Gauss nodes: cond(V) ~ 1e2).
Eigen::Matrix<double, 8, 8> inverse_vandermonde() {
  Eigen::Matrix<double, 8, 8> V;
  for (int j = 0; j < 8; ++j) {
    double power = 1.0;
    for (int k = 0; k < 8; ++k, power *= kNodes[static_cast<std::size_t>(j)]) V(j, k) = power;
  }
  return V.inverse();
}
const Eigen::Matrix<double, 8, 8> kInverseVandermonde = inverse_vandermonde();

// The coefficients a_k of the speed's interpolating polynomial sum a_k x^k.
void interpolate(const double (&speeds)[8], double (&coefficients)[8]) {
  const Eigen::Map<const Eigen::Matrix<double, 8, 1>> values(speeds);
  Eigen::Map<Eigen::Matrix<double, 8, 1>> a(coefficients);
  a = kInverseVandermonde * values;
}

// The length of a point's displacement, and whether the point is finite, in
// the plane and in space.
double magnitude(const Complex& v) { return std::abs(v); }
double magnitude(const Eigen::Vector3d& v) { return v.norm(); }
bool finite_point(const Complex& p) { return std::isfinite(p.real()) && std::isfinite(p.imag()); }
bool finite_point(const Eigen::Vector3d& p) { return p.allFinite(); }

// |P'(tau)|: a central difference of order 8 with step kDerivativeStep *
// width; within four steps of an end (where a clamped motion would be sampled
// beyond its knots), a one-sided difference of order 4 with a tenth of that
// step.
template <class AnyPath>
double path_speed(const AnyPath& path, double tau, double from, double to, double width) {
  const double h = limits::kDerivativeStep * width;
  if (tau - 4.0 * h >= from && tau + 4.0 * h <= to) return magnitude(central_derivative8(path, tau, h));
  const double g = 0.1 * h;
  const double side = tau - from < to - tau ? 1.0 : -1.0;  // forward near `from`, backward near `to`
  return magnitude(one_sided_derivative4(path, tau, side * g));
}

// The speeds at the nodes of [a, b] and their Gauss-Legendre integral.
template <class AnyPath>
double sample_cell(const AnyPath& path, double a, double b, double from, double to, double (&speeds)[8]) {
  const double half = 0.5 * (b - a), middle = 0.5 * (a + b);
  double sum = 0.0;
  for (std::size_t j = 0; j < 8; ++j) {
    speeds[j] = ArcLengthTable::speed(path, middle + half * kNodes[j], from, to, b - a);
    sum += kWeights[j] * speeds[j];
  }
  return half * sum;
}

}  // namespace

double ArcLengthTable::speed(const Path& path, double tau, double from, double to, double width) {
  return path_speed(path, tau, from, to, width);
}

double ArcLengthTable::speed(const Path3& path, double tau, double from, double to, double width) {
  return path_speed(path, tau, from, to, width);
}

ArcLengthTable::ArcLengthTable(const Path& path, double from, double to) : from_(from), to_(to) { build(path); }

ArcLengthTable::ArcLengthTable(const Path3& path, double from, double to) : from_(from), to_(to) { build(path); }

template <class AnyPath>
void ArcLengthTable::build(const AnyPath& path) {
  const double from = from_, to = to_;
  if (!(std::isfinite(from) && std::isfinite(to) && from < to)) {
    throw std::invalid_argument("arc length needs a finite interval [from, to] with from < to");
  }
  // A first estimate of the length and of the size of the points, from the
  // initial cells.
  const int n = limits::kArcLengthInitialCells;
  struct Initial {
    double a, b, length;
    double speeds[8];
  };
  std::vector<Initial> initial(static_cast<std::size_t>(n));
  double estimate = 0.0, size = 0.0;
  const auto origin = path(from);
  for (int i = 0; i < n; ++i) {
    Initial& cell = initial[static_cast<std::size_t>(i)];
    cell.a = i == 0 ? from : from + (to - from) * i / n;
    cell.b = i == n - 1 ? to : from + (to - from) * (i + 1) / n;
    cell.length = sample_cell(path, cell.a, cell.b, from, to, cell.speeds);
    estimate += cell.length;
    const auto p = path(cell.b);
    if (!finite_point(p)) {
      throw std::invalid_argument("the path is not finite at t = " + std::to_string(cell.b));
    }
    size = std::max({size, magnitude(p), magnitude(p - origin)});
  }
  if (!std::isfinite(estimate)) throw std::invalid_argument("the path's length is not finite");
  if (!(estimate > limits::kArcLengthZero * std::max(size, magnitude(origin)))) {
    throw std::invalid_argument("the path has zero length: the point does not move");
  }
  noise_ = limits::kArcLengthNoise * std::max(size, magnitude(origin));
  for (const Initial& cell : initial) {
    refine(path, cell.a, cell.b, cell.speeds, cell.length,
           limits::kArcLengthTolerance * estimate * (cell.b - cell.a) / (to - from), 0);
  }
  double running = 0.0;
  for (Cell& cell : cells_) {
    cell.start_length = running;
    running += cell.length;
  }
  total_ = running;
}

template <class AnyPath>
void ArcLengthTable::refine(const AnyPath& path, double a, double b, const double (&speeds)[8], double length,
                            double tolerance, int depth) {
  Cell whole;
  whole.from = a;
  whole.to = b;
  whole.length = length;
  interpolate(speeds, whole.coefficients);
  const auto keep = [&] { cells_.push_back(whole); };
  const double middle = 0.5 * (a + b);
  if (depth >= limits::kArcLengthMaxDepth || cells_.size() >= static_cast<std::size_t>(limits::kArcLengthMaxCells) ||
      !(a < middle && middle < b)) {
    keep();
    return;
  }
  double left[8], right[8];
  const double left_length = sample_cell(path, a, middle, from_, to_, left);
  const double right_length = sample_cell(path, middle, b, from_, to_, right);
  // Never below the rounding of the finite differences (limits.hpp): a short
  // span far from the origin could not meet a tolerance relative to its own
  // length, and would refine to the maximum depth everywhere.
  const double allowed = std::max(tolerance, noise_);
  const bool halves_agree = std::abs(left_length + right_length - length) <= allowed;
  const bool interpolant_agrees = std::abs(partial(whole, middle) - left_length) <= allowed;
  if (halves_agree && interpolant_agrees) {
    keep();
    return;
  }
  refine(path, a, middle, left, left_length, 0.5 * tolerance, depth + 1);
  refine(path, middle, b, right, right_length, 0.5 * tolerance, depth + 1);
}

double ArcLengthTable::speed_in(const Cell& cell, double tau) const {
  const double x = (2.0 * tau - cell.from - cell.to) / (cell.to - cell.from);
  double sum = 0.0;
  for (int k = 7; k >= 0; --k) sum = sum * x + cell.coefficients[k];
  return sum;
}

double ArcLengthTable::partial(const Cell& cell, double tau) const {
  if (tau <= cell.from) return 0.0;
  if (tau >= cell.to) return cell.length;
  // The integral from -1 to x of the speed polynomial, times the half width
  // (exact for that polynomial): sum a_k (x^{k+1} - (-1)^{k+1}) / (k + 1).
  const double x = (2.0 * tau - cell.from - cell.to) / (cell.to - cell.from);
  double at_x = 0.0, at_minus_one = 0.0;
  for (int k = 7; k >= 0; --k) {
    const double c = cell.coefficients[k] / (k + 1);
    at_x = (at_x + c) * x;
    at_minus_one = (at_minus_one + c) * -1.0;
  }
  return 0.5 * (cell.to - cell.from) * (at_x - at_minus_one);
}

double ArcLengthTable::length_at(double tau) const {
  if (tau <= from_) return 0.0;
  if (tau >= to_) return total_;
  const auto it = std::upper_bound(cells_.begin(), cells_.end(), tau,
                                   [](double value, const Cell& cell) { return value < cell.from; });
  const Cell& cell = *(it == cells_.begin() ? it : it - 1);
  return cell.start_length + partial(cell, tau);
}

double ArcLengthTable::parameter_at(double fraction) const {
  if (!(fraction > 0.0)) return from_;
  if (fraction >= 1.0) return to_;
  const double target = fraction * total_;
  auto it = std::upper_bound(cells_.begin(), cells_.end(), target,
                             [](double value, const Cell& cell) { return value < cell.start_length; });
  const Cell& cell = *(it == cells_.begin() ? it : it - 1);
  const double goal = target - cell.start_length;
  if (goal >= cell.length) return cell.to;
  // Newton on partial(tau) = goal, kept inside a bisection bracket.
  double lo = cell.from, hi = cell.to;
  double tau = cell.from + (cell.to - cell.from) * (cell.length > 0.0 ? goal / cell.length : 0.5);
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double error = partial(cell, tau) - goal;
    if (std::abs(error) <= 1e-15 * total_) break;
    if (error > 0.0)
      hi = tau;
    else
      lo = tau;
    const double slope = speed_in(cell, tau);
    double next = slope > 0.0 ? tau - error / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == tau || hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * std::abs(tau)) {
      tau = next;
      break;
    }
    tau = next;
  }
  return tau;
}

}  // namespace pita
