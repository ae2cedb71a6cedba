// `pita audit poses`: what of PITA Fig. 10 carries over to affine poses,
// measured (docs/reference/audit.md "What carries over to affine poses"). For each dimension (the
// plane, space), each pose method through three poses and each property of
// analysis/pose_properties.hpp: the worst value over the crafted and random
// triples of analysis/pose_audit_configs.hpp (the share of random triples
// where the motion exists, for "exists"; the median ARA, for "steady"), the
// verdict, and the triple where the worst value was reached.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "analysis/audit.hpp"
#include "analysis/pose_audit_configs.hpp"
#include "analysis/pose_properties.hpp"

namespace pita::analysis {

inline constexpr int kDefaultPoseAuditConfigs = 200;

struct PoseAuditOptions {
  std::vector<PoseMethod> methods;         // empty: default_pose_audit_methods()
  std::vector<int> dimensions;             // 2 and/or 3; empty: both
  int configs = kDefaultPoseAuditConfigs;  // random triples per dimension (crafted ones come on top)
  std::uint64_t seed = 1;
  int jobs = 0;  // threads; 0: the number of cores
  // Called after each finished cell with (done, total), from the calling thread; may be empty.
  std::function<void(int, int)> progress;
  const std::atomic<bool>* stop = nullptr;  // set from outside to stop: run_pose_audit throws AuditStopped
};

struct PoseAuditCell {
  int dimension = 2;
  PoseMethod method = PoseMethod::poly_sam;
  PoseProperty property = PoseProperty::exists;
  bool holds = true;
  // The number the table shows: the worst value (largest deviation, smallest
  // reaction), the share of random triples where the motion exists, or the
  // median ARA.
  double value = 0.0;
  double largest = 0.0;  // steady: the largest ARA; exists: the share where it does not
  // A deviation's largest value on the near-singular triples, which do not
  // decide the verdict (rounding amplified by their conditioning).
  double near_singular = 0.0;
  int measured = 0;       // triples that decided the verdict
  int worst_config = -1;  // index into the dimension's configurations, -1 if none
  PoseProbe worst;        // the measurement there
  // exists: the share of the tame, wild and near-singular triples where the motion exists.
  std::array<double, 3> share_by_mix{1.0, 1.0, 1.0};
};

struct PoseAuditReport {
  PoseAuditOptions options;
  std::vector<int> dimensions;
  std::vector<PoseMethod> methods;
  std::vector<PoseProperty> properties;
  std::vector<PoseAuditConfig<Affine2>> plane;  // the triples measured in 2D (if 2 is a dimension)
  std::vector<PoseAuditConfig<Affine3>> space;  // in 3D
  std::vector<PoseAuditCell> cells;             // dimensions x methods x properties, in that order
  const PoseAuditCell& cell(int dimension, PoseMethod m, PoseProperty p) const;
  // The name of configuration `index` of `dimension` ("tame #4").
  std::string config_name(int dimension, int index) const;
};

// The pose methods of both dimensions through three poses, in the registry's
// order (polySAM, bezier-SAM, biarc-SAM, four-point-SAM, P4, P5, P6, P9), but
// linear interpolation of the matrices (the SAM paper's foil, which --methods
// can name).
std::vector<PoseMethod> default_pose_audit_methods();

// Whether the pose audit can measure `method`: a method of both dimensions
// (PoseMethodInfo::in_space) that takes three poses.
bool pose_auditable(PoseMethod method);

// Runs the audit. Deterministic for a seed and a count, whatever `jobs`.
// Throws std::invalid_argument for a method pose_auditable refuses, a
// dimension other than 2 or 3, a count outside [1, kMaxAuditConfigs].
PoseAuditReport run_pose_audit(const PoseAuditOptions& options);

}  // namespace pita::analysis
