#include "analysis/pose_audit_report.hpp"

#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace pita::analysis {

namespace pose_report {

using Json = nlohmann::ordered_json;

std::string id(PoseMethod m) { return std::string(info(m).id); }
std::string id(PoseProperty p) { return std::string(info(p).id); }

std::string csv_text(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

template <class Pose>
Json pose_json(const Pose& P) {
  Json rows = Json::array();
  for (int i = 0; i < P.L.rows(); ++i) {
    Json row = Json::array();
    for (int j = 0; j < P.L.cols(); ++j) row.push_back(P.L(i, j));
    row.push_back(P.b[i]);
    rows.push_back(row);
  }
  return rows;
}

template <class Pose>
Json triple_json(const PoseAuditConfig<Pose>& config) {
  Json out = Json::array();
  for (const TimedPoseOf<Pose>& p : config.poses) out.push_back(Json{{"t", p.t}, {"matrix", pose_json(p.pose)}});
  return out;
}

Json configuration_json(const PoseAuditReport& report, const PoseAuditCell& cell) {
  const auto index = static_cast<std::size_t>(cell.worst_config);
  Json config{{"index", cell.worst_config}, {"name", report.config_name(cell.dimension, cell.worst_config)}};
  config["poses"] = cell.dimension == 2 ? triple_json(report.plane.at(index)) : triple_json(report.space.at(index));
  if (cell.worst.t && std::isfinite(*cell.worst.t)) config["t"] = *cell.worst.t;
  config["relation"] = cell.worst.relation;
  Json parameters = Json::object();
  for (const auto& [name, value] : cell.worst.parameters) parameters[name] = value;
  config["parameters"] = parameters;
  if (!cell.worst.note.empty()) config["note"] = cell.worst.note;
  return config;
}

Json cell_json(const PoseAuditReport& report, const PoseAuditCell& cell) {
  Json j{{"dimension", cell.dimension},
         {"method", id(cell.method)},
         {"property", id(cell.property)},
         {"holds", cell.holds}};
  j["value"] = std::isfinite(cell.value) ? Json(cell.value) : Json(nullptr);
  if (cell.property == PoseProperty::exists) {
    j["share_by_mix"] =
        Json{{"tame", cell.share_by_mix[0]}, {"wild", cell.share_by_mix[1]}, {"near-singular", cell.share_by_mix[2]}};
  }
  if (cell.property == PoseProperty::steady) j["largest"] = cell.largest;
  if (info(cell.property).verdict == PoseVerdict::deviation) j["near_singular"] = cell.near_singular;
  j["measured"] = cell.measured;
  if (cell.worst_config >= 0) j["configuration"] = configuration_json(report, cell);
  return j;
}

std::string pose_audit_json(const PoseAuditReport& report) {
  Json j;
  j["seed"] = report.options.seed;
  j["configs"] = report.options.configs;
  j["crafted"] = static_cast<int>(crafted_pose_configs<Affine2>().size());
  j["dimensions"] = report.dimensions;
  j["methods"] = Json::array();
  for (PoseMethod m : report.methods) j["methods"].push_back(id(m));
  j["properties"] = Json::array();
  for (PoseProperty p : report.properties) {
    const PosePropertyInfo& pi = info(p);
    const char* holds = pi.verdict == PoseVerdict::share      ? "share == 1"
                        : pi.verdict == PoseVerdict::reaction ? "smallest value > threshold"
                        : pi.verdict == PoseVerdict::deviation
                            ? "largest value <= threshold"
                            : "every value <= threshold * max(1, mean |w|); the value is the median";
    j["properties"].push_back(Json{{"id", pi.id},
                                   {"fig10", pi.fig10},
                                   {"measure", pi.measure},
                                   {"holds_when", holds},
                                   {"threshold", pi.threshold}});
  }
  j["cells"] = Json::array();
  for (const PoseAuditCell& c : report.cells) j["cells"].push_back(cell_json(report, c));
  return j.dump(2) + "\n";
}

std::string pose_audit_csv(const PoseAuditReport& report) {
  std::string out = "dimension,method,property,holds,value,measured,config,t\n";
  for (const PoseAuditCell& c : report.cells) {
    const bool timed = c.worst.t && std::isfinite(*c.worst.t);
    out += fmt::format("{},{},{},{},{:.6g},{},{},{}\n", c.dimension, id(c.method), id(c.property),
                       c.holds ? "true" : "false", c.value, c.measured,
                       csv_text(report.config_name(c.dimension, c.worst_config)),
                       timed ? fmt::format("{:.17g}", *c.worst.t) : "");
  }
  return out;
}

std::string pose_audit_markdown(const PoseAuditReport& report) {
  std::string out = fmt::format("# pita audit poses: seed {}, {} random triples per dimension (+{} crafted)\n",
                                report.options.seed, report.options.configs, crafted_pose_configs<Affine2>().size());
  for (int d : report.dimensions) {
    out +=
        fmt::format("\n## {}D ({})\n\n| method |", d, d == 2 ? PoseTraits<Affine2>::noun : PoseTraits<Affine3>::noun);
    for (PoseProperty p : report.properties) out += fmt::format(" {} |", id(p));
    out += "\n|---|";
    for (std::size_t i = 0; i < report.properties.size(); ++i) out += "---|";
    out += "\n";
    for (PoseMethod m : report.methods) {
      out += fmt::format("| {} |", id(m));
      for (PoseProperty p : report.properties) out += fmt::format(" {} |", pose_cell_text(report.cell(d, m, p), true));
      out += "\n";
    }
  }
  out +=
      "\nyes/no: the property holds / fails, with the worst value measured; exists: the share of random triples "
      "with a real motion; steady: the median ARA (docs/reference/audit.md says what each measures).\n";
  out += "\n## Where each property fails\n\n";
  for (const PoseAuditCell& c : report.cells) {
    if (c.holds || c.worst_config < 0) continue;
    out += fmt::format("- {}D {} {}: {:.3g} on {}{}{}\n", c.dimension, id(c.method), id(c.property),
                       c.property == PoseProperty::exists ? c.largest : c.worst.value,
                       report.config_name(c.dimension, c.worst_config),
                       c.worst.t && std::isfinite(*c.worst.t) ? fmt::format(" at t = {:.6g}", *c.worst.t) : "",
                       c.worst.note.empty() ? "" : " (" + c.worst.note + ")");
  }
  return out;
}

}  // namespace pose_report

std::string pose_cell_text(const PoseAuditCell& cell, bool bold) {
  const std::string verdict = cell.holds ? "yes" : bold ? "**no**" : "no";
  if (cell.property == PoseProperty::exists) return fmt::format("{:.0f}%", 100.0 * cell.value);
  if (cell.measured == 0) return verdict + " (not measured)";
  return fmt::format("{} {:.1e}", verdict, cell.value);
}

std::string format_pose_audit(const PoseAuditReport& report, AuditFormat format) {
  if (format == AuditFormat::json) return pose_report::pose_audit_json(report);
  if (format == AuditFormat::csv) return pose_report::pose_audit_csv(report);
  return pose_report::pose_audit_markdown(report);
}

}  // namespace pita::analysis
