#include "analysis/audit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <exception>
#include <mutex>
#include <thread>

#include <fmt/format.h>

namespace pita::analysis {

namespace {

AuditCell measure_cell(Method method, Property property, const std::vector<AuditConfig>& configs,
                       std::uint64_t seed, const std::atomic<bool>* stop) {
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
    const std::uint64_t stream = stream_seed(seed, 2 + static_cast<std::uint64_t>(property),
                                             static_cast<std::uint64_t>(config.index));
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
    throw std::invalid_argument(
        fmt::format("the number of configurations must be between 1 and {} (got {})", kMaxAuditConfigs, options.configs));
  }
  AuditReport report;
  report.options = options;
  report.methods = options.methods.empty() ? default_audit_methods() : options.methods;
  for (Method m : report.methods) {
    if (info(m).keyframe_count != 3) {
      throw std::invalid_argument(fmt::format("{} takes {} keyframes; the properties of Sec. 4 are defined for "
                                              "methods through three", info(m).id, info(m).keyframe_count));
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

  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t jobs = std::min<std::size_t>(options.jobs > 0 ? static_cast<std::size_t>(options.jobs) : cores, total);
  std::atomic<std::size_t> next{0};
  std::atomic<int> done{0};
  // The first exception of any thread (an interruption, or out of memory) is
  // rethrown here once every thread has stopped; the others then stop early.
  std::atomic<bool> failed{false};
  std::exception_ptr first_error;
  std::mutex error_lock;
  const auto work = [&] {
    try {
      for (std::size_t i = next++; i < total && !failed; i = next++) {
        const Method m = report.methods[i / report.properties.size()];
        const Property p = report.properties[i % report.properties.size()];
        report.cells[i] = measure_cell(m, p, report.configs, options.seed, options.stop);
        const int finished = ++done;
        if (options.progress) options.progress(finished, static_cast<int>(total));
      }
    } catch (...) {
      const std::lock_guard<std::mutex> lock(error_lock);
      if (!first_error) first_error = std::current_exception();
      failed = true;
    }
  };
  std::vector<std::thread> threads;
  for (std::size_t j = 1; j < jobs; ++j) threads.emplace_back(work);
  work();
  for (std::thread& t : threads) t.join();
  if (first_error) std::rethrow_exception(first_error);
  return report;
}

}  // namespace pita::analysis
