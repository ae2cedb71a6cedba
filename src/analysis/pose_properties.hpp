// The properties of PITA Sec. 4 (Fig. 10) that make sense for affine poses,
// as measurements (docs/reference/audit.md "What carries over to affine poses"): for one pose
// method and one triple of timed poses, a number that is zero (to rounding)
// where the property holds, or, for knot control, the size of the reaction,
// or, for steadiness, the SAM paper's ARA. Distances are the pose distance
// (analysis/pose_audit_configs.hpp) over the triple's extent, times are in
// units of the knot span: every number is the same for the triple moved by
// a similarity of the world.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "analysis/pose_audit_configs.hpp"
#include "core/pose_method.hpp"

namespace pita::analysis {

enum class PoseProperty {
  exists,
  interpolates,
  symmetric,
  left_affine_invariant,
  right_affine_invariant,
  knot_controlled,
  steady,
};

// How a cell's verdict is read from its numbers.
enum class PoseVerdict {
  share,      // the share of random triples where the motion exists; holds when it is 1
  deviation,  // holds when the largest value is at most the threshold
  reaction,   // holds when the smallest value is above the threshold
  steadiness  // holds when every value is at most the threshold times its scale; the cell shows the median
};

struct PosePropertyInfo {
  PoseProperty property;
  std::string_view id;       // "left-affine-invariant"
  std::string_view fig10;    // the section of the PITA paper (or the SAM paper) it carries over: "4.5 H"
  std::string_view measure;  // what the number measures, for the docs and the JSON report
  PoseVerdict verdict = PoseVerdict::deviation;
  double threshold = 0.0;
};

// Every property, in the order of the table (the one list; names and
// thresholds are read from it everywhere).
std::span<const PosePropertyInfo> all_pose_properties();
const PosePropertyInfo& info(PoseProperty property);
const PosePropertyInfo* find_pose_property(std::string_view id);

// One measurement: the value (NaN where the motion, or its counterpart, does
// not exist and the property is not measured), what the verdict compares it
// with (the threshold times `scale`), the time where it was reached, and what
// was compared.
struct PoseProbe {
  double value = 0.0;
  double scale = 1.0;
  std::optional<double> t;
  std::string relation;
  std::vector<std::pair<std::string, double>> parameters;
  std::string note;  // why the motion does not exist
};

// Measures `property` for `method` (a pose method of the SAM family through
// three poses) on `poses`. `seed` draws the affinity G or H the invariances
// ask for.
template <class Pose>
PoseProbe probe_pose(PoseProperty property, PoseMethod method, const PoseTriple<Pose>& poses, std::uint64_t seed);

}  // namespace pita::analysis
