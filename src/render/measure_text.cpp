#include "render/measure_text.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace pita::render {

namespace {

std::string number(double x) { return rounding_or_value(x); }

// The parameters named `name` ("B.q.x") or under it ("B.q": B.q.x, B.q.y).
std::vector<const analysis::ParameterReaction*> parameters(const analysis::MotionMeasures& m,
                                                           const std::string& name) {
  std::vector<const analysis::ParameterReaction*> found;
  for (const analysis::ParameterReaction& p : m.parameters) {
    if (p.name == name || p.name.starts_with(name + ".")) found.push_back(&p);
  }
  return found;
}

std::string line(const analysis::MotionMeasures& m, const scene::MeasureName& name) {
  using scene::MeasureKind;
  switch (name.kind) {
    case MeasureKind::discrepancy_max: {
      if (m.discrepancy.empty()) return "E max: -";
      std::string values;
      for (const analysis::DiscrepancyStats& d : m.discrepancy) {
        values += fmt::format("{}{} {}", values.empty() ? "" : ", ", d.predictor, d.frames ? number(d.max) : "-");
      }
      return "E max: " + values;
    }
    case MeasureKind::discrepancy_of:
    case MeasureKind::discrepancy_time:
      for (const analysis::DiscrepancyStats& d : m.discrepancy) {
        if (d.predictor != name.parameter || d.frames == 0) continue;
        return fmt::format("E max ({}): {} at t = {}", d.predictor, number(d.max), number(d.t_of_max));
      }
      return fmt::format("E max ({}): -", name.parameter);
    case MeasureKind::path_length:
      if (!m.path_p) return "length: -";
      return m.path_q ? fmt::format("length p {}, q {}", number(m.path_p->length), number(m.path_q->length))
                      : fmt::format("length {}", number(m.path_p->length));
    case MeasureKind::turning:
      if (!m.path_p) return "turning: -";
      return m.path_q ? fmt::format("turning p {}, q {} rad", number(m.path_p->turning), number(m.path_q->turning))
                      : fmt::format("turning {} rad", number(m.path_p->turning));
    case MeasureKind::winding_range:
      if (!m.winding_min) return "winding: -";
      return fmt::format("winding [{}, {}]", number(*m.winding_min), number(*m.winding_max));
    case MeasureKind::overreaction: {
      if (m.most_sensitive < 0) return "overreaction: -";
      const auto& best = m.parameters[static_cast<std::size_t>(m.most_sensitive)];
      return fmt::format("most sensitive: {} (gain {})", best.name, number(best.gain));
    }
    case MeasureKind::pop: {
      if (m.kind != analysis::MeasuredKind::arrows) return "pop: -";
      if (m.largest_jump < 0) {
        for (const auto& p : m.parameters) {
          if (!p.defined) return fmt::format("pop: {} leaves the domain", p.name);
        }
        return "pop: -";
      }
      const auto& worst = m.parameters[static_cast<std::size_t>(m.largest_jump)];
      return m.pops ? fmt::format("pop: {} jumps {}", worst.name, number(worst.jump))
                    : fmt::format("no pop (largest jump {})", number(worst.jump));
    }
    case MeasureKind::ara:
      return m.ara ? fmt::format("ARA {}", number(*m.ara)) : "ARA: -";
    case MeasureKind::velocity_jump:
      return m.velocity_jump ? fmt::format("velocity jump {}", number(*m.velocity_jump)) : "velocity jump: -";
    case MeasureKind::area:
      if (!m.area) return "area: -";
      return m.area->monotone ? std::string("area monotone")
                              : fmt::format("area not monotone (dip {} at t = {})", number(m.area->excursion),
                                            number(m.area->t_of_excursion));
    case MeasureKind::gain:
    case MeasureKind::turn:
    case MeasureKind::jump: {
      const std::string_view kind = name.kind == MeasureKind::gain ? "gain" : name.kind == MeasureKind::turn ? "turn" : "jump";
      const auto found = parameters(m, name.parameter);
      if (found.empty()) return fmt::format("{} {}: -", kind, name.parameter);
      double value = 0.0;
      bool pop = false;
      for (const auto* p : found) {
        value = std::max(value, name.kind == MeasureKind::gain ? p->gain
                                : name.kind == MeasureKind::turn ? p->turn
                                                                 : p->jump);
        pop = pop || p->pop;
      }
      return fmt::format("{} {}: {}{}{}", kind, name.parameter, number(value),
                         name.kind == MeasureKind::turn ? " rad per unit" : "", pop ? " (pop)" : "");
    }
    case MeasureKind::handle_shift:
    case MeasureKind::angle:
    case MeasureKind::frame_distance:  // claims only
    case MeasureKind::property:        // claims only
      break;  // compared with another motion by the panel's drawing, not measured here
    case MeasureKind::scale_step:
    case MeasureKind::turn_step:
    case MeasureKind::scale_min:
    case MeasureKind::scale_max:
      break;  // of the drawn frames (analysis/frame_steps.hpp), by the panel's drawing
  }
  return name.text + ": -";
}

}  // namespace

std::string rounding_or_value(double value) {
  return std::abs(value) < 1e-12 ? std::string("< 1e-12") : fmt::format("{:.3g}", value);
}

std::vector<std::string> measure_lines(const analysis::MotionMeasures& measures,
                                       std::span<const scene::MeasureName> show) {
  std::vector<std::string> lines;
  for (const scene::MeasureName& name : show) lines.push_back(line(measures, name));
  return lines;
}

void add_measure_text(const scene::MeasuresLayer& layer, const std::vector<std::string>& lines, Drawing& drawing,
                      const std::string& layer_pointer) {
  if (layer.at) {
    std::string text;
    for (const std::string& line : lines) text += (text.empty() ? "" : "\n") + line;
    drawing.items.push_back({layer_pointer, -1, Label{text, *layer.at, layer.size, layer.color}});
    return;
  }
  Legend legend{layer.corner, layer.size, {}, false, layer_pointer};
  for (const std::string& line : lines) legend.entries.push_back({layer.color, line});
  drawing.legends.push_back(std::move(legend));
}

}  // namespace pita::render
