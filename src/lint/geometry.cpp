#include "lint/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/overloaded.hpp"
#include "render/painter.hpp"

namespace pita::lint {

namespace {

using render::ViewTransform;

void set_line(DataShape& data, const scene::LineStyle& line) {
  data.color = line.color;
  data.stroked = true;
  data.style = fmt::format("{} {:g}px{}", color_text(line.color), line.width,
                           line.dash.empty() ? "" : fmt::format(" dashed {}", fmt::join(line.dash, ",")));
}

// A shape's data on the canvas, with its style; nullopt for a label (a text).
std::optional<DataShape> data_shape(const render::Shape& shape, const ViewTransform& view) {
  std::optional<render::CanvasOutline> outline = render::canvas_outline(shape, view);
  if (!outline) return std::nullopt;
  DataShape data;
  static_cast<render::CanvasOutline&>(data) = std::move(*outline);
  std::visit(overloaded{[&](const render::Polyline& s) { set_line(data, s.line); },
                        [&](const render::FilledPath& s) {
                          data.color = s.fill;
                          data.fill_opacity = s.opacity * s.fill.a;
                          data.style = fmt::format("fill {}", color_text(s.fill));
                          if (s.outline) set_line(data, *s.outline);
                        },
                        [&](const render::Circle& s) { set_line(data, s.line); },
                        [&](const render::ArrowShape& s) { set_line(data, s.line); }, [](const render::Label&) {},
                        [](const render::Image&) {}},
             shape);
  return data;
}

// The "type" of the layer at `pointer` ("/layers/3", "/panels/1/layers/0").
std::string layer_type_at(const scene::Scene& scene, const scene::Panel& panel, const std::string& pointer) {
  const std::size_t slash = pointer.rfind("/layers/");
  if (slash == std::string::npos) return "";
  std::size_t index = 0;
  try {
    index = std::stoul(pointer.substr(slash + 8));
  } catch (const std::exception&) {
    return "";
  }
  // The layers the pointer names: the panel's ("/panels/1/layers/0": its own,
  // else the scene's) or the scene's ("/layers/0").
  const auto type_in = [&](const auto& scene_layers, const auto& drawn) {
    const auto& layers = slash > 0 ? drawn.layers : scene_layers;
    return index < layers.size() ? std::string(scene::layer_type(layers[index])) : std::string();
  };
  const auto arrows = [&](const auto& keys) {
    return type_in(scene::figure_of(scene, keys).layers, scene::layers_of<scene::Layer>(scene, panel));
  };
  const auto poses = [&](const auto& keys) {
    return type_in(scene::figure_of(scene, keys).layers, scene::layers_of<scene::PoseLayer>(scene, panel));
  };
  return std::visit(overloaded{[&](const scene::KeyframeKeys& keys) { return arrows(keys); },
                               [&](const scene::PointKeys& keys) { return arrows(keys); },
                               [&](const scene::PlanePoseKeys& keys) { return poses(keys); },
                               [&](const scene::SpacePoseKeys& keys) { return poses(keys); }},
                    panel.keys);
}

std::string panel_name(const scene::Scene& scene, std::size_t i) {
  const std::string& title = scene.panels[i].title;
  if (scene.panels.size() == 1 && title.empty()) return "the figure";
  return title.empty() ? fmt::format("panel {}", i) : fmt::format("panel {} ({})", i, title);
}

}  // namespace

std::string color_text(const scene::Color& c) {
  const auto byte = [](double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
  return fmt::format("#{:02x}{:02x}{:02x}", byte(c.r), byte(c.g), byte(c.b));
}

FigureGeometry figure_geometry(const scene::Scene& scene, const render::Figure& figure) {
  const scene::Canvas& canvas = scene.canvas;
  FigureGeometry geometry;
  geometry.canvas = {0.0, 0.0, static_cast<double>(canvas.width), static_cast<double>(canvas.height)};
  if (!scene.title.empty()) {
    geometry.titles.push_back(
        {render::text_ink_box(scene.title, canvas.font, render::kTitleSize, render::scene_title_placement(canvas),
                              render::is_markup(scene.title)),
         "/title", scene.title, TextKind::title});
    geometry.title_cells.push_back(geometry.canvas);
  }
  for (std::size_t i = 0; i < figure.drawings.size(); ++i) {
    const scene::Panel& panel = scene.panels[i];
    const render::PanelPlacement& place = figure.placements[i];
    const render::Drawing& drawing = figure.drawings[i];
    if (!panel.title.empty()) {
      geometry.titles.push_back(
          {render::text_ink_box(panel.title, canvas.font, render::kPanelTitleSize, render::panel_title_placement(place),
                                render::is_markup(panel.title)),
           panel.pointer.empty() ? "/title" : panel.pointer + "/title", panel.title, TextKind::title});
      geometry.title_cells.push_back(place.cell);
    }
    PanelGeometry out;
    out.pointer = panel.pointer;
    out.name = panel_name(scene, i);
    out.area = render::drawing_area(place);
    out.plot = place.plot;
    out.scale = place.transform.scale;
    std::map<std::string, std::string> types;  // of each layer pointer met
    for (const render::Item& item : drawing.items) {
      if (const auto* label = std::get_if<render::Label>(&item.shape)) {
        out.texts.push_back(
            {render::text_ink_box(label->text, canvas.font, label->size,
                                  render::label_placement(*label, place.transform), render::is_markup(label->text)),
             item.layer, label->text, TextKind::label});
        continue;
      }
      std::optional<DataShape> data = data_shape(item.shape, place.transform);
      if (!data) continue;
      auto [type, inserted] = types.try_emplace(item.layer);
      if (inserted) type->second = layer_type_at(scene, panel, item.layer);
      data->layer = item.layer;
      data->type = type->second;
      data->index = item.index;
      data->frame = item.index >= 0 && (data->type == "pattern" || data->type == "shapes");
      out.data.push_back(std::move(*data));
    }
    for (const render::Legend& legend : drawing.legends) {
      const render::LegendGeometry placed = render::legend_geometry(legend, out.area);
      Rect box = legend.swatches ? placed.box : render::empty_rect();
      for (const render::LegendRow& row : placed.rows) {
        const Rect ink = render::text_ink_box(row.entry->text, canvas.font, legend.size, row.text, false);
        out.texts.push_back({ink, legend.layer, row.entry->text, TextKind::legend});
        box = united(box, ink);
      }
      if (!placed.rows.empty()) out.legends.push_back({box, legend.layer});
    }
    geometry.panels.push_back(std::move(out));
  }
  return geometry;
}

}  // namespace pita::lint
