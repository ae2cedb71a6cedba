// What the lint looks at: a figure as it lands on the canvas, in canvas
// pixels, before anything is painted. Every text is a box of ink (measured
// with the same Pango layout the painter draws), every stroke an edge,
// every fill a contour, each tagged with the JSON Pointer it comes from.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "analysis/claims.hpp"
#include "motion/stage.hpp"
#include "render/canvas_geometry.hpp"
#include "render/figure.hpp"
#include "scene/scene.hpp"

namespace pita::lint {

using render::Rect;

enum class TextKind { title, label, legend };

struct TextBox {
  Rect box;           // its ink, canvas pixels
  std::string owner;  // "/title", "/panels/2/title", "/layers/3"
  std::string text;
  TextKind kind = TextKind::label;
};

// One shape of a layer's data (not text), on the canvas: its edges, filled
// areas and bounds (render/canvas_geometry.hpp), and what it belongs to.
struct DataShape : render::CanvasOutline {
  std::string layer;          // the layer's pointer
  std::string type;           // its "type" ("pattern", "poses", ...)
  int index = -1;             // its frame or keyframe, -1 if none
  scene::Color color;         // of its stroke (a fill without outline: of the fill)
  std::string style;          // its colour, width and dash, as text: what tells series apart
  bool stroked = false;       // drawn with a line (not only filled)
  bool frame = false;         // a frame of a pattern (its one segment) or a shape carried to a frame
  double fill_opacity = 0.0;  // of its filled areas (0 without): what hides what is under it
};

struct LegendBox {
  Rect box;
  std::string layer;
};

struct PanelGeometry {
  std::string pointer;  // the panel's ("" for a scene without "panels")
  std::string name;     // for messages: "panel 2 (P6 La-LP)"
  Rect area;            // where its drawing is painted (and clipped to)
  Rect plot;            // the area less its margins: what the view is fitted into
  double scale = 1.0;   // pixels per unit of the scene's plane (of its view)
  std::vector<DataShape> data;
  std::vector<TextBox> texts;  // labels and legend lines
  std::vector<LegendBox> legends;
};

// A claim that a distance between drawn motions is above a bound
// ("frame-distance:/panels/1", "above": 0.4): what it asks a reader to see,
// measured on the motions the figure draws (scene::is_drawn_distance).
struct ClaimedDistance {
  std::string claim;  // its pointer, "/claims/2"
  std::string says;
  std::size_t panel = 0;             // the claim's panel
  std::optional<std::size_t> other;  // the panel it compares with, if any
  double value = 0.0;                // in the scene's units
};

struct FigureGeometry {
  Rect canvas;
  std::vector<TextBox> titles;    // the scene's and the panels' titles
  std::vector<Rect> title_cells;  // where each title may go (the canvas's band, a panel's cell)
  std::vector<PanelGeometry> panels;
  std::vector<ClaimedDistance> claimed;
};

// Without `claimed` (claimed_distances fills it).
FigureGeometry figure_geometry(const scene::Scene& scene, const render::Figure& figure);

// The claims of the stage's arrow panels that a distance between drawn
// motions is above a bound and that hold, with the distance measured
// (`claims`: their outcomes, as analysis::check_claims gives them, in order).
// A claim that fails is left out: pita check reports it.
// Whether the small-feature check reads `claim`: a distance between drawn
// motions claimed above a bound, on a panel of keyframes.
bool is_claimed_distance(const scene::Scene& scene, const scene::Claim& claim);

std::vector<ClaimedDistance> claimed_distances(const motion::Stage& stage,
                                               const std::vector<analysis::ClaimOutcome>& claims);

// "#rrggbb".
std::string color_text(const scene::Color& color);

// Boxes (render/canvas_geometry.hpp).
using render::intersects;
using render::shrunk;
using render::united;

}  // namespace pita::lint
