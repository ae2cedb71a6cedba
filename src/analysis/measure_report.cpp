#include "analysis/measure_report.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <set>
#include <string_view>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

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
    case Json::value_t::number_float: out += report_number(value.get<double>()); return;
    case Json::value_t::string: out += json_string(value.get_ref<const std::string&>()); return;
    default: out += value.dump(); return;  // integers and booleans
  }
}

// The overreaction to each keyframe parameter, the most sensitive one first.
Json overreaction_json(const MotionMeasures& m) {
  Json overreaction = Json::object();
  if (m.most_sensitive >= 0) {
    const auto& best = m.parameters[static_cast<std::size_t>(m.most_sensitive)];
    overreaction["most_sensitive"] = best.name;
    overreaction["gain"] = best.gain;
  }
  Json parameters = Json::array();
  for (const auto& p : m.parameters) {
    parameters.push_back(Json{{"name", p.name}, {"defined", p.defined}, {"gain", p.gain}, {"turn", p.turn},
                              {"jump", p.jump}, {"pop", p.pop}});
  }
  overreaction["parameters"] = std::move(parameters);
  return overreaction;
}

// A motion's measures, each present only where it applies, in the order they are written.
Json motion_json(const MotionMeasures& m) {
  Json j{{"pointer", m.pointer}, {"title", m.title}, {"method", m.method},
         {"kind", std::string(measured_kind_name(m.kind))}};
  if (m.no_motion) {
    j["no_motion"] = *m.no_motion;
    return j;
  }
  if (m.kind == MeasuredKind::arrows) {
    j["samples"] = m.samples;
    j["extent"] = m.extent;
    Json discrepancy = Json::object();
    for (const auto& d : m.discrepancy) {
      discrepancy[d.predictor] = Json{{"frames", d.frames}, {"max", d.max}, {"mean", d.mean}, {"t_of_max", d.t_of_max}};
    }
    j["discrepancy"] = std::move(discrepancy);
  }
  if (m.path_p) {
    j["path"] = Json{{"p", Json{{"length", m.path_p->length}, {"turning", m.path_p->turning}}}};
    if (m.path_q) j["path"]["q"] = Json{{"length", m.path_q->length}, {"turning", m.path_q->turning}};
  }
  if (m.winding_min) j["winding"] = Json{{"min", *m.winding_min}, {"max", *m.winding_max}};
  if (m.kind == MeasuredKind::arrows) {
    j["overreaction"] = overreaction_json(m);
    j["pop"] = Json{{"detected", m.pops}};
    if (m.largest_jump >= 0) {
      const auto& worst = m.parameters[static_cast<std::size_t>(m.largest_jump)];
      j["pop"]["parameter"] = worst.name;
      j["pop"]["jump"] = worst.jump;
    }
  }
  if (m.ara) j["ara"] = *m.ara;
  if (m.velocity_jump) j["velocity_jump"] = *m.velocity_jump;
  if (m.area) {
    // det L: the area of the plane's poses, the volume of poses of space.
    j[m.kind == MeasuredKind::space_poses ? "volume" : "area"] =
        Json{{"monotone", m.area->monotone}, {"excursion", m.area->excursion},
             {"t_of_excursion", m.area->t_of_excursion}, {"first", m.area->first}, {"last", m.area->last}};
  }
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

std::string measures_csv(const std::vector<MotionMeasures>& all) {
  // The union of the parameter names, in first-seen order.
  std::vector<std::string> names;
  std::set<std::string> seen;
  for (const auto& m : all) {
    for (const auto& p : m.parameters) {
      if (seen.insert(p.name).second) names.push_back(p.name);
    }
  }
  std::string s =
      "pointer,title,method,kind,no_motion,samples,extent,"
      "previous_max,previous_mean,previous_t,average_max,average_mean,average_t,pita_max,pita_mean,pita_t,"
      "p_length,p_turning,q_length,q_turning,winding_min,winding_max,"
      "most_sensitive,most_sensitive_gain,pop,largest_jump_parameter,largest_jump,ara,area_monotone,area_excursion,"
      "area_t,velocity_jump";
  for (const auto& name : names) s += ",gain_" + name;
  s += '\n';
  const auto opt = [](const std::optional<double>& x) { return x ? report_number(*x) : std::string(); };
  for (const auto& m : all) {
    std::vector<std::string> row{csv_field(m.pointer), csv_field(m.title), csv_field(m.method),
                                 std::string(measured_kind_name(m.kind)),
                                 csv_field(m.no_motion.value_or(""))};
    const bool arrows = m.kind == MeasuredKind::arrows && !m.no_motion;
    row.push_back(arrows ? std::to_string(m.samples) : "");
    row.push_back(arrows ? report_number(m.extent) : "");
    for (int i = 0; i < 3; ++i) {
      const bool has = arrows && m.discrepancy.size() > static_cast<std::size_t>(i) && m.discrepancy[i].frames > 0;
      row.push_back(has ? report_number(m.discrepancy[i].max) : "");
      row.push_back(has ? report_number(m.discrepancy[i].mean) : "");
      row.push_back(has ? report_number(m.discrepancy[i].t_of_max) : "");
    }
    row.push_back(m.path_p ? report_number(m.path_p->length) : "");
    row.push_back(m.path_p ? report_number(m.path_p->turning) : "");
    row.push_back(m.path_q ? report_number(m.path_q->length) : "");
    row.push_back(m.path_q ? report_number(m.path_q->turning) : "");
    row.push_back(opt(m.winding_min));
    row.push_back(opt(m.winding_max));
    const auto* best = m.most_sensitive >= 0 ? &m.parameters[static_cast<std::size_t>(m.most_sensitive)] : nullptr;
    const auto* jump = m.largest_jump >= 0 ? &m.parameters[static_cast<std::size_t>(m.largest_jump)] : nullptr;
    row.push_back(best ? best->name : "");
    row.push_back(best ? report_number(best->gain) : "");
    row.push_back(arrows ? (m.pops ? "true" : "false") : "");
    row.push_back(jump ? jump->name : "");
    row.push_back(jump ? report_number(jump->jump) : "");
    row.push_back(opt(m.ara));
    row.push_back(m.area ? (m.area->monotone ? "true" : "false") : "");
    row.push_back(m.area ? report_number(m.area->excursion) : "");
    row.push_back(m.area ? report_number(m.area->t_of_excursion) : "");
    row.push_back(opt(m.velocity_jump));
    for (const auto& name : names) {
      std::string cell;
      for (const auto& p : m.parameters) {
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

std::string measures_markdown(const std::string& path, const std::vector<MotionMeasures>& all) {
  std::string s = fmt::format("# pita measure {}\n\n", path);
  bool any_arrows = false;
  for (const auto& m : all) any_arrows = any_arrows || (!of_poses(m.kind) && !m.no_motion);
  if (any_arrows) {
    s += "| panel | method | E max prev / avg / pita | E mean prev / avg / pita | length p, q | turning p, q (rad) "
         "| winding range (rad) | most sensitive (gain) | pop (jump) |\n"
         "|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& m : all) {
      if (of_poses(m.kind) || m.no_motion) continue;
      std::string max, mean;
      for (const auto& d : m.discrepancy) {
        max += (max.empty() ? "" : " / ") + (d.frames ? short_number(d.max) : std::string("-"));
        mean += (mean.empty() ? "" : " / ") + (d.frames ? short_number(d.mean) : std::string("-"));
      }
      const std::string length = m.path_p ? short_number(m.path_p->length) + (m.path_q ? ", " + short_number(m.path_q->length) : "") : "-";
      const std::string turning =
          m.path_p ? short_number(m.path_p->turning) + (m.path_q ? ", " + short_number(m.path_q->turning) : "") : "-";
      const std::string winding =
          m.winding_min ? fmt::format("[{}, {}]", short_number(*m.winding_min), short_number(*m.winding_max)) : "-";
      std::string sensitive = "-", pop = "-";
      if (m.most_sensitive >= 0) {
        const auto& best = m.parameters[static_cast<std::size_t>(m.most_sensitive)];
        sensitive = fmt::format("{} ({})", best.name, short_number(best.gain));
      }
      if (m.kind == MeasuredKind::arrows) {
        pop = m.pops ? "yes" : "no";
        if (m.largest_jump >= 0) {
          const auto& worst = m.parameters[static_cast<std::size_t>(m.largest_jump)];
          pop += fmt::format(" ({} {})", worst.name, short_number(worst.jump));
        }
      }
      s += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", report_panel_name(m), md_cell(m.method),
                       max.empty() ? "-" : max, mean.empty() ? "-" : mean, length, turning, winding, sensitive, pop);
    }
    s += '\n';
  }
  // One table for the poses of the plane (det L an area), one for those of
  // space (det L a volume).
  for (const MeasuredKind kind : {MeasuredKind::plane_poses, MeasuredKind::space_poses}) {
    const auto shown = [&](const MotionMeasures& m) { return m.kind == kind && !m.no_motion; };
    if (std::none_of(all.begin(), all.end(), shown)) continue;
    s += fmt::format("| panel | method | ARA | {0} monotone | largest excursion (at t) | det L first, last | velocity jump |\n"
                     "|---|---|---|---|---|---|---|\n",
                     kind == MeasuredKind::plane_poses ? "area" : "volume");
    for (const auto& m : all) {
      if (!shown(m)) continue;
      s += fmt::format("| {} | {} | {} | {} | {} (t = {}) | {}, {} | {} |\n", report_panel_name(m), md_cell(m.method),
                       short_number(*m.ara), m.area->monotone ? "yes" : "no", short_number(m.area->excursion),
                       short_number(m.area->t_of_excursion), short_number(m.area->first), short_number(m.area->last),
                       short_number(m.velocity_jump.value_or(0.0)));
    }
    s += '\n';
  }
  for (const auto& m : all) {
    if (m.no_motion) s += fmt::format("- {}: no motion: {}\n", report_panel_name(m), md_cell(*m.no_motion));
  }
  // Overreaction gains, one column per arrow panel.
  std::vector<const MotionMeasures*> reacting;
  for (const auto& m : all) {
    if (!m.parameters.empty()) reacting.push_back(&m);
  }
  if (!reacting.empty()) {
    std::vector<std::string> names;
    std::set<std::string> seen;
    for (const auto* m : reacting) {
      for (const auto& p : m->parameters) {
        if (seen.insert(p.name).second) names.push_back(p.name);
      }
    }
    s += "\nOverreaction gain per parameter (max frame displacement / extent per unit normalised tweak; "
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
        for (const auto& p : m->parameters) {
          if (p.name != name) continue;
          cell = p.defined ? short_number(p.gain) : std::string("undefined");
          if (p.pop) cell += " *";
        }
        s += " " + cell + " |";
      }
      s += '\n';
    }
  }
  return s;
}

}  // namespace pita::analysis
