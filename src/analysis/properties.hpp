// The properties of PITA Sec. 4 as measurements (Fig. 10): for one method and
// one keyframe configuration, a number that is zero (to rounding) where the
// property holds, or, for the two properties that ask the motion to react to
// a change (winding-aware, knot-controlled), the size of the reaction. Every
// number is similarity-invariant: distances are divided by the
// configuration's extent, times by its knot span (docs/paper-notes.md N36).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/keyframe.hpp"
#include "core/pitas/registry.hpp"

namespace pita::analysis {

enum class Property {
  exists,
  smooth,
  similarity_invariant,
  symmetric,
  handle_invariant,
  winding_aware,
  pop_free,
  knot_controlled,
  order_independent,
  affine_invariant,
  globally_perseverant,
  radially_perseverant,
  locally_perseverant,
};

struct PropertyInfo {
  Property property;
  std::string_view id;       // "similarity-invariant"
  std::string_view letter;   // Fig. 10's row letter ("H"), empty for the rows all PITAs share
  std::string_view section;  // "4.3, PITA Eq. 40"
  // What the number measures, for docs/reference/audit.md and the JSON report.
  std::string_view measure;
  // false: the property holds when the largest value over the configurations
  // is at most `threshold` (a deviation). true: it holds when the smallest
  // value is above `threshold` (a reaction).
  bool reaction = false;
  double threshold = 0.0;
};

// Every property, in the order of Sec. 4 (the one table; names, letters and
// thresholds are read from it everywhere).
std::span<const PropertyInfo> all_properties();
const PropertyInfo& info(Property property);
const PropertyInfo* find_property(std::string_view id);

// A similarity x -> z x + u that also adds `turn` to windings
// (arg z = turn modulo 2 pi).
struct Similarity {
  Complex translation{};
  double scale = 1.0;
  double rotation = 0.0;  // radians, any real (windings gain it)
};
Arrow apply(const Similarity& S, const Arrow& A);

// One measurement and what it compared: the motion through `original` and
// the motion through `counterpart` (transformed, swapped or tweaked), at the
// time `t` of the original where the value was reached.
struct Probe {
  double value = 0.0;
  std::optional<double> t;
  KeyframeTriple original;
  std::optional<KeyframeTriple> counterpart;
  // How frames of the two motions are compared, in words.
  std::string relation;
  // The parameters of the comparison (similarity, handle, tweak, ...), by name.
  std::vector<std::pair<std::string, double>> parameters;
  std::string note;  // the failure message when the motion does not exist
};

// Measures `property` for `method` on keyframes `k`. `seed` draws the
// similarity, handle or tweak that the property asks for.
Probe probe(Property property, Method method, const KeyframeTriple& k, std::uint64_t seed);

}  // namespace pita::analysis
