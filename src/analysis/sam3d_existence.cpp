#include "analysis/sam3d_existence.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <complex>
#include <map>
#include <numbers>
#include <thread>
#include <utility>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "core/affine_power_of_space.hpp"
#include "core/limits.hpp"
#include "core/worker_pool.hpp"

namespace pita::analysis {

namespace {

constexpr std::array<PaperExistenceBound, 3> kPaperBounds = {{
    {2.0 * kPi / 3.0, 0.29, "2 pi/3"},
    {kPi / 2.0, 0.33, "pi/2"},
    {kPi / 4.0, 0.50, "pi/4"},
}};

// Where has_real_logarithm trusts the sign of the discriminant: relative to
// |L|_F^6, about 1e5 times its rounding error.
constexpr double kDiscriminantMargin = 1e-8;

// Where the experiment accepts 27 matrices at once (plainly_all_have_logarithms):
// relative to (1 + |L|_F^2)^2, the size of det and c2 (cubic and quadratic in
// L), about 1e4 times their rounding error.
constexpr double kAllPlainMargin = 1e-12;

// The 3^9 perturbation patterns, entry k of L gets sign (pattern / 3^k mod 3) - 1.
constexpr int kPatterns = 19683;
constexpr int kUnperturbed = (kPatterns - 1) / 2;  // every digit 1: every sign 0

Eigen::Matrix3d signs_of(int pattern) {
  Eigen::Matrix3d S;
  for (int k = 0; k < 9; ++k) {
    S(k / 3, k % 3) = static_cast<double>(pattern % 3) - 1.0;
    pattern /= 3;
  }
  return S;
}

using Row = std::array<double, 3>;

// The invariants of the characteristic polynomial x^3 - c1 x^2 + c2 x - det
// of the matrix with rows v, u, w, in two stages so that the experiment's
// loop computes the part of rows 1 and 2 once for the 27 choices of row 0
// (and has_real_logarithm the same numbers, rounded the same way).
struct LowerRows {
  Row cross;   // u x w: det = v . (u x w); its first entry is the minor a11 a22 - a12 a21
  double sum;  // a11 + a22
  double a10, a20;
  double norm2;  // |u|^2 + |w|^2
};

double squared(const Row& r) { return r[0] * r[0] + r[1] * r[1] + r[2] * r[2]; }

LowerRows lower_rows(const Row& u, const Row& w) {
  return {{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]},
          u[1] + w[2],
          u[0],
          w[0],
          squared(u) + squared(w)};
}

// Whether the matrix with rows v and `lower` has a real logarithm, from its
// characteristic polynomial x^3 - c1 x^2 + c2 x - det alone; nullopt when
// that cannot tell (the eigenvalues must).
std::optional<bool> decided_by_invariants(const Row& v, const LowerRows& lower) {
  const double det = v[0] * lower.cross[0] + v[1] * lower.cross[1] + v[2] * lower.cross[2];
  if (!(det > 0.0)) return false;
  // With det > 0 and c1, c2 > 0 every eigenvalue is positive or complex: real
  // roots of a polynomial whose coefficients alternate in sign are positive
  // (Descartes), and beside a complex pair the real one has the sign of det.
  // Most of the experiment's matrices end here.
  const double c1 = v[0] + lower.sum;
  const double c2 = lower.cross[0] + v[0] * lower.sum - v[1] * lower.a10 - v[2] * lower.a20;
  if (c1 > 0.0 && c2 > 0.0) return true;
  // Otherwise the cubic's discriminant tells a complex pair (< 0: the real
  // eigenvalue has det's sign, a log) from three distinct real eigenvalues
  // (> 0: not all positive, so two distinct negative ones, no log). Near zero
  // (degree 6 in L: relative to |L|^6, far above its rounding), undecided.
  const double q1 = -c1, q2 = c2, q3 = -det;  // x^3 + q1 x^2 + q2 x + q3
  const double discriminant =
      18.0 * q1 * q2 * q3 - 4.0 * q1 * q1 * q1 * q3 + q1 * q1 * q2 * q2 - 4.0 * q2 * q2 * q2 - 27.0 * q3 * q3;
  const double norm2 = squared(v) + lower.norm2;
  const double margin = kDiscriminantMargin * norm2 * norm2 * norm2;
  if (discriminant < -margin) return true;
  if (discriminant > margin) return false;
  return std::nullopt;
}

// Interval arithmetic, enough for the cubic's discriminant over a cube of
// matrices (plainly_all_have_logarithms). Rounding is not directed: the
// margins it is compared with are far above it.
struct Interval {
  double lo, hi;
};
Interval operator+(Interval a, Interval b) { return {a.lo + b.lo, a.hi + b.hi}; }
Interval operator-(Interval a, Interval b) { return {a.lo - b.hi, a.hi - b.lo}; }
Interval operator*(double k, Interval a) {
  return k >= 0.0 ? Interval{k * a.lo, k * a.hi} : Interval{k * a.hi, k * a.lo};
}
// Plain comparisons, not std::min and std::max: their instances are shared
// with every other file, which under the fuzzer's instrumentation made this
// loop ten times slower (scripts/sanitizers/coverage-ignore.txt).
double smaller(double a, double b) { return b < a ? b : a; }
double larger(double a, double b) { return a < b ? b : a; }
Interval operator*(Interval a, Interval b) {
  const double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
  return {smaller(smaller(p1, p2), smaller(p3, p4)), larger(larger(p1, p2), larger(p3, p4))};
}
Interval square(Interval a) {
  const double l = a.lo * a.lo, h = a.hi * a.hi;
  if (a.lo <= 0.0 && a.hi >= 0.0) return {0.0, larger(l, h)};
  return {smaller(l, h), larger(l, h)};
}

// Whether all 27 matrices with rows (R's row 0 plus p times signs in {-1, 0,
// 1}) and `lower` have a real logarithm by the tests of
// decided_by_invariants, shown at once: det, c1 and c2 are affine in row 0,
// so over the cube |v - R row 0| <= p each lies within its value at the
// centre plus or minus p times the 1-norm of its gradient; then det > 0 and
// either c1, c2 > 0 or the discriminant (by intervals) below its margin for
// every matrix. The margins, far above the rounding of these few operations,
// keep the answer the one the 27 tests would give. False means "test them".
bool plainly_all_have_logarithms(const Eigen::Matrix3d& R, double p, const LowerRows& lower) {
  const Row v = {R(0, 0), R(0, 1), R(0, 2)};
  const double scale = 1.0 + squared(v) + lower.norm2;
  const double margin = kAllPlainMargin * scale * scale;
  const double det = v[0] * lower.cross[0] + v[1] * lower.cross[1] + v[2] * lower.cross[2];
  const double det_spread = p * (std::abs(lower.cross[0]) + std::abs(lower.cross[1]) + std::abs(lower.cross[2]));
  if (!(det - det_spread > margin)) return false;
  const double c1 = v[0] + lower.sum;
  const double c2 = lower.cross[0] + v[0] * lower.sum - v[1] * lower.a10 - v[2] * lower.a20;
  const double c2_spread = p * (std::abs(lower.sum) + std::abs(lower.a10) + std::abs(lower.a20));
  if (c1 - p > margin && c2 - c2_spread > margin) return true;
  // x^3 + q1 x^2 + q2 x + q3 as in decided_by_invariants, q1 = -c1, q2 = c2,
  // q3 = -det; its discriminant below minus the largest margin of any of the
  // 27 (|v|^2 at most the sum of (|v_e| + p)^2).
  const Interval q1{-c1 - p, -c1 + p}, q2{c2 - c2_spread, c2 + c2_spread}, q3{-det - det_spread, -det + det_spread};
  const Interval discriminant = 18.0 * (q1 * q2 * q3) - 4.0 * (square(q1) * q1 * q3) + square(q1) * square(q2) -
                                4.0 * (square(q2) * q2) - 27.0 * square(q3);
  double norm2 = lower.norm2;
  for (const double e : v) norm2 += (std::abs(e) + p) * (std::abs(e) + p);
  const double discriminant_margin = kDiscriminantMargin * norm2 * norm2 * norm2;
  return discriminant.hi < -discriminant_margin - margin;
}

Row row_of(const Eigen::Matrix3d& L, int r) { return {L(r, 0), L(r, 1), L(r, 2)}; }

}  // namespace

bool has_real_logarithm(const Eigen::Matrix3d& L) {
  if (!L.allFinite()) return false;
  if (const std::optional<bool> decided = decided_by_invariants(row_of(L, 0), lower_rows(row_of(L, 1), row_of(L, 2)))) {
    return *decided;
  }
  const std::array<std::complex<double>, 3> values = pita::eigenvalues(L);
  if (values[1].imag() != 0.0) return true;  // a complex pair beside a real one, positive as det > 0
  // Three real ones, ordered: with det > 0 either all positive or one positive
  // and two negative.
  if (values[2].real() > 0.0) return true;
  const double a = values[1].real(), b = values[2].real();
  const double scale = L.norm();
  if (std::abs(a - b) > limits::kDoubleNegativeEigenvalue * scale) return false;  // two distinct negative eigenvalues
  // A double negative eigenvalue: a log iff it has two eigenvectors (a
  // rotation by pi with uniform scale on the plane). EAR decides exactly.
  try {
    Affine3 A;
    A.L = L;
    (void)AffinePowers(A);
    return true;
  } catch (const NoRealLogarithm&) {
    return false;
  }
}

std::vector<Eigen::Vector3d> icosphere_axes(int subdivisions) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> vertices = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                                           {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  for (Eigen::Vector3d& v : vertices) v.normalize();
  std::vector<std::array<int, 3>> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                           {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                           {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                           {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int step = 0; step < subdivisions; ++step) {
    std::map<std::pair<int, int>, int> middle;
    const auto midpoint = [&](int i, int j) {
      const std::pair<int, int> key(std::min(i, j), std::max(i, j));
      const auto found = middle.find(key);
      if (found != middle.end()) return found->second;
      vertices.push_back((vertices[static_cast<std::size_t>(i)] + vertices[static_cast<std::size_t>(j)]).normalized());
      const int index = static_cast<int>(vertices.size()) - 1;
      middle.emplace(key, index);
      return index;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& [a, b, c] : faces) {
      const int ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      finer.push_back({a, ab, ca});
      finer.push_back({b, bc, ab});
      finer.push_back({c, ca, bc});
      finer.push_back({ab, bc, ca});
    }
    faces = std::move(finer);
  }
  // One per antipodal pair: the one whose first non-zero coordinate (beyond
  // rounding) is positive.
  std::vector<Eigen::Vector3d> axes;
  for (const Eigen::Vector3d& v : vertices) {
    const int k = std::abs(v.x()) > 1e-9 ? 0 : std::abs(v.y()) > 1e-9 ? 1 : 2;
    if (v(k) > 0.0) axes.push_back(v);
  }
  return axes;
}

namespace {

// The first configuration without a SAM among the rotations by `angles` about
// every axis, perturbed by p; parallel over axes.
std::optional<NoSamConfiguration> first_without_sam(std::span<const double> angles, double p,
                                                    const Sam3dExistenceOptions& options) {
  const std::vector<Eigen::Vector3d> axes = icosphere_axes(options.subdivisions);

  // The least axis known to have a configuration without a SAM: the search
  // of any later axis is cut short (the first in the order of the axes is
  // the answer, whatever the number of threads).
  std::atomic<std::size_t> found_at{axes.size()};
  const auto search = [&](std::int64_t index, const std::atomic<bool>& stopping) -> std::optional<NoSamConfiguration> {
    const auto i = static_cast<std::size_t>(index);
    const auto beaten = [&] {
      return stopping.load(std::memory_order_relaxed) || found_at.load(std::memory_order_relaxed) < i;
    };
    for (std::size_t j = 0; j < angles.size() && !beaten(); ++j) {
      const Eigen::Matrix3d R = Eigen::AngleAxisd(angles[j], axes[i]).toRotationMatrix();
      // Row r of R with its 27 perturbations: choice c adds p times the
      // signs (c / 3^e mod 3) - 1 to entry e. Pattern k (signs_of) is the
      // choices k mod 27, k / 27 mod 27 and k / 729 of rows 0, 1 and 2, so
      // these loops visit the patterns in the order of k.
      std::array<std::array<Row, 27>, 3> rows;
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 27; ++c) {
          for (int e = 0, digits = c; e < 3; ++e, digits /= 3) {
            rows[r][c][e] = R(r, e) + p * (static_cast<double>(digits % 3) - 1.0);
          }
        }
      }
      std::optional<int> without;
      if (p == 0.0) {  // every pattern is R itself: one test, not 3^9 (at pi, the exact one of EAR)
        if (!has_real_logarithm(R)) without = kUnperturbed;
      }
      for (int c2 = 0; c2 < 27 && !without && p != 0.0; ++c2) {
        for (int c1 = 0; c1 < 27 && !without; ++c1) {
          const LowerRows lower = lower_rows(rows[1][c1], rows[2][c2]);
          if (plainly_all_have_logarithms(R, p, lower)) continue;
          for (int c0 = 0; c0 < 27; ++c0) {
            const std::optional<bool> decided = decided_by_invariants(rows[0][c0], lower);
            if (decided && *decided) continue;
            Eigen::Matrix3d L;
            L << rows[0][c0][0], rows[0][c0][1], rows[0][c0][2], rows[1][c1][0], rows[1][c1][1], rows[1][c1][2],
                rows[2][c2][0], rows[2][c2][1], rows[2][c2][2];
            if (!decided && has_real_logarithm(L)) continue;  // the eigenvalues decide
            without = c0 + 27 * c1 + 729 * c2;
            break;
          }
        }
      }
      if (without) {
        std::size_t least = found_at.load();
        while (i < least && !found_at.compare_exchange_weak(least, i)) {
        }
        return NoSamConfiguration{axes[i], angles[j], signs_of(*without), p};
      }
    }
    return std::nullopt;
  };
  PoolOptions pool;
  pool.threads = static_cast<int>(options.jobs == 0 ? std::max(1U, std::thread::hardware_concurrency()) : options.jobs);
  std::optional<NoSamConfiguration> first;
  run_ordered(
      static_cast<std::int64_t>(axes.size()), pool, search,
      [&](std::int64_t, std::optional<NoSamConfiguration>&& found) {
        if (!found) return true;
        first = std::move(found);
        return false;  // the first axis in order that has one
      },
      [] { return true; });
  return first;
}

// The number of grid steps of p up to p_max.
int grid_steps(const Sam3dExistenceOptions& options) {
  return static_cast<int>(std::floor(options.p_max / options.p_step + 1e-9));
}

}  // namespace

std::optional<NoSamConfiguration> find_no_sam(double theta, double p, const Sam3dExistenceOptions& options) {
  const int count = std::max(1, options.angles);
  std::vector<double> angles;
  for (int j = 0; j < count; ++j) angles.push_back(count == 1 ? theta : -theta + 2.0 * theta * j / (count - 1));
  return first_without_sam(angles, p, options);
}

SafePerturbation largest_safe_perturbation(double theta, const Sam3dExistenceOptions& options,
                                           const std::function<void(double)>& progress) {
  SafePerturbation result;
  result.theta = theta;
  const std::uint64_t axes = icosphere_axes(options.subdivisions).size();
  result.matrices_checked = axes * static_cast<std::uint64_t>(std::max(1, options.angles)) * kPatterns;
  // Grid indices: low passes (0: p = 0, the rotations themselves, checked
  // too), high fails or is one past the grid.
  const int steps = grid_steps(options);
  int low = 0, high = steps + 1;
  std::optional<NoSamConfiguration> failure_at_high;
  if (const auto failure = find_no_sam(theta, 0.0, options)) {
    result.largest_p = 0.0;
    result.at_next = failure;
    return result;
  }
  int calls = 0;
  const int total_calls = static_cast<int>(std::ceil(std::log2(steps + 1.0))) + 1;
  while (high - low > 1) {
    const int middle = (low + high) / 2;
    const std::optional<NoSamConfiguration> failure = find_no_sam(theta, middle * options.p_step, options);
    if (failure) {
      high = middle;
      failure_at_high = failure;
    } else {
      low = middle;
    }
    if (progress) progress(std::min(1.0, ++calls / static_cast<double>(total_calls)));
  }
  result.largest_p = low * options.p_step;
  result.at_next = high <= steps ? failure_at_high : std::nullopt;
  return result;
}

SafeCurve largest_safe_perturbation_curve(int steps, const Sam3dExistenceOptions& options,
                                          const std::function<void(double)>& progress) {
  SafeCurve curve;
  const int top = grid_steps(options);
  // Grid index i stands for p = i p_step; -1 for "even p = 0 fails".
  int bound = top;  // the previous angle's largest passing index: no later angle passes above it
  for (int k = 0; k <= steps; ++k) {
    const double theta = std::numbers::pi * k / steps;
    const std::array<double, 1> angle = {theta};
    const auto passes = [&](int i) {
      ++curve.tests;
      return i < 0 || !first_without_sam(angle, i * options.p_step, options).has_value();
    };
    int low = -1, high = bound + 1;  // low passes (or is -1), high fails (or is beyond the bound)
    if (k > 0 && passes(bound)) {
      low = bound;
    } else {
      if (k > 0) high = bound;
      // Gallop down from the bound to a passing index, then bisect.
      for (int drop = 1;; drop *= 2) {  // ends: index -1 passes
        const int i = std::max(-1, high - drop);
        if (passes(i)) {
          low = i;
          break;
        }
        high = i;
      }
      while (high - low > 1) {
        const int middle = (low + high) / 2;
        (passes(middle) ? low : high) = middle;
      }
    }
    bound = std::max(low, 0);
    curve.thetas.push_back(theta);
    curve.largest_p.push_back(std::max(low, 0) * options.p_step);
    if (progress) progress(static_cast<double>(k + 1) / (steps + 1));
  }
  return curve;
}

std::uint64_t existence_work(const Sam3dExistenceOptions& options, std::size_t thetas, bool single_p) {
  const std::uint64_t per_test =
      icosphere_axes(options.subdivisions).size() * static_cast<std::uint64_t>(std::max(1, options.angles)) * kPatterns;
  const auto calls = single_p ? 1u : static_cast<std::uint64_t>(std::ceil(std::log2(grid_steps(options) + 1.0))) + 1;
  return static_cast<std::uint64_t>(thetas) * calls * per_test;
}

std::uint64_t existence_curve_work(int steps, const Sam3dExistenceOptions& options) {
  const std::uint64_t per_test = icosphere_axes(options.subdivisions).size() * kPatterns;
  // Worst case per angle: a gallop and a bisection over the whole grid.
  const auto calls = 2 * static_cast<std::uint64_t>(std::ceil(std::log2(grid_steps(options) + 2.0))) + 1;
  return static_cast<std::uint64_t>(std::max(0, steps) + 1) * calls * per_test;
}

std::span<const PaperExistenceBound> paper_existence_bounds() { return kPaperBounds; }

}  // namespace pita::analysis
