#include "core/arc_length.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/limits.hpp"

namespace pita {

namespace {

// 8-point Gauss-Legendre nodes on [-1, 1], ascending, and their weights.
constexpr std::array<double, 8> kNodes{-0.96028985649753623168, -0.79666647741362673959,
                                       -0.52553240991632898582, -0.18343464249564980494,
                                       0.18343464249564980494,  0.52553240991632898582,
                                       0.79666647741362673959,  0.96028985649753623168};
constexpr std::array<double, 8> kWeights{0.10122853629037625915, 0.22238103445337447054,
                                         0.31370664587788728734, 0.36268378337836198297,
                                         0.36268378337836198297, 0.31370664587788728734,
                                         0.22238103445337447054, 0.10122853629037625915};

// Barycentric weights of the nodes, 1 / prod_{k != j} (x_j - x_k).
std::array<double, 8> barycentric_weights() {
  std::array<double, 8> lambda{};
  for (std::size_t j = 0; j < 8; ++j) {
    double product = 1.0;
    for (std::size_t k = 0; k < 8; ++k) {
      if (k != j) product *= kNodes[j] - kNodes[k];
    }
    lambda[j] = 1.0 / product;
  }
  return lambda;
}
const std::array<double, 8> kBarycentric = barycentric_weights();

// The interpolating polynomial of `values` (at the nodes) at x in [-1, 1].
double interpolate(const double (&values)[8], double x) {
  double numerator = 0.0, denominator = 0.0;
  for (std::size_t j = 0; j < 8; ++j) {
    const double dx = x - kNodes[j];
    if (dx == 0.0) return values[j];
    const double term = kBarycentric[j] / dx;
    numerator += term * values[j];
    denominator += term;
  }
  return numerator / denominator;
}

// The speeds at the nodes of [a, b] and their Gauss-Legendre integral.
double sample_cell(const ArcLengthTable::Path& path, double a, double b, double from, double to,
                   double (&speeds)[8]) {
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
  // Central difference of order 8 with step kDerivativeStep * width; within
  // four steps of an end (where a clamped motion would be sampled beyond its
  // knots), a one-sided difference of order 4 with a tenth of that step.
  const double h = limits::kDerivativeStep * width;
  Complex derivative;
  if (tau - 4.0 * h >= from && tau + 4.0 * h <= to) {
    static constexpr double c[4] = {4.0 / 5.0, -1.0 / 5.0, 4.0 / 105.0, -1.0 / 280.0};
    for (int k = 0; k < 4; ++k) {
      derivative += c[k] * (path(tau + (k + 1) * h) - path(tau - (k + 1) * h));
    }
    derivative /= h;
  } else {
    const double g = 0.1 * h;
    const double side = tau - from < to - tau ? 1.0 : -1.0;  // forward near `from`, backward near `to`
    const double s = side * g;
    derivative = (-25.0 * path(tau) + 48.0 * path(tau + s) - 36.0 * path(tau + 2.0 * s) +
                  16.0 * path(tau + 3.0 * s) - 3.0 * path(tau + 4.0 * s)) / (12.0 * s);
  }
  return std::abs(derivative);
}

ArcLengthTable::ArcLengthTable(const Path& path, double from, double to) : from_(from), to_(to) {
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
  const Point origin = path(from);
  for (int i = 0; i < n; ++i) {
    Initial& cell = initial[static_cast<std::size_t>(i)];
    cell.a = i == 0 ? from : from + (to - from) * i / n;
    cell.b = i == n - 1 ? to : from + (to - from) * (i + 1) / n;
    cell.length = sample_cell(path, cell.a, cell.b, from, to, cell.speeds);
    estimate += cell.length;
    const Point p = path(cell.b);
    if (!std::isfinite(p.real()) || !std::isfinite(p.imag())) {
      throw std::invalid_argument("the path is not finite at t = " + std::to_string(cell.b));
    }
    size = std::max({size, std::abs(p), std::abs(p - origin)});
  }
  if (!std::isfinite(estimate)) throw std::invalid_argument("the path's length is not finite");
  if (!(estimate > limits::kArcLengthZero * std::max(size, std::abs(origin)))) {
    throw std::invalid_argument("the path has zero length: the point does not move");
  }
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

void ArcLengthTable::refine(const Path& path, double a, double b, const double (&speeds)[8],
                            double length, double tolerance, int depth) {
  const auto keep = [&] {
    Cell cell;
    cell.from = a;
    cell.to = b;
    cell.length = length;
    std::copy(std::begin(speeds), std::end(speeds), std::begin(cell.speeds));
    cells_.push_back(cell);
  };
  const double middle = 0.5 * (a + b);
  if (depth >= limits::kArcLengthMaxDepth || cells_.size() >= static_cast<std::size_t>(limits::kArcLengthMaxCells) || !(a < middle && middle < b)) {
    keep();
    return;
  }
  double left[8], right[8];
  const double left_length = sample_cell(path, a, middle, from_, to_, left);
  const double right_length = sample_cell(path, middle, b, from_, to_, right);
  Cell whole;
  whole.from = a;
  whole.to = b;
  std::copy(std::begin(speeds), std::end(speeds), std::begin(whole.speeds));
  const bool halves_agree = std::abs(left_length + right_length - length) <= tolerance;
  const bool interpolant_agrees = std::abs(partial(whole, middle) - left_length) <= tolerance;
  if (halves_agree && interpolant_agrees) {
    keep();
    return;
  }
  refine(path, a, middle, left, left_length, 0.5 * tolerance, depth + 1);
  refine(path, middle, b, right, right_length, 0.5 * tolerance, depth + 1);
}

double ArcLengthTable::speed_in(const Cell& cell, double tau) const {
  const double x = (2.0 * tau - cell.from - cell.to) / (cell.to - cell.from);
  return interpolate(cell.speeds, x);
}

double ArcLengthTable::partial(const Cell& cell, double tau) const {
  if (tau <= cell.from) return 0.0;
  if (tau >= cell.to) return cell.length;
  // Gauss-Legendre on [from, tau] of the cell's interpolated speed (exact
  // for that polynomial of degree 7).
  const double half = 0.5 * (tau - cell.from), middle = 0.5 * (tau + cell.from);
  double sum = 0.0;
  for (std::size_t j = 0; j < 8; ++j) sum += kWeights[j] * speed_in(cell, middle + half * kNodes[j]);
  return half * sum;
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
    if (error > 0.0) hi = tau; else lo = tau;
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
