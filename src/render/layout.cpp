#include "render/layout.hpp"

#include <algorithm>
#include <cmath>

namespace pita::render {

namespace {

scene::Box united(const scene::Box& a, const scene::Box& b) {
  return {{std::min(a.min.real(), b.min.real()), std::min(a.min.imag(), b.min.imag())},
          {std::max(a.max.real(), b.max.real()), std::max(a.max.imag(), b.max.imag())}};
}

// A box with room on both axes: a degenerate side (a vertical pattern, a
// single point) gets the other side's size, or 1 when both are zero.
// The smallest side of a view, relative to its larger side.
constexpr double kMinViewAspect = 1e-3;

scene::Box padded(scene::Box box) {
  const double w = box.max.real() - box.min.real(), h = box.max.imag() - box.min.imag();
  const double side = std::max({w, h, 0.0}) > 0.0 ? std::max(w, h) : 1.0;
  const double min_side = kMinViewAspect * side;
  if (w < min_side) {
    box.min -= Point{0.5 * (min_side - w), 0.0};
    box.max += Point{0.5 * (min_side - w), 0.0};
  }
  if (h < min_side) {
    box.min -= Point{0.0, 0.5 * (min_side - h)};
    box.max += Point{0.0, 0.5 * (min_side - h)};
  }
  return box;
}

ViewTransform fit(const scene::Box& view, const Rect& plot, bool y_up) {
  const double w = view.max.real() - view.min.real(), h = view.max.imag() - view.min.imag();
  ViewTransform transform;
  transform.world_center = 0.5 * (view.min + view.max);
  transform.canvas_center = {plot.x + 0.5 * plot.width, plot.y + 0.5 * plot.height};
  transform.scale = std::max(std::min(plot.width / w, plot.height / h), 0.0);
  transform.y_up = y_up;
  return transform;
}

// The room a drawing's corner legends take at the top and the bottom of its panel.
struct Bands {
  double top = 0.0, bottom = 0.0;
};

Bands legend_bands(const Drawing& drawing) {
  Bands bands;
  for (const Legend& legend : drawing.legends) {
    if (legend.entries.empty()) continue;
    const double room = legend_height(legend) + 2.0 * kLegendPad;
    const bool bottom = legend.corner == scene::LegendLayer::Corner::bottom_left ||
                        legend.corner == scene::LegendLayer::Corner::bottom_right;
    (bottom ? bands.bottom : bands.top) = std::max(bottom ? bands.bottom : bands.top, room);
  }
  return bands;
}

}  // namespace

double legend_height(const Legend& legend) {
  return kLegendLineHeight * legend.size * static_cast<double>(legend.entries.size());
}

std::vector<PanelPlacement> layout_panels(const scene::Scene& scene, const std::vector<Drawing>& drawings) {
  const scene::Canvas& canvas = scene.canvas;
  const int n = static_cast<int>(drawings.size());
  if (n == 0) return {};
  const int columns = canvas.columns > 0 ? std::min(canvas.columns, std::max(n, 1))
                                         : static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  const int rows = (n + columns - 1) / columns;
  const double top = scene.title.empty() ? 0.0 : kTitleBand;
  const double cell_w = canvas.width / static_cast<double>(columns);
  const double cell_h = (canvas.height - top) / static_cast<double>(std::max(rows, 1));

  std::optional<scene::Box> shared;
  if (canvas.shared_fit) {
    for (const Drawing& d : drawings) {
      if (const auto b = bounds(d)) shared = shared ? united(*shared, *b) : *b;
    }
  }

  // With one view for all (shared or given), one room for legends too: one scale.
  Bands common;
  if (canvas.view || shared) {
    for (const Drawing& d : drawings) {
      const Bands b = legend_bands(d);
      common.top = std::max(common.top, b.top);
      common.bottom = std::max(common.bottom, b.bottom);
    }
  }

  std::vector<PanelPlacement> placements;
  for (int i = 0; i < n; ++i) {
    PanelPlacement p;
    p.cell = {cell_w * (i % columns), top + cell_h * (i / columns), cell_w, cell_h};
    const bool titled = !scene.panels[static_cast<std::size_t>(i)].title.empty();
    p.title = {p.cell.x, p.cell.y, p.cell.width, titled ? kPanelTitleBand : 0.0};
    const Rect inner{p.cell.x, p.cell.y + p.title.height, p.cell.width, std::max(p.cell.height - p.title.height, 1.0)};
    const double margin = canvas.margin * std::min(inner.width, inner.height);
    const Bands bands = canvas.view || shared ? common : legend_bands(drawings[static_cast<std::size_t>(i)]);
    // A legend takes at most a third of the panel's height; beyond, it lies over the data (pita lint says so).
    const double above = std::max(margin, std::min(bands.top, inner.height / 3.0));
    const double below = std::max(margin, std::min(bands.bottom, inner.height / 3.0));
    p.plot = {inner.x + margin, inner.y + above, std::max(inner.width - 2 * margin, 1.0),
              std::max(inner.height - above - below, 1.0)};
    if (canvas.view) {
      p.view = *canvas.view;
    } else if (shared) {
      p.view = padded(*shared);
    } else if (const auto b = bounds(drawings[static_cast<std::size_t>(i)])) {
      p.view = padded(*b);
    } else {
      p.view = {{-1.0, -1.0}, {1.0, 1.0}};
    }
    p.transform = fit(p.view, p.plot, canvas.y_up);
    placements.push_back(p);
  }
  return placements;
}

std::vector<PanelPlacement> layout_in_views(const scene::Scene& scene, const std::vector<Drawing>& drawings,
                                            const std::vector<scene::Box>& views) {
  std::vector<PanelPlacement> placements = layout_panels(scene, drawings);
  for (std::size_t i = 0; i < placements.size() && i < views.size(); ++i) {
    placements[i].view = views[i];
    placements[i].transform = fit(views[i], placements[i].plot, scene.canvas.y_up);
  }
  return placements;
}

}  // namespace pita::render
