#include "analysis/sam3d_existence.hpp"

#include <algorithm>
#include <atomic>
#include <complex>
#include <array>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <thread>
#include <utility>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "core/affine_power3.hpp"

namespace pita::analysis {

namespace {

constexpr double kPi = std::numbers::pi;

constexpr std::array<PaperExistenceBound, 3> kPaperBounds = {{
    {2.0 * kPi / 3.0, 0.29, "2 pi/3"},
    {kPi / 2.0, 0.33, "pi/2"},
    {kPi / 4.0, 0.50, "pi/4"},
}};

// Where has_real_logarithm trusts the sign of the discriminant: relative to
// |L|_F^6, about 1e5 times its rounding error.
constexpr double kDiscriminantMargin = 1e-8;

// The 3^9 perturbation patterns, entry k of L gets sign (pattern / 3^k mod 3) - 1.
constexpr int kPatterns = 19683;

Eigen::Matrix3d signs_of(int pattern) {
  Eigen::Matrix3d S;
  for (int k = 0; k < 9; ++k) {
    S(k / 3, k % 3) = static_cast<double>(pattern % 3) - 1.0;
    pattern /= 3;
  }
  return S;
}

}  // namespace

bool has_real_logarithm(const Eigen::Matrix3d& L) {
  if (!L.allFinite() || !(L.determinant() > 0.0)) return false;
  // The characteristic polynomial x^3 - c1 x^2 + c2 x - det. With det > 0
  // and c1, c2 > 0 every eigenvalue is positive or complex: real roots of a
  // polynomial whose coefficients alternate in sign are positive (Descartes),
  // and beside a complex pair the real one has the sign of det. Most of the
  // experiment's matrices end here, without the cubic's roots.
  const double c1 = L.trace();
  const double c2 = L(0, 0) * L(1, 1) - L(0, 1) * L(1, 0) + L(0, 0) * L(2, 2) - L(0, 2) * L(2, 0) +
                    L(1, 1) * L(2, 2) - L(1, 2) * L(2, 1);
  if (c1 > 0.0 && c2 > 0.0) return true;
  // Otherwise the cubic's discriminant tells a complex pair (< 0: the real
  // eigenvalue has det's sign, a log) from three distinct real eigenvalues
  // (> 0: not all positive, so two distinct negative ones, no log). Near zero
  // (degree 6 in L: relative to |L|^6, far above its rounding), the roots.
  const double q1 = -c1, q2 = c2, q3 = -L.determinant();  // x^3 + q1 x^2 + q2 x + q3
  const double discriminant =
      18.0 * q1 * q2 * q3 - 4.0 * q1 * q1 * q1 * q3 + q1 * q1 * q2 * q2 - 4.0 * q2 * q2 * q2 - 27.0 * q3 * q3;
  const double norm2 = L.squaredNorm();
  const double margin = kDiscriminantMargin * norm2 * norm2 * norm2;
  if (discriminant < -margin) return true;
  if (discriminant > margin) return false;
  const std::array<std::complex<double>, 3> values = pita::eigenvalues(L);
  if (values[1].imag() != 0.0) return true;  // a complex pair beside a real one, positive as det > 0
  // Three real ones, ordered: with det > 0 either all positive or one positive
  // and two negative.
  if (values[2].real() > 0.0) return true;
  const double a = values[1].real(), b = values[2].real();
  const double scale = L.norm();
  if (std::abs(a - b) > 1e-6 * scale) return false;  // two distinct negative eigenvalues
  // A double negative eigenvalue: a log iff it has two eigenvectors (a
  // rotation by pi with uniform scale on the plane). EAR decides exactly.
  try {
    Affine3 A;
    A.L = L;
    (void)AffinePowers3(A);
    return true;
  } catch (const NoRealLogarithm&) {
    return false;
  }
}

std::vector<Eigen::Vector3d> icosphere_axes(int subdivisions) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> vertices = {
      {-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
      {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
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
  std::vector<Eigen::Matrix3d> perturbations(kPatterns);
  for (int k = 0; k < kPatterns; ++k) perturbations[static_cast<std::size_t>(k)] = p * signs_of(k);

  std::atomic<std::size_t> next{0};
  std::atomic<bool> found{false};
  std::mutex mutex;
  std::optional<NoSamConfiguration> first;
  const auto work = [&] {
    for (std::size_t i = next++; i < axes.size() && !found.load(std::memory_order_relaxed); i = next++) {
      for (std::size_t j = 0; j < angles.size() && !found.load(std::memory_order_relaxed); ++j) {
        const Eigen::Matrix3d R = Eigen::AngleAxisd(angles[j], axes[i]).toRotationMatrix();
        for (int k = 0; k < kPatterns; ++k) {
          if (has_real_logarithm(R + perturbations[static_cast<std::size_t>(k)])) continue;
          const std::lock_guard<std::mutex> lock(mutex);
          if (!first) first = NoSamConfiguration{axes[i], angles[j], signs_of(k), p};
          found = true;
          break;
        }
      }
    }
  };
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const unsigned jobs = std::min<unsigned>(options.jobs == 0 ? cores : options.jobs, static_cast<unsigned>(axes.size()));
  std::vector<std::thread> threads;
  for (unsigned t = 1; t < jobs; ++t) threads.emplace_back(work);
  work();  // the calling thread works too
  for (std::thread& t : threads) t.join();
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

std::span<const PaperExistenceBound> paper_existence_bounds() { return kPaperBounds; }

}  // namespace pita::analysis
