// Where each panel goes on the canvas and how the plane maps onto it. All
// sizes are canvas pixels (at scale 1); y of the canvas points down.
#pragma once

#include <string>
#include <vector>

#include "render/drawing.hpp"
#include "scene/scene.hpp"

namespace pita::render {

inline constexpr double kTitleSize = 18.0;       // scene title, pixels
inline constexpr double kTitleBand = 34.0;       // height reserved for it
inline constexpr double kPanelTitleSize = 13.0;  // panel titles
inline constexpr double kPanelTitleBand = 22.0;

// Legends (painted in a corner of their panel, render/painter.hpp): a line
// is kLegendLineHeight times the text's size, kLegendPad pixels from the
// panel's sides.
inline constexpr double kLegendLineHeight = 1.5;
inline constexpr double kLegendPad = 6.0;
double legend_height(const Legend& legend);  // its lines, pixels

struct Rect {
  double x = 0, y = 0, width = 0, height = 0;
};

// The similarity from the plane to the canvas: a uniform scale about the
// view's centre, y flipped when the scene's y axis points up.
struct ViewTransform {
  Point world_center;
  Point canvas_center;
  double scale = 1.0;  // pixels per world unit
  bool y_up = true;

  Point operator()(Point world) const {
    const Point d = (world - world_center) * scale;
    return canvas_center + Point{d.real(), y_up ? -d.imag() : d.imag()};
  }
};

struct PanelPlacement {
  Rect cell;        // the panel's share of the canvas
  Rect title;       // its title band (height 0 without a title)
  Rect plot;        // where its drawing goes, margins removed
  scene::Box view;  // the world box shown
  ViewTransform transform;
};

// One placement per panel, for drawings[i] of panel i: the grid of
// canvas.columns columns (default ceil(sqrt(n))) below the scene's title, and
// each panel's view (canvas.view, else its own drawing's bounds, or the union
// of all for "shared"), fitted into its plot area keeping proportions. The
// plot area leaves room above and below for the legends in the panel's top
// and bottom corners, so that they do not lie over the data (with a shared
// or given view, every panel leaves the room of the most, to keep one scale).
std::vector<PanelPlacement> layout_panels(const scene::Scene& scene, const std::vector<Drawing>& drawings);

// layout_panels with each panel's world view given (views[i] for panel i, one
// per drawing, each side positive): the cells and plot areas are
// layout_panels', each view is fitted into its plot area in place of the
// drawing's bounds. pita serve --edit holds a figure's views while it is
// edited, so that what is dragged stays under the pointer.
std::vector<PanelPlacement> layout_in_views(const scene::Scene& scene, const std::vector<Drawing>& drawings,
                                            const std::vector<scene::Box>& views);

}  // namespace pita::render
