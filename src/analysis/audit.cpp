#include "analysis/audit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>

#include "core/worker_pool.hpp"

namespace pita::analysis {

namespace {

AuditCell measure_cell(Method method, Property property, const std::vector<AuditConfig>& configs, std::uint64_t seed,
                       const std::atomic<bool>* stop) {
  const PropertyInfo& p = info(property);
  AuditCell cell;
  cell.method = method;
  cell.property = property;
  int failures = 0;
  bool first = true;
  for (const AuditConfig& config : configs) {
    if (stop != nullptr && stop->load()) throw AuditStopped{};
    // Configurations on a branch cut are for "exists" and "pop-free" only. A
    // reaction may be as small as one likes near a singular configuration, so
    // only tame and wild ones decide the reaction properties (N36).
    if (config.on_cut && property != Property::pop_free && property != Property::exists) continue;
    if (p.reaction && (config.mix == ConfigMix::crafted || config.mix == ConfigMix::near_singular)) continue;
    const std::uint64_t stream =
        stream_seed(seed, 2 + static_cast<std::uint64_t>(property), static_cast<std::uint64_t>(config.index));
    Probe probe = analysis::probe(property, method, config.keyframes, stream);
    if (property == Property::exists) {
      ++cell.measured;
      if (probe.value > 0.0) {
        if (failures++ == 0) cell.worst_config = config.index, cell.worst = std::move(probe);
      }
      continue;
    }
    if (std::isnan(probe.value)) continue;  // no motion here: "exists" reports it
    ++cell.measured;
    const bool worse = first || (p.reaction ? probe.value < cell.value : probe.value > cell.value);
    if (worse) {
      cell.value = probe.value;
      cell.worst_config = config.index;
      cell.worst = std::move(probe);
      first = false;
    }
  }
  if (property == Property::exists) {
    cell.value = static_cast<double>(failures) / static_cast<double>(std::max<std::size_t>(configs.size(), 1));
    cell.holds = failures == 0;
    if (failures == 0) cell.worst_config = -1;
    return cell;
  }
  cell.holds = cell.measured > 0 && (p.reaction ? cell.value > p.threshold : cell.value <= p.threshold);
  return cell;
}

}  // namespace

std::vector<Method> default_audit_methods() {
  std::vector<Method> out;
  for (const MethodInfo& m : all_methods()) {
    if (m.keyframe_count == 3 && !m.appendix_variant) out.push_back(m.method);
  }
  return out;
}

const AuditCell& AuditReport::cell(Method m, Property p) const {
  for (const AuditCell& c : cells) {
    if (c.method == m && c.property == p) return c;
  }
  throw std::out_of_range("no such cell in the audit");
}

AuditReport run_audit(const AuditOptions& options) {
  if (options.configs < 1 || options.configs > kMaxAuditConfigs) {
    throw std::invalid_argument(fmt::format("the number of configurations must be between 1 and {} (got {})",
                                            kMaxAuditConfigs, options.configs));
  }
  AuditReport report;
  report.options = options;
  report.methods = options.methods.empty() ? default_audit_methods() : options.methods;
  for (Method m : report.methods) {
    if (info(m).keyframe_count != 3) {
      throw std::invalid_argument(
          fmt::format("{} takes {} keyframes; the properties of Sec. 4 are defined for "
                      "methods through three",
                      info(m).id, info(m).keyframe_count));
    }
  }
  if (options.properties.empty()) {
    for (const PropertyInfo& p : all_properties()) report.properties.push_back(p.property);
  } else {
    report.properties = options.properties;
  }
  report.configs = audit_configs(options.seed, options.configs);
  const std::size_t total = report.methods.size() * report.properties.size();
  report.cells.resize(total);

  PoolOptions pool;
  pool.threads = options.jobs > 0 ? options.jobs : static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  // Cells in parallel; the progress is told on the calling thread.
  run_ordered(
      static_cast<std::int64_t>(total), pool,
      [&](std::int64_t i, const std::atomic<bool>&) {
        const Method m = report.methods[static_cast<std::size_t>(i) / report.properties.size()];
        const Property p = report.properties[static_cast<std::size_t>(i) % report.properties.size()];
        return measure_cell(m, p, report.configs, options.seed, options.stop);
      },
      [&](std::int64_t i, auto&& cell) {
        report.cells[static_cast<std::size_t>(i)] = std::move(cell);
        if (options.progress) options.progress(static_cast<int>(i + 1), static_cast<int>(total));
        return true;
      },
      [] { return true; });
  return report;
}

}  // namespace pita::analysis
