#include "render/label_placement.hpp"

#include <limits>
#include <optional>

#include "render/canvas_geometry.hpp"
#include "render/painter.hpp"

namespace pita::render {

namespace {

// Boxes within this many pixels of data or text do not count as meeting it
// (as in `pita lint`: antialiasing and the ink's own rounding).
constexpr double kSlack = 1.0;
// What leaving the panel costs against meeting one shape or text.
constexpr double kOutsidePenalty = 1000.0;

struct PanelContent {
  Rect area;
  std::vector<CanvasOutline> data;
  std::vector<Rect> texts;  // labels placed so far, legends
};

double conflicts(const PanelContent& panel, const Rect& ink) {
  if (!(ink.width > 0.0 && ink.height > 0.0)) return 0.0;  // no ink
  const Rect box = shrunk(ink, kSlack);
  double count = contains(panel.area, ink) ? 0.0 : kOutsidePenalty;
  for (const CanvasOutline& shape : panel.data) count += lies_under(shape, box, true) ? 1.0 : 0.0;
  for (const Rect& text : panel.texts) count += intersects(box, shrunk(text, kSlack)) ? 1.0 : 0.0;
  return count;
}

Rect label_ink(const Label& label, const ViewTransform& view, const std::string& font) {
  return text_ink_box(label.text, font, label.size, label_placement(label, view), is_markup(label.text));
}

}  // namespace

Rect spot_box(const Rect& ink, Point at, Spot spot, double gap) {
  const double w = ink.width, h = ink.height, x = at.real(), y = at.imag();
  const double left = x - gap - w, right = x + gap, centre_x = x - 0.5 * w;
  const double above = y - gap - h, below = y + gap, centre_y = y - 0.5 * h;
  switch (spot) {
    case Spot::right:
      return {right, centre_y, w, h};
    case Spot::above_right:
      return {right, above, w, h};
    case Spot::above:
      return {centre_x, above, w, h};
    case Spot::above_left:
      return {left, above, w, h};
    case Spot::left:
      return {left, centre_y, w, h};
    case Spot::below_left:
      return {left, below, w, h};
    case Spot::below:
      return {centre_x, below, w, h};
    case Spot::below_right:
      return {right, below, w, h};
  }
  return ink;
}

void place_labels(const scene::Scene& scene, std::vector<Drawing>& drawings,
                  const std::vector<PanelPlacement>& placements) {
  const std::string& font = scene.canvas.font;
  for (std::size_t i = 0; i < drawings.size() && i < placements.size(); ++i) {
    Drawing& drawing = drawings[i];
    const ViewTransform& view = placements[i].transform;
    bool any = false;
    for (const Item& item : drawing.items) {
      const auto* label = std::get_if<Label>(&item.shape);
      any = any || (label != nullptr && label->avoid_data);
    }
    if (!any) continue;
    PanelContent panel;
    panel.area = drawing_area(placements[i]);
    for (const Item& item : drawing.items) {
      if (const auto* label = std::get_if<Label>(&item.shape)) {
        if (!label->avoid_data) panel.texts.push_back(label_ink(*label, view, font));
      } else if (std::optional<CanvasOutline> outline = canvas_outline(item.shape, view)) {
        panel.data.push_back(std::move(*outline));
      }
    }
    for (const Legend& legend : drawing.legends) {
      const LegendGeometry placed = legend_geometry(legend, panel.area);
      if (legend.swatches) panel.texts.push_back(placed.box);
      for (const LegendRow& row : placed.rows) {
        panel.texts.push_back(text_ink_box(row.entry->text, font, legend.size, row.text, false));
      }
    }
    for (Item& item : drawing.items) {
      auto* label = std::get_if<Label>(&item.shape);
      if (label == nullptr || !label->avoid_data) continue;
      label->shift = {0.0, 0.0};
      const Rect ink = label_ink(*label, view, font);
      Rect best = ink;
      double fewest = conflicts(panel, ink);
      const Point at = view(label->at);
      for (const double gap : kSpotGaps) {
        for (const Spot spot : kSpots) {
          if (fewest == 0.0) break;
          const Rect box = spot_box(ink, at, spot, gap * label->size);
          const double count = conflicts(panel, box);
          if (count < fewest) {
            fewest = count;
            best = box;
          }
        }
      }
      label->shift = {best.x - ink.x, best.y - ink.y};
      panel.texts.push_back(best);
    }
  }
}

}  // namespace pita::render
