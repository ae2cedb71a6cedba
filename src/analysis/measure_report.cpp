#include "analysis/measure_report.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <set>
#include <string_view>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/overloaded.hpp"

namespace pita::analysis {

namespace {

using Json = nlohmann::ordered_json;

// Shortest round-trip form; the measures are finite (analysis/measure.hpp).
std::string report_number(double x) { return fmt::format("{}", x); }

// A string as JSON, escaped by nlohmann-json (bytes that are not UTF-8, from
// a file name, become U+FFFD).
std::string json_string(std::string_view text) {
  return Json(text).dump(-1, ' ', false, Json::error_handler_t::replace);
}

// `value` written on one line, ": " after each key and ", " between entries,
// numbers in report_number's form; but an array (the overreaction's
// parameters) one element to a line.
void write_json(const Json& value, std::string& out) {
  switch (value.type()) {
    case Json::value_t::object: {
      out += '{';
      const char* separator = "";
      for (const auto& [key, item] : value.items()) {
        out += separator + json_string(key) + ": ";
        write_json(item, out);
        separator = ", ";
      }
      out += '}';
      return;
    }
    case Json::value_t::array:
      out += '[';
      for (std::size_t i = 0; i < value.size(); ++i) {
        out += i ? ",\n       " : "\n       ";
        write_json(value[i], out);
      }
      out += ']';
      return;
    case Json::value_t::number_float:
      out += report_number(value.get<double>());
      return;
    case Json::value_t::string:
      out += json_string(value.get_ref<const std::string&>());
      return;
    default:
      out += value.dump();
      return;  // integers and booleans
  }
}

// The overreaction to each keyframe parameter, the most sensitive one first.
Json overreaction_json(const ArrowMeasures& m) {
  Json overreaction = Json::object();
  if (m.most_sensitive >= 0) {
    const auto& best = m.parameters[static_cast<std::size_t>(m.most_sensitive)];
    overreaction["most_sensitive"] = best.name;
    overreaction["gain"] = best.gain;
  }
  Json parameters = Json::array();
  for (const auto& p : m.parameters) {
    parameters.push_back(Json{{"name", p.name},
                              {"defined", p.defined},
                              {"gain", p.gain},
                              {"turn", p.turn},
                              {"jump", p.jump},
                              {"pop", p.pop}});
  }
  overreaction["parameters"] = std::move(parameters);
  return overreaction;
}

Json path_json(const PathStats& path) {
  return Json{{"length", path.length}, {"turning", path.turning}, {"inflections", path.inflections}};
}

// The members of each kind's measures, in the order they are written.
void add_json(const ArrowMeasures& m, Json& j) {
  j["samples"] = m.samples;
  j["extent"] = m.extent;
  Json discrepancy = Json::object();
  for (const auto& d : m.discrepancy) {
    discrepancy[d.predictor] = Json{{"frames", d.frames}, {"max", d.max}, {"mean", d.mean}, {"t_of_max", d.t_of_max}};
  }
  j["discrepancy"] = std::move(discrepancy);
  j["path"] = Json{{"p", path_json(m.path_p)}, {"q", path_json(m.path_q)}};
  j["winding"] = Json{{"min", m.winding_min}, {"max", m.winding_max}};
  j["overreaction"] = overreaction_json(m);
  j["pop"] = Json{{"detected", m.pops}};
  if (m.largest_jump >= 0) {
    const auto& worst = m.parameters[static_cast<std::size_t>(m.largest_jump)];
    j["pop"]["parameter"] = worst.name;
    j["pop"]["jump"] = worst.jump;
  }
}

void add_json(const PointMeasures& m, Json& j) { j["path"] = Json{{"p", path_json(m.path)}}; }

template <class Pose>
void add_json(const PoseMeasures<Pose>& m, Json& j) {
  j["ara"] = m.ara;
  j["velocity_jump"] = m.velocity_jump;
  j[std::string(m.det_name)] = Json{{"monotone", m.area.monotone},
                                    {"excursion", m.area.excursion},
                                    {"t_of_excursion", m.area.t_of_excursion},
                                    {"first", m.area.first},
                                    {"last", m.area.last}};
}

// A motion's measures, each present only where it applies, in the order they are written.
Json motion_json(const MotionMeasures& m) {
  Json j{
      {"pointer", m.pointer}, {"title", m.title}, {"method", m.method}, {"kind", std::string(measured_kind_name(m))}};
  if (m.no_motion) {
    j["no_motion"] = *m.no_motion;
    return j;
  }
  std::visit([&](const auto& measured) { add_json(measured, j); }, m.measured);
  return j;
}

// The members of a motion that begin a line of their own.
bool on_own_line(std::string_view key) {
  constexpr std::array<std::string_view, 9> kKeys = {"discrepancy", "path",          "winding", "overreaction", "pop",
                                                     "ara",         "velocity_jump", "area",    "volume"};
  return std::find(kKeys.begin(), kKeys.end(), key) != kKeys.end();
}

std::string json_motion(const MotionMeasures& m) {
  std::string s = "    {";
  bool first = true;
  const Json motion = motion_json(m);  // named: items() of a temporary would outlive it
  for (const auto& [key, item] : motion.items()) {
    if (!first) s += on_own_line(key) ? ",\n     " : ", ";
    first = false;
    s += json_string(key) + ": ";
    write_json(item, s);
  }
  return s + "}";
}

}  // namespace

std::string measures_json(const std::string& path, const std::vector<MotionMeasures>& all) {
  std::string s = "{\"scene\": " + json_string(path) + ", \"motions\": [\n";
  for (std::size_t i = 0; i < all.size(); ++i) s += json_motion(all[i]) + (i + 1 < all.size() ? ",\n" : "\n");
  return s + "]}\n";
}

namespace {

// A CSV field (RFC 4180): quoted when it holds a comma, a quote or a line break.
std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\n\r") == std::string_view::npos) return std::string(text);
  std::string out = "\"";
  for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

namespace {

// The cells of a kind's measures, from "samples" to "velocity_jump" (27 columns).
constexpr std::size_t kMeasureColumns = 29;
using MeasureCells = std::vector<std::string>;

std::string yes_no(bool value) { return value ? "true" : "false"; }

MeasureCells csv_cells(const ArrowMeasures& m) {
  MeasureCells row{std::to_string(m.samples), report_number(m.extent)};
  for (std::size_t i = 0; i < 3; ++i) {
    const bool has = m.discrepancy.size() > i && m.discrepancy[i].frames > 0;
    row.push_back(has ? report_number(m.discrepancy[i].max) : "");
    row.push_back(has ? report_number(m.discrepancy[i].mean) : "");
    row.push_back(has ? report_number(m.discrepancy[i].t_of_max) : "");
  }
  for (const PathStats& path : {m.path_p, m.path_q}) {
    row.push_back(report_number(path.length));
    row.push_back(report_number(path.turning));
    row.push_back(std::to_string(path.inflections));
  }
  row.push_back(report_number(m.winding_min));
  row.push_back(report_number(m.winding_max));
  const auto* best = m.most_sensitive >= 0 ? &m.parameters[static_cast<std::size_t>(m.most_sensitive)] : nullptr;
  const auto* jump = m.largest_jump >= 0 ? &m.parameters[static_cast<std::size_t>(m.largest_jump)] : nullptr;
  row.push_back(best ? best->name : "");
  row.push_back(best ? report_number(best->gain) : "");
  row.push_back(yes_no(m.pops));
  row.push_back(jump ? jump->name : "");
  row.push_back(jump ? report_number(jump->jump) : "");
  row.resize(kMeasureColumns);  // no ARA, area or velocity jump
  return row;
}

MeasureCells csv_cells(const PointMeasures& m) {
  MeasureCells row(11);  // no samples, extent or discrepancy
  row.push_back(report_number(m.path.length));
  row.push_back(report_number(m.path.turning));
  row.push_back(std::to_string(m.path.inflections));
  row.resize(kMeasureColumns);  // no q, winding, overreaction, ARA or area
  return row;
}

template <class Pose>
MeasureCells csv_cells(const PoseMeasures<Pose>& m) {
  MeasureCells row(kMeasureColumns - 5);  // the measures of keyframes' paths and tweaks
  row.push_back(report_number(m.ara));
  row.push_back(yes_no(m.area.monotone));
  row.push_back(report_number(m.area.excursion));
  row.push_back(report_number(m.area.t_of_excursion));
  row.push_back(report_number(m.velocity_jump));
  return row;
}

}  // namespace

std::string measures_csv(const std::vector<MotionMeasures>& all) {
  // The union of the parameter names, in first-seen order.
  std::vector<std::string> names;
  std::set<std::string> seen;
  for (const auto& m : all) {
    for (const auto& p : parameters_of(m)) {
      if (seen.insert(p.name).second) names.push_back(p.name);
    }
  }
  std::string s =
      "pointer,title,method,kind,no_motion,samples,extent,"
      "previous_max,previous_mean,previous_t,average_max,average_mean,average_t,pita_max,pita_mean,pita_t,"
      "p_length,p_turning,p_inflections,q_length,q_turning,q_inflections,winding_min,winding_max,"
      "most_sensitive,most_sensitive_gain,pop,largest_jump_parameter,largest_jump,ara,area_monotone,area_excursion,"
      "area_t,velocity_jump";
  for (const auto& name : names) s += ",gain_" + name;
  s += '\n';
  for (const auto& m : all) {
    std::vector<std::string> row{csv_field(m.pointer), csv_field(m.title), csv_field(m.method),
                                 std::string(measured_kind_name(m)), csv_field(m.no_motion.value_or(""))};
    const MeasureCells cells = m.no_motion
                                   ? MeasureCells(kMeasureColumns)
                                   : std::visit([](const auto& measured) { return csv_cells(measured); }, m.measured);
    row.insert(row.end(), cells.begin(), cells.end());
    for (const auto& name : names) {
      std::string cell;
      for (const auto& p : parameters_of(m)) {
        if (p.name == name && p.defined) cell = report_number(p.gain);
      }
      row.push_back(cell);
    }
    for (std::size_t i = 0; i < row.size(); ++i) s += (i ? "," : "") + row[i];
    s += '\n';
  }
  return s;
}

namespace {

std::string md_cell(std::string_view text) {
  std::string out;
  for (const char c : text) out += c == '|' ? std::string("\\|") : c == '\n' ? std::string(" ") : std::string(1, c);
  return out;
}

std::string short_number(double x) { return fmt::format("{:.4g}", x); }

std::string report_panel_name(const MotionMeasures& m) {
  if (!m.title.empty()) return md_cell(m.title);
  return m.pointer.empty() ? std::string("(scene)") : md_cell(m.pointer);
}

}  // namespace

namespace {

// The cells of the table of paths: "E max prev / avg / pita" to "pop (jump)".
std::string path_row(const ArrowMeasures& m) {
  std::string max, mean;
  for (const auto& d : m.discrepancy) {
    max += (max.empty() ? "" : " / ") + (d.frames ? short_number(d.max) : std::string("-"));
    mean += (mean.empty() ? "" : " / ") + (d.frames ? short_number(d.mean) : std::string("-"));
  }
  std::string sensitive = "-";
  if (m.most_sensitive >= 0) {
    const auto& best = m.parameters[static_cast<std::size_t>(m.most_sensitive)];
    sensitive = fmt::format("{} ({})", best.name, short_number(best.gain));
  }
  std::string pop = m.pops ? "yes" : "no";
  if (m.largest_jump >= 0) {
    const auto& worst = m.parameters[static_cast<std::size_t>(m.largest_jump)];
    pop += fmt::format(" ({} {})", worst.name, short_number(worst.jump));
  }
  return fmt::format("{} | {} | {}, {} | {}, {} | {}, {} | [{}, {}] | {} | {}", max.empty() ? "-" : max,
                     mean.empty() ? "-" : mean, short_number(m.path_p.length), short_number(m.path_q.length),
                     short_number(m.path_p.turning), short_number(m.path_q.turning), m.path_p.inflections,
                     m.path_q.inflections, short_number(m.winding_min), short_number(m.winding_max), sensitive, pop);
}

std::string path_row(const PointMeasures& m) {
  return fmt::format("- | - | {} | {} | {} | - | - | -", short_number(m.path.length), short_number(m.path.turning),
                     m.path.inflections);
}

// The table of a kind of poses: "ARA" to "velocity jump".
template <class Pose>
std::string pose_row(const PoseMeasures<Pose>& m) {
  return fmt::format("{} | {} | {} (t = {}) | {}, {} | {}", short_number(m.ara), m.area.monotone ? "yes" : "no",
                     short_number(m.area.excursion), short_number(m.area.t_of_excursion), short_number(m.area.first),
                     short_number(m.area.last), short_number(m.velocity_jump));
}

// A table: its header, then a row for each measured motion that `cells`
// gives cells ("" for a motion of another table); "" when no motion has a row.
template <class Cells>
std::string md_table(const std::vector<MotionMeasures>& all, std::string_view header, Cells cells) {
  std::string rows;
  for (const auto& m : all) {
    if (m.no_motion) continue;
    const std::string row = std::visit(cells, m.measured);
    if (!row.empty()) rows += fmt::format("| {} | {} | {} |\n", report_panel_name(m), md_cell(m.method), row);
  }
  return rows.empty() ? std::string() : std::string(header) + rows + "\n";
}

// The table of the poses of one kind: det L an area for the plane, a volume for space.
template <class Pose>
std::string pose_table(const std::vector<MotionMeasures>& all) {
  const std::string header = fmt::format(
      "| panel | method | ARA | {} monotone | largest excursion (at t) | det L first, last | velocity jump |\n"
      "|---|---|---|---|---|---|---|\n",
      PoseMeasures<Pose>::det_name);
  return md_table(
      all, header,
      overloaded{[](const PoseMeasures<Pose>& m) { return pose_row(m); },
                 [](const ArrowMeasures&) { return std::string(); }, [](const PointMeasures&) { return std::string(); },
                 []<class Other>(const PoseMeasures<Other>&) { return std::string(); }});
}

// The table of paths (keyframes and points), then one per kind of poses.
std::string md_tables(const std::vector<MotionMeasures>& all) {
  constexpr std::string_view kPathHeader =
      "| panel | method | E max prev / avg / pita | E mean prev / avg / pita | length p, q | turning p, q (rad) "
      "| inflections p, q | winding range (rad) | most sensitive (gain) | pop (jump) |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n";
  return md_table(all, kPathHeader,
                  overloaded{[](const ArrowMeasures& m) { return path_row(m); },
                             [](const PointMeasures& m) { return path_row(m); },
                             []<class Pose>(const PoseMeasures<Pose>&) { return std::string(); }}) +
         pose_table<Affine2>(all) + pose_table<Affine3>(all);
}

// Overreaction gains, one column per arrow panel.
std::string md_gains(const std::vector<MotionMeasures>& all) {
  std::vector<const MotionMeasures*> reacting;
  for (const auto& m : all) {
    if (!parameters_of(m).empty()) reacting.push_back(&m);
  }
  if (reacting.empty()) return "";
  std::vector<std::string> names;
  std::set<std::string> seen;
  for (const auto* m : reacting) {
    for (const auto& p : parameters_of(*m)) {
      if (seen.insert(p.name).second) names.push_back(p.name);
    }
  }
  std::string s =
      "\nOverreaction gain per parameter (max frame displacement / extent per unit normalised tweak; "
      "* marks a pop):\n\n| parameter |";
  std::string rule = "|---|";
  for (const auto* m : reacting) {
    s += " " + report_panel_name(*m) + " |";
    rule += "---|";
  }
  s += "\n" + rule + "\n";
  for (const auto& name : names) {
    s += "| " + name + " |";
    for (const auto* m : reacting) {
      std::string cell = " ";
      for (const auto& p : parameters_of(*m)) {
        if (p.name != name) continue;
        cell = p.defined ? short_number(p.gain) : std::string("undefined");
        if (p.pop) cell += " *";
      }
      s += " " + cell + " |";
    }
    s += '\n';
  }
  return s;
}

}  // namespace

std::string measures_markdown(const std::string& path, const std::vector<MotionMeasures>& all) {
  std::string s = fmt::format("# pita measure {}\n\n", path) + md_tables(all);
  for (const auto& m : all) {
    if (m.no_motion) s += fmt::format("- {}: no motion: {}\n", report_panel_name(m), md_cell(*m.no_motion));
  }
  return s + md_gains(all);
}

}  // namespace pita::analysis
