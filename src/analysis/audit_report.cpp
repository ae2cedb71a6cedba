#include "analysis/audit_report.hpp"

#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "analysis/paper_table.hpp"
#include "scene/arrow_json.hpp"

namespace pita::analysis {

namespace {

using Json = nlohmann::ordered_json;

std::string id(Method m) { return std::string(info(m).id); }
std::string id(Property p) { return std::string(info(p).id); }

// A keyframe: its time, then its arrow.
Json keyframe_json(const Keyframe& k) {
  Json keyframe{{"t", k.t}};
  keyframe.update(scene::arrow_json(k.arrow));
  return keyframe;
}

Json keyframes_json(const KeyframeTriple& k) {
  return Json::array({keyframe_json(k.a), keyframe_json(k.b), keyframe_json(k.c)});
}

// A CSV field, quoted (RFC 4180) when it holds a comma, a quote or a newline.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

bool finite_time(const Probe& probe) { return probe.t && std::isfinite(*probe.t); }

std::string where(const AuditReport& report, const AuditCell& cell) {
  if (cell.worst_config < 0) return "";
  return report.configs[static_cast<std::size_t>(cell.worst_config)].name;
}

Json cell_json(const AuditReport& report, const AuditCell& cell, const std::string& counterexample) {
  Json j{{"method", id(cell.method)}, {"property", id(cell.property)}, {"holds", cell.holds}};
  j["violation"] = std::isfinite(cell.value) ? Json(cell.value) : Json(nullptr);
  j["measured"] = cell.measured;
  if (cell.worst_config >= 0) {
    Json config{{"index", cell.worst_config},
                {"name", where(report, cell)},
                {"keyframes", keyframes_json(cell.worst.original)}};
    if (cell.worst.counterpart) config["counterpart"] = keyframes_json(*cell.worst.counterpart);
    if (finite_time(cell.worst)) config["t"] = *cell.worst.t;
    config["relation"] = cell.worst.relation;
    Json parameters = Json::object();
    for (const auto& [name, value] : cell.worst.parameters) parameters[name] = value;
    config["parameters"] = parameters;
    if (!cell.worst.note.empty()) config["note"] = cell.worst.note;
    j["configuration"] = config;
  }
  if (!counterexample.empty()) j["counterexample"] = counterexample;
  return j;
}

// The counterexample file of cell i, or "".
std::string file_of(const std::vector<std::string>& counterexamples, std::size_t i) {
  return i < counterexamples.size() ? counterexamples[i] : std::string();
}

// The paper's table (Fig. 10) and where the measurement disagrees with it.
Json paper_json(const AuditReport& report) {
  Json paper;
  paper["source"] = "PITA paper, Fig. 10 and Sec. 3.3, 4.1-4.11 (P1-P8 only)";
  paper["table"] = Json::array();
  for (const PrintedRow& row : printed_table()) {
    Json methods = Json::array();
    for (Method m : row.printed) methods.push_back(id(m));
    paper["table"].push_back(Json{{"property", id(row.property)}, {"printed", methods}, {"source", row.source}});
  }
  paper["disagreements"] = Json::array();
  for (const Disagreement& d : disagreements(report)) {
    paper["disagreements"].push_back(Json{{"method", id(d.method)},
                                          {"property", id(d.property)},
                                          {"printed", d.printed},
                                          {"measured", d.measured},
                                          {"reason", d.reason}});
  }
  return paper;
}

std::string audit_json(const AuditReport& report, const std::vector<std::string>& counterexamples) {
  Json j;
  j["seed"] = report.options.seed;
  j["configs"] = report.options.configs;
  j["crafted"] = static_cast<int>(crafted_configs().size());
  j["methods"] = Json::array();
  for (Method m : report.methods) j["methods"].push_back(id(m));
  j["properties"] = Json::array();
  for (Property p : report.properties) {
    const PropertyInfo& pi = info(p);
    j["properties"].push_back(
        Json{{"id", pi.id},
             {"letter", pi.letter},
             {"section", pi.section},
             {"measure", pi.measure},
             {"holds_when", pi.reaction ? "smallest value > threshold" : "largest value <= threshold"},
             {"threshold", pi.threshold}});
  }
  j["cells"] = Json::array();
  for (std::size_t i = 0; i < report.cells.size(); ++i) {
    j["cells"].push_back(cell_json(report, report.cells[i], file_of(counterexamples, i)));
  }
  j["paper"] = paper_json(report);
  return j.dump(2) + "\n";
}

std::string audit_csv(const AuditReport& report, const std::vector<std::string>& counterexamples) {
  std::string out = "method,property,holds,violation,measured,config,t,counterexample\n";
  for (std::size_t i = 0; i < report.cells.size(); ++i) {
    const AuditCell& c = report.cells[i];
    const bool timed = c.worst.t && std::isfinite(*c.worst.t);
    out += fmt::format("{},{},{},{:.6g},{},{},{},{}\n", id(c.method), id(c.property), c.holds ? "true" : "false",
                       c.value, c.measured, csv_field(where(report, c)),
                       timed ? fmt::format("{:.17g}", *c.worst.t) : "", csv_field(file_of(counterexamples, i)));
  }
  return out;
}

// Markdown: Fig. 10's layout, methods as rows, then the numbers.
std::string audit_markdown(const AuditReport& report, const std::vector<std::string>& counterexamples) {
  std::string out = fmt::format("# pita audit: seed {}, {} random configurations (+{} crafted)\n\n",
                                report.options.seed, report.options.configs, crafted_configs().size());
  out += "| method |";
  for (Property p : report.properties) out += fmt::format(" {} |", id(p));
  out += "\n|---|";
  for (std::size_t i = 0; i < report.properties.size(); ++i) out += "---|";
  out += "\n";
  for (Method m : report.methods) {
    out += fmt::format("| {} |", id(m));
    for (Property p : report.properties) {
      const AuditCell& c = report.cell(m, p);
      const std::optional<bool> said = printed(m, p);
      const bool differs = said && *said != c.holds;
      out += fmt::format(" {}{} {:.1e} |", c.holds ? "yes" : "**no**", differs ? " (≠ paper)" : "", c.value);
    }
    out += "\n";
  }
  out +=
      "\nyes/no: the property holds / fails; the number is the worst measured value (docs/reference/audit.md "
      "says what each measures); \"≠ paper\": Fig. 10 or the text says otherwise.\n";
  const std::vector<Disagreement> diffs = disagreements(report);
  if (!diffs.empty()) {
    out += "\n## Where the measurement disagrees with the paper\n\n";
    for (const Disagreement& d : diffs) {
      out += fmt::format("- {} {}: printed {}, measured {}. {}\n", id(d.method), id(d.property),
                         d.printed ? "yes" : "no", d.measured ? "yes" : "no", d.reason);
    }
  }
  out += "\n## Counterexamples\n\n";
  for (std::size_t i = 0; i < report.cells.size(); ++i) {
    const AuditCell& c = report.cells[i];
    if (c.holds || c.worst_config < 0) continue;
    const std::string file = file_of(counterexamples, i);
    out += fmt::format("- {} {}: {:.3g} on {}{}{}\n", id(c.method), id(c.property), c.value, where(report, c),
                       finite_time(c.worst) ? fmt::format(" at t = {:.6g}", *c.worst.t) : "",
                       file.empty() ? "" : fmt::format(" ({})", file));
  }
  return out;
}

}  // namespace

std::string counterexample_name(const AuditCell& cell) { return id(cell.method) + "-" + id(cell.property) + ".json"; }

std::string format_audit(const AuditReport& report, AuditFormat format,
                         const std::vector<std::string>& counterexamples) {
  if (format == AuditFormat::json) return audit_json(report, counterexamples);
  if (format == AuditFormat::csv) return audit_csv(report, counterexamples);
  return audit_markdown(report, counterexamples);
}

std::string counterexample_scene(const AuditReport& report, const AuditCell& cell) {
  if (cell.holds || cell.worst_config < 0) return "";
  const PropertyInfo& p = info(cell.property);
  const Probe& w = cell.worst;
  std::string check = w.relation;
  for (const auto& [name, value] : w.parameters) check += fmt::format("; {} = {:.17g}", name, value);
  // The swapped keyframes of PITA Eq. 42 come in the order P(b, B, a, A, c, C, t)
  // takes them: the counterpart panel keeps that order ("knots": "as-given",
  // docs/paper-notes.md N41).
  const bool two = w.counterpart.has_value();
  const bool swapped = cell.property == Property::order_independent;
  std::string replay = "pita eval THIS.json --t T gives the original's frames";
  if (two) replay += ", pita eval THIS.json --panel 1 --t T the counterpart's";
  if (two && swapped) replay += " (P(b, B, a, A, c, C, t): its keyframes in the order given)";
  Json j;
  j["description"] = fmt::format(
      "pita audit (seed {}, {} configurations): {} is not {} (PITA Sec. {}). Measured {:.6g} on configuration {} "
      "({}){}; {} (threshold {:g}). Compared: {}. Replay: {}.",
      report.options.seed, report.options.configs, id(cell.method), p.id, p.section, cell.value, cell.worst_config,
      where(report, cell), finite_time(w) ? fmt::format(" at t = {:.17g}", *w.t) : "", p.measure, p.threshold, check,
      replay);
  j["title"] = fmt::format("{} is not {}: {:.3g}", id(cell.method), p.id, cell.value);
  j["method"] = id(cell.method);
  j["keyframes"] = keyframes_json(w.original);
  j["samples"] = 17;
  j["canvas"] = Json{{"width", two ? 1000 : 600}, {"height", 500}, {"columns", two ? 2 : 1}};
  j["layers"] = Json::array({Json{{"type", "trajectory"}, {"point", "p"}, {"color", "gray"}}, Json{{"type", "pattern"}},
                             Json{{"type", "keyframes"}}});
  Json panels = Json::array();
  panels.push_back(Json{{"title", "original"}, {"keyframes", keyframes_json(w.original)}});
  if (two) {
    Json counterpart{{"title", swapped ? "counterpart: first two keyframes swapped" : "counterpart"},
                     {"keyframes", keyframes_json(*w.counterpart)}};
    if (swapped) counterpart["options"] = Json{{"knots", "as-given"}};
    panels.push_back(counterpart);
  }
  j["panels"] = panels;
  return j.dump(2) + "\n";
}

}  // namespace pita::analysis
