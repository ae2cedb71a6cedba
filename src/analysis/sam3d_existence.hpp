// Where a SAM exists in 3D: the experiment of the SAM paper's Sec. 5.2. Axes
// through the vertices of an icosahedron subdivided twice; for each, the
// rotations by angles in [-theta, theta]; each entry of their matrix L
// perturbed by -p, 0 or +p in all 3^9 combinations; does every such L have a
// real logarithm (a SAM, Culver's condition)? For each theta: the largest p
// for which it does (docs/paper-notes.md N59).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

namespace pita::analysis {

// Whether L has a real logarithm (Culver, Sec. 5.1): det L > 0 and no
// negative real eigenvalue of odd multiplicity, nor one in a Jordan block.
// The eigenvalues come from the closed-form cubic; only a negative pair equal
// to rounding (a rotation by pi) asks the exact test of EAR in 3D.
bool has_real_logarithm(const Eigen::Matrix3d& L);

// Unit vectors through the vertices of an icosahedron subdivided
// `subdivisions` times (each edge halved, the midpoints pushed onto the unit
// sphere), one per antipodal pair: rotations by [-theta, theta] about u and
// about -u are the same set. 6, 21, 81, 321, ... axes.
std::vector<Eigen::Vector3d> icosphere_axes(int subdivisions);

inline constexpr int kMaxExistenceSubdivisions = 4;
inline constexpr int kMaxExistenceAngles = 1001;

struct Sam3dExistenceOptions {
  int subdivisions = 2;  // of the icosahedron
  int angles = 17;       // rotation angles per axis, evenly spaced over [-theta, theta]
  double p_step = 0.01;  // the grid of p searched (the paper gives two decimals)
  double p_max = 1.0;    // the largest p tried
  unsigned jobs = 0;     // threads (0: one per core), parallel over axes
};

// A configuration without a SAM: the axis, the angle, the signs of the
// perturbation (row-major, each -1, 0 or +1) and p.
struct NoSamConfiguration {
  Eigen::Vector3d axis;
  double angle = 0.0;
  Eigen::Matrix3d signs;
  double p = 0.0;
};

// The first configuration found at (theta, p) without a SAM, or nullopt when
// all of them have one. Parallel over axes; the threads stop at the first
// found.
std::optional<NoSamConfiguration> find_no_sam(double theta, double p, const Sam3dExistenceOptions& options);

struct SafePerturbation {
  double theta = 0.0;
  double largest_p = 0.0;                     // on the grid; 0 when p_step itself fails
  std::optional<NoSamConfiguration> at_next;  // what fails one step above (nullopt: p_max passes)
  std::uint64_t matrices_checked = 0;         // per (theta, p) test: axes x angles x 3^9
};

// The largest p on the grid (multiples of p_step up to p_max) such that every
// configuration has a SAM, by bisection: assumes that a p that fails makes
// every larger one fail (N59 says why and how it was checked).
// `progress`, when given, is called with the fraction of the search done.
SafePerturbation largest_safe_perturbation(double theta, const Sam3dExistenceOptions& options,
                                           const std::function<void(double)>& progress = {});

// The figure's curve (docs/reference/audit.md "Where a SAM exists in 3D", N61): at the angles
// theta_k = k pi / steps, k = 0..steps, the largest p on the grid for which
// every rotation by an angle j pi / steps with |j| <= k, about every axis,
// perturbed, has a SAM: the experiment at theta_k with 2k + 1 angles. Only
// angles >= 0 are checked: a rotation by -a is the transpose of the rotation
// by a, the perturbations are closed under transposition, and a matrix and its
// transpose have the same eigenvalues. Each angle is searched downwards from
// the previous angle's bound (galloping, then bisection), with the same
// monotonicity in p as largest_safe_perturbation.
struct SafeCurve {
  std::vector<double> thetas;     // k pi / steps
  std::vector<double> largest_p;  // non-increasing; 0 also when p = 0 itself fails (rounding at pi)
  std::uint64_t tests = 0;        // (angle, p) pairs checked, each axes x 3^9 matrices at most
};
inline constexpr int kMaxExistenceCurveSteps = 720;
SafeCurve largest_safe_perturbation_curve(int steps, const Sam3dExistenceOptions& options,
                                          const std::function<void(double)>& progress = {});

// The matrices a run checks at most, before it starts (each test of (theta, p)
// may stop at its first configuration without a SAM, so runs are often far
// cheaper): `thetas` searches of the largest safe p (a bisection over the
// grid of p, plus p = 0), or with `single_p` one test per theta.
std::uint64_t existence_work(const Sam3dExistenceOptions& options, std::size_t thetas, bool single_p);
// The same for the curve of `steps` steps: each angle alone, a gallop and a
// bisection from the previous angle's bound (counted as its worst case).
std::uint64_t existence_curve_work(int steps, const Sam3dExistenceOptions& options);
// The work `pita audit sam3d-existence` does without --budget: about 150
// times its default run's bound (3 thetas, 81 axes, 17 angles: 6.5e8), some
// seconds on 2 cores (most tests stop at their first configuration without a
// SAM, so runs are far below their bound).
inline constexpr double kExistenceWorkBudget = 1e11;

// The paper's stated bounds (Sec. 5.2): theta < 2 pi / 3: p < 0.29; theta <
// pi / 2: p < 0.33; theta < pi / 4: p < 0.50.
struct PaperExistenceBound {
  double theta;
  double p;
  const char* theta_text;
};
std::span<const PaperExistenceBound> paper_existence_bounds();

}  // namespace pita::analysis
