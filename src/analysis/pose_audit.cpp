#include "analysis/pose_audit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>

#include "core/worker_pool.hpp"

namespace pita::analysis {

namespace pose_cells {

// Which triples a property is measured on: "exists" counts the random ones;
// knot control, a reaction, only tame and wild ones (near a singular triple a
// reaction can be as small as one likes, N36); the others every triple where
// the motion exists.
template <class Pose>
bool measured_on(PoseProperty property, const PoseAuditConfig<Pose>& config) {
  if (property == PoseProperty::exists) return config.mix != ConfigMix::crafted;
  if (info(property).verdict == PoseVerdict::reaction) {
    return config.mix == ConfigMix::tame || config.mix == ConfigMix::wild;
  }
  return true;
}

// Whether a triple decides the verdict: the deviations of near-singular
// triples (a pose with a singular value down to 1e-3, neighbours turned by
// almost pi, ...) are rounding amplified by their conditioning; they are
// reported apart (PoseAuditCell::near_singular), not judged.
template <class Pose>
bool judged_on(PoseProperty property, const PoseAuditConfig<Pose>& config) {
  return info(property).verdict != PoseVerdict::deviation || config.mix != ConfigMix::near_singular;
}

int mix_slot(ConfigMix mix) { return mix == ConfigMix::tame ? 0 : mix == ConfigMix::wild ? 1 : 2; }

// The share cell: the share of random triples where the motion exists.
template <class Pose>
void measure_existence(PoseAuditCell& cell, const std::vector<PoseAuditConfig<Pose>>& configs,
                       const std::atomic<bool>* stop) {
  std::array<int, 3> built{0, 0, 0}, total{0, 0, 0};
  for (const PoseAuditConfig<Pose>& config : configs) {
    if (stop != nullptr && stop->load()) throw AuditStopped{};
    if (!measured_on(PoseProperty::exists, config)) continue;
    PoseProbe probe = probe_pose(PoseProperty::exists, cell.method, config.poses, 0);
    const int slot = mix_slot(config.mix);
    ++total[slot], ++cell.measured;
    if (probe.value == 0.0) {
      ++built[slot];
    } else if (cell.worst_config < 0) {
      cell.worst_config = config.index, cell.worst = std::move(probe);
    }
  }
  const int all = total[0] + total[1] + total[2], exists = built[0] + built[1] + built[2];
  for (int i = 0; i < 3; ++i) cell.share_by_mix[i] = total[i] > 0 ? static_cast<double>(built[i]) / total[i] : 1.0;
  cell.value = all > 0 ? static_cast<double>(exists) / all : 1.0;
  cell.largest = 1.0 - cell.value;
  cell.holds = exists == all;
}

template <class Pose>
PoseAuditCell measure_cell(int dimension, PoseMethod method, PoseProperty property,
                           const std::vector<PoseAuditConfig<Pose>>& configs, std::uint64_t seed,
                           const std::atomic<bool>* stop) {
  const PosePropertyInfo& p = info(property);
  PoseAuditCell cell;
  cell.dimension = dimension, cell.method = method, cell.property = property;
  if (property == PoseProperty::exists) {
    measure_existence(cell, configs, stop);
    return cell;
  }
  std::vector<double> values;
  double worst = 0.0;  // the verdict's number: the value, or value / scale for steadiness
  for (const PoseAuditConfig<Pose>& config : configs) {
    if (stop != nullptr && stop->load()) throw AuditStopped{};
    if (!measured_on(property, config)) continue;
    const std::uint64_t stream =
        stream_seed(seed, 200 + 10 * static_cast<std::uint64_t>(dimension) + static_cast<std::uint64_t>(property),
                    static_cast<std::uint64_t>(config.index));
    PoseProbe probe = probe_pose(property, method, config.poses, stream);
    if (std::isnan(probe.value)) continue;  // no motion here: "exists" reports it
    if (!judged_on(property, config)) {
      cell.near_singular = std::max(cell.near_singular, probe.value);
      continue;
    }
    const double judged = probe.value / probe.scale;
    const bool first = values.empty();
    values.push_back(probe.value);
    if (first || (p.verdict == PoseVerdict::reaction ? judged < worst : judged > worst)) {
      worst = judged, cell.worst_config = config.index, cell.worst = std::move(probe);
    }
  }
  cell.measured = static_cast<int>(values.size());
  if (values.empty()) {
    cell.holds = false;
    return cell;
  }
  cell.largest = *std::max_element(values.begin(), values.end());
  if (p.verdict == PoseVerdict::steadiness) {
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    cell.value = values[values.size() / 2];
  } else {
    cell.value = worst;
  }
  cell.holds = p.verdict == PoseVerdict::reaction ? worst > p.threshold : worst <= p.threshold;
  return cell;
}

}  // namespace pose_cells

bool pose_auditable(PoseMethod method) {
  const PoseMethodInfo& m = info(method);
  return m.in_space && m.min_poses <= 3 && m.max_poses >= 3;
}

std::vector<PoseMethod> default_pose_audit_methods() {
  std::vector<PoseMethod> out;
  for (const PoseMethodInfo& m : all_pose_methods()) {
    if (pose_auditable(m.method) && m.method != PoseMethod::linear) out.push_back(m.method);
  }
  return out;
}

const PoseAuditCell& PoseAuditReport::cell(int dimension, PoseMethod m, PoseProperty p) const {
  for (const PoseAuditCell& c : cells) {
    if (c.dimension == dimension && c.method == m && c.property == p) return c;
  }
  throw std::out_of_range("no such cell in the pose audit");
}

std::string PoseAuditReport::config_name(int dimension, int index) const {
  if (index < 0) return "";
  return dimension == 2 ? plane.at(static_cast<std::size_t>(index)).name
                        : space.at(static_cast<std::size_t>(index)).name;
}

PoseAuditReport run_pose_audit(const PoseAuditOptions& options) {
  if (options.configs < 1 || options.configs > kMaxAuditConfigs) {
    throw std::invalid_argument(fmt::format("the number of configurations must be between 1 and {} (got {})",
                                            kMaxAuditConfigs, options.configs));
  }
  PoseAuditReport report;
  report.options = options;
  report.dimensions = options.dimensions.empty() ? std::vector<int>{2, 3} : options.dimensions;
  for (int d : report.dimensions) {
    if (d != 2 && d != 3) throw std::invalid_argument(fmt::format("the dimension must be 2 or 3 (got {})", d));
  }
  report.methods = options.methods.empty() ? default_pose_audit_methods() : options.methods;
  for (PoseMethod m : report.methods) {
    if (!pose_auditable(m)) {
      throw std::invalid_argument(
          fmt::format("{} is not a pose method of both dimensions through three poses", info(m).id));
    }
  }
  for (const PosePropertyInfo& p : all_pose_properties()) report.properties.push_back(p.property);
  for (int d : report.dimensions) {
    if (d == 2) report.plane = pose_audit_configs<Affine2>(options.seed, options.configs);
    if (d == 3) report.space = pose_audit_configs<Affine3>(options.seed, options.configs);
  }
  const std::size_t per_dimension = report.methods.size() * report.properties.size();
  const std::size_t total = report.dimensions.size() * per_dimension;
  report.cells.resize(total);
  PoolOptions pool;
  pool.threads = options.jobs > 0 ? options.jobs : static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  run_ordered(
      static_cast<std::int64_t>(total), pool,
      [&](std::int64_t index, const std::atomic<bool>&) {
        const auto i = static_cast<std::size_t>(index);
        const int d = report.dimensions[i / per_dimension];
        const PoseMethod m = report.methods[i % per_dimension / report.properties.size()];
        const PoseProperty p = report.properties[i % report.properties.size()];
        return d == 2 ? pose_cells::measure_cell(d, m, p, report.plane, options.seed, options.stop)
                      : pose_cells::measure_cell(d, m, p, report.space, options.seed, options.stop);
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
