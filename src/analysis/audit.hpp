// `pita audit`: PITA Fig. 10 measured. For each method and each property of
// Sec. 4 (analysis/properties.hpp), the worst value over the crafted and
// random configurations of analysis/audit_configs.hpp, the verdict, and the
// configuration where the worst value was reached (the counterexample).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "analysis/audit_configs.hpp"
#include "analysis/properties.hpp"
#include "core/pitas/registry.hpp"

namespace pita::analysis {

inline constexpr int kDefaultAuditConfigs = 200;
inline constexpr int kMaxAuditConfigs = 1'000'000;

struct AuditOptions {
  std::vector<Method> methods;         // empty: default_audit_methods()
  std::vector<Property> properties;    // empty: every property
  int configs = kDefaultAuditConfigs;  // random configurations (crafted ones come on top)
  std::uint64_t seed = 1;
  int jobs = 0;  // threads; 0: the number of cores
  // Called after each finished (method, property) cell with (done, total),
  // from any thread; may be empty.
  std::function<void(int, int)> progress;
  // Set from outside (an interrupt) to stop early; run_audit then throws
  // AuditStopped.
  const std::atomic<bool>* stop = nullptr;
};

struct AuditStopped {};

struct AuditCell {
  Method method = Method::P1;
  Property property = Property::exists;
  bool holds = true;
  double value = 0.0;     // the worst value (largest deviation, smallest reaction, share not built)
  int measured = 0;       // configurations where the property could be measured
  int worst_config = -1;  // index into AuditReport::configs, -1 if none
  Probe worst;            // the measurement at worst_config
};

struct AuditReport {
  AuditOptions options;
  std::vector<Method> methods;
  std::vector<Property> properties;
  std::vector<AuditConfig> configs;
  std::vector<AuditCell> cells;  // methods x properties, method-major
  const AuditCell& cell(Method m, Property p) const;
};

// Every arrow method that takes three keyframes: P1-P10, P5S and the
// independent combinations of Fig. 7 (the registry's order), not the
// appendices' variants (He-G, La-T1, La-T2, Ne-M), which --methods can name.
std::vector<Method> default_audit_methods();

// Runs the audit. Deterministic for a given seed and configuration count,
// whatever `jobs`. Throws std::invalid_argument for a method that does not
// take three keyframes or a count outside [1, kMaxAuditConfigs].
AuditReport run_audit(const AuditOptions& options);

}  // namespace pita::analysis
