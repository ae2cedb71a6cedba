// Arc length of a point's path and its inverse (the chapter's Sec. 3.2.1:
// "adaptive Gaussian integration" building a table of (u, s) pairs, then
// Newton-Raphson with bisection to find the parameter at a given length;
// docs/paper-notes.md N20).
//
// The path is any function of the motion's time, P(tau), tau in [from, to]: a
// point of the plane (Path) or of space (Path3, 3D pose scenes).
// Its speed |P'(tau)| is taken by a central difference of order 8 whose step
// is kDerivativeStep of the table interval (one-sided of order 4 within four
// steps of an end, so that motions clamped outside their knots are never
// sampled there). Each table interval keeps the speeds at its 8 Gauss-Legendre nodes;
// the length to any tau inside it integrates their interpolating polynomial,
// so inverting the table costs no further evaluation of the motion.
//
// Accuracy: an interval is accepted when its Gauss-Legendre length agrees
// with the sum over its halves, and its interpolated length to the midpoint
// agrees with the left half's, both within kArcLengthTolerance of the total
// length times the interval's share of [from, to]; so lengths and their
// inverse are right to about 1e-11 of the path length (the tests check
// 1e-9 against closed forms: circles, log-spirals, parabolas).
#pragma once

#include <functional>
#include <vector>

#include <Eigen/Core>

#include "core/arrow.hpp"

namespace pita {

class ArcLengthTable {
 public:
  using Path = std::function<Point(double)>;
  using Path3 = std::function<Eigen::Vector3d(double)>;

  // Builds the table of `path` over [from, to] (from < to, finite). Throws
  // std::invalid_argument when the path has (numerically) zero length, which
  // no reparameterisation can spread over time, or when a point is not finite.
  ArcLengthTable(const Path& path, double from, double to);
  ArcLengthTable(const Path3& path, double from, double to);

  double from() const { return from_; }
  double to() const { return to_; }
  double length() const { return total_; }

  // s(tau): the length from `from` to tau (clamped to [from, to]).
  double length_at(double tau) const;
  // The tau with s(tau) = fraction * length(), fraction clamped to [0, 1];
  // from() at 0 and to() at 1 exactly.
  double parameter_at(double fraction) const;
  // How many table intervals the adaptive integration kept.
  std::size_t intervals() const { return cells_.size(); }

  // The speed |P'(tau)| as the table measures it (a finite difference).
  // The finite-difference step is kDerivativeStep * width (width: the table
  // interval being sampled).
  static double speed(const Path& path, double tau, double from, double to, double width);
  static double speed(const Path3& path, double tau, double from, double to, double width);

 private:
  struct Cell {
    double from = 0.0, to = 0.0;
    double start_length = 0.0;  // s at `from`
    double length = 0.0;
    double coefficients[8] = {};  // of the speed's polynomial in x in [-1, 1] over [from, to],
                                  // interpolating it at the 8 Gauss-Legendre nodes
  };
  double partial(const Cell& cell, double tau) const;   // length from cell.from to tau
  double speed_in(const Cell& cell, double tau) const;  // the interpolated speed
  template <class AnyPath>
  void build(const AnyPath& path);
  template <class AnyPath>
  void refine(const AnyPath& path, double a, double b, const double (&speeds)[8], double length, double tolerance,
              int depth);

  double from_ = 0.0, to_ = 1.0, total_ = 0.0;
  double noise_ = 0.0;  // the rounding floor of the tolerance (limits::kArcLengthNoise)
  std::vector<Cell> cells_;
};

}  // namespace pita
