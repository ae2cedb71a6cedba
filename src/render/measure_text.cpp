#include "render/measure_text.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace pita::render {

namespace {

std::string number(double x) { return rounding_or_value(x); }

// The line of a number the motion lacks: "ARA: -", "gain B.q: -".
std::string missing(const scene::MeasureName& name) {
  using scene::MeasureKind;
  switch (name.kind) {
    case MeasureKind::discrepancy_max:
      return "E max: -";
    case MeasureKind::discrepancy_of:
    case MeasureKind::discrepancy_time:
      return fmt::format("E max ({}): -", name.parameter);
    case MeasureKind::path_length:
      return "length: -";
    case MeasureKind::turning:
      return "turning: -";
    case MeasureKind::inflections:
      return "inflections: -";
    case MeasureKind::winding_range:
      return "winding: -";
    case MeasureKind::overreaction:
      return "overreaction: -";
    case MeasureKind::pop:
      return "pop: -";
    case MeasureKind::ara:
      return "ARA: -";
    case MeasureKind::velocity_jump:
      return "velocity jump: -";
    case MeasureKind::area:
      return "area: -";
    case MeasureKind::gain:
      return fmt::format("gain {}: -", name.parameter);
    case MeasureKind::turn:
      return fmt::format("turn {}: -", name.parameter);
    case MeasureKind::jump:
      return fmt::format("jump {}: -", name.parameter);
    case MeasureKind::handle_shift:
    case MeasureKind::angle:
    case MeasureKind::frame_distance:    // claims only
    case MeasureKind::carried_distance:  // claims only
    case MeasureKind::property:          // claims only
    case MeasureKind::guess_distance:
    case MeasureKind::guess_discrepancy:  // claims only
    case MeasureKind::knot_distance:      // by the panel's drawing
      break;                              // compared with another motion by the panel's drawing, not measured here
    case MeasureKind::scale_step:
    case MeasureKind::turn_step:
    case MeasureKind::scale_min:
    case MeasureKind::scale_max:
    case MeasureKind::turn_step_time:
      break;  // of the drawn frames (analysis/frame_steps.hpp), by the panel's drawing
  }
  return name.text + ": -";
}

// "gain B.q: 1.36": the largest of the parameters named `name` ("B.q.x") or
// under it ("B.q": B.q.x, B.q.y), "(pop)" when one of them pops.
std::string reaction_line(const analysis::ArrowMeasures& m, const scene::MeasureName& name) {
  using scene::MeasureKind;
  const std::string_view kind = name.kind == MeasureKind::gain   ? "gain"
                                : name.kind == MeasureKind::turn ? "turn"
                                                                 : "jump";
  double value = 0.0;
  bool found = false, pop = false;
  for (const analysis::ParameterReaction& p : m.parameters) {
    if (p.name != name.parameter && !p.name.starts_with(name.parameter + ".")) continue;
    found = true;
    value = std::max(value, name.kind == MeasureKind::gain ? p.gain : name.kind == MeasureKind::turn ? p.turn : p.jump);
    pop = pop || p.pop;
  }
  if (!found) return missing(name);
  return fmt::format("{} {}: {}{}{}", kind, name.parameter, number(value),
                     name.kind == MeasureKind::turn ? " rad per unit" : "", pop ? " (pop)" : "");
}

std::string pop_line(const analysis::ArrowMeasures& m) {
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

// The line of a measure of keyframes (the others are missing).
std::string line(const analysis::ArrowMeasures& m, const scene::MeasureName& name) {
  using scene::MeasureKind;
  switch (name.kind) {
    case MeasureKind::discrepancy_max: {
      std::string values;
      for (const analysis::DiscrepancyStats& d : m.discrepancy) {
        values += fmt::format("{}{} {}", values.empty() ? "" : ", ", d.predictor, d.frames ? number(d.max) : "-");
      }
      return values.empty() ? missing(name) : "E max: " + values;
    }
    case MeasureKind::discrepancy_of:
    case MeasureKind::discrepancy_time:
      for (const analysis::DiscrepancyStats& d : m.discrepancy) {
        if (d.predictor != name.parameter || d.frames == 0) continue;
        return fmt::format("E max ({}): {} at t = {}", d.predictor, number(d.max), number(d.t_of_max));
      }
      return missing(name);
    case MeasureKind::path_length:
      return fmt::format("length p {}, q {}", number(m.path_p.length), number(m.path_q.length));
    case MeasureKind::turning:
      return fmt::format("turning p {}, q {} rad", number(m.path_p.turning), number(m.path_q.turning));
    case MeasureKind::inflections:
      return fmt::format("inflections p {}, q {}", m.path_p.inflections, m.path_q.inflections);
    case MeasureKind::winding_range:
      return fmt::format("winding [{}, {}]", number(m.winding_min), number(m.winding_max));
    case MeasureKind::overreaction: {
      if (m.most_sensitive < 0) return missing(name);
      const auto& best = m.parameters[static_cast<std::size_t>(m.most_sensitive)];
      return fmt::format("most sensitive: {} (gain {})", best.name, number(best.gain));
    }
    case MeasureKind::pop:
      return pop_line(m);
    case MeasureKind::gain:
    case MeasureKind::turn:
    case MeasureKind::jump:
      return reaction_line(m, name);
    case MeasureKind::ara:
    case MeasureKind::velocity_jump:
    case MeasureKind::area:  // of poses
    case MeasureKind::handle_shift:
    case MeasureKind::angle:
    case MeasureKind::frame_distance:
    case MeasureKind::carried_distance:
    case MeasureKind::property:
    case MeasureKind::knot_distance:
    case MeasureKind::guess_distance:
    case MeasureKind::guess_discrepancy:
    case MeasureKind::scale_step:
    case MeasureKind::turn_step:
    case MeasureKind::scale_min:
    case MeasureKind::scale_max:
    case MeasureKind::turn_step_time:
      break;
  }
  return missing(name);
}

// A curve through points has a path only.
std::string line(const analysis::PointMeasures& m, const scene::MeasureName& name) {
  if (name.kind == scene::MeasureKind::path_length) return fmt::format("length {}", number(m.path.length));
  if (name.kind == scene::MeasureKind::turning) return fmt::format("turning {} rad", number(m.path.turning));
  if (name.kind == scene::MeasureKind::inflections) return fmt::format("inflections {}", m.path.inflections);
  return missing(name);
}

// Poses have ARA, the velocity jump and det L.
template <class Pose>
std::string line(const analysis::PoseMeasures<Pose>& m, const scene::MeasureName& name) {
  if (name.kind == scene::MeasureKind::ara) return fmt::format("ARA {}", number(m.ara));
  if (name.kind == scene::MeasureKind::velocity_jump) return fmt::format("velocity jump {}", number(m.velocity_jump));
  if (name.kind != scene::MeasureKind::area) return missing(name);
  return m.area.monotone ? std::string("area monotone")
                         : fmt::format("area not monotone (dip {} at t = {})", number(m.area.excursion),
                                       number(m.area.t_of_excursion));
}

}  // namespace

std::string rounding_or_value(double value) {
  return std::abs(value) < 1e-12 ? std::string("< 1e-12") : fmt::format("{:.3g}", value);
}

std::vector<std::string> measure_lines(const analysis::MotionMeasures& measures,
                                       std::span<const scene::MeasureName> show) {
  std::vector<std::string> lines;
  for (const scene::MeasureName& name : show) {
    // A motion that does not exist has no number (its panel fails first).
    lines.push_back(measures.no_motion
                        ? missing(name)
                        : std::visit([&](const auto& measured) { return line(measured, name); }, measures.measured));
  }
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
