// The keyframe configurations `pita audit` measures the properties of Sec. 4
// on (PITA Fig. 10): crafted edge cases first, then random ones drawn from a
// seed in three mixes, tame, wild and near-singular (docs/paper-notes.md N36).
// Configuration i depends only on (seed, i): the same seed gives the same
// configurations on any machine and in any order of evaluation.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/keyframe.hpp"

namespace pita::analysis {

enum class ConfigMix { crafted, tame, wild, near_singular };

struct AuditConfig {
  int index = 0;  // position in the list (crafted ones first)
  ConfigMix mix = ConfigMix::tame;
  std::string name;  // "tame #12", "crafted: P2 branch cut (collinear)"
  KeyframeTriple keyframes;
  // Exactly on a branch cut (PITA Fig. 12): measured for "exists" and
  // "pop-free" only; the other properties exclude such isolated singular
  // configurations (Sec. 4.1).
  bool on_cut = false;
};

std::string_view mix_name(ConfigMix mix);  // "crafted", "tame", "wild", "near-singular"

// The crafted edge cases (always measured, whatever the seed): the branch
// cuts of P2, of the principal logs of P5/P5S/P10 and of the -Pe methods
// (PITA Fig. 12), keyframes that are translations or rotations of each
// other, and uneven knots.
std::vector<AuditConfig> crafted_configs();

// The crafted cases then `random_count` random ones: i-th random one tame,
// wild or near-singular in turn (i mod 3).
std::vector<AuditConfig> audit_configs(std::uint64_t seed, int random_count);

// A small deterministic generator (SplitMix64), the same on every platform:
// the audit does not depend on the standard library's distributions.
class AuditRandom {
 public:
  explicit AuditRandom(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  double uniform(double lo, double hi);  // [lo, hi)
  double sign();                         // -1 or +1
 private:
  std::uint64_t state_;
};

// A stream of its own for each (seed, purpose, index): configurations and the
// similarities, handles and tweaks drawn for them do not shift when the
// number of configurations changes.
std::uint64_t stream_seed(std::uint64_t seed, std::uint64_t purpose, std::uint64_t index);

// The size of a configuration: the largest distance from B's origin to a
// keyframe's origin or tip, or magnitude. Distances are reported in this unit.
double extent(const KeyframeTriple& k);

}  // namespace pita::analysis
