// A whole figure: every panel's drawing laid out on the canvas and painted
// with cairo onto an SVG, PNG or PDF surface, returned as the file's bytes.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include <cairo.h>

#include "render/drawing.hpp"
#include "render/layout.hpp"
#include "render/panel_drawing.hpp"
#include "scene/scene.hpp"

namespace pita::render {

enum class Format { svg, png, pdf };

// "svg", "png", "pdf" (any case) -> Format; nullopt otherwise.
std::optional<Format> format_from_name(std::string_view name);
std::string_view extension(Format format);  // "svg", ...

// PNG size limits: each side at most kMaxPngSide pixels after scaling.
inline constexpr int kMaxPngSide = 16384;
inline constexpr double kMinScale = 0.01;
inline constexpr double kMaxScale = 16.0;

// The drawings of every panel and their placements (what `render` paints).
struct Figure {
  std::vector<Drawing> drawings;
  std::vector<PanelPlacement> placements;
};
// Throws RenderError (render/panel_drawing.hpp), also, before drawing
// anything, when the figure's estimated work exceeds `budget` times the
// default budget (render/budget.hpp), or an image cannot be decoded. A scene
// whose keyframes move (PITA Sec. 7.4) overlays its figure at each tau of
// its animation's "overlay".
Figure build_figure(const scene::Scene& scene, double budget = 1.0);
// The same with the motions of a stage built already (pita sweep checks
// them first).
Figure build_figure(const motion::Stage& stage, double budget = 1.0);
// The same in the world views given, one per panel (layout_in_views): what
// pita serve --edit draws while a figure's views are held.
Figure build_figure_in_views(const motion::Stage& stage, const std::vector<scene::Box>& views, double budget = 1.0);

// Every panel's drawing, without layout or budget; with a selection, one
// frame of an animation (render/panel_drawing.hpp). Throws RenderError. The
// second draws the motions of a stage built once (animate's frames); with a
// cache shared by the frames of one stage, a layer that reads nothing of the
// frame is drawn once (render/static_layers.hpp).
std::vector<Drawing> frame_drawings(const scene::Scene& scene, const FrameSelection* selection);
std::vector<Drawing> frame_drawings(const motion::Stage& stage, const FrameSelection* selection,
                                    StaticLayers* cache = nullptr);

// Decodes every image of the scene's shapes (once per thread): a corrupt PNG
// is refused before anything is drawn. Throws RenderError.
void check_images(const scene::Scene& scene);

// layout_panels, refusing placements that overflow. Throws RenderError.
// With `views`, in those (layout_in_views).
std::vector<PanelPlacement> checked_layout(const scene::Scene& scene, const std::vector<Drawing>& drawings,
                                           const std::vector<scene::Box>* views = nullptr);

// Which part of a figure paint_figure paints: all of it; an animation's
// backdrop (the background, the titles and the first `leading[i]` items of
// drawing i, no legends); or the rest, over a backdrop (render/backdrop.hpp).
struct WholeFigure {};
struct BackdropPart {
  const std::vector<std::size_t>* leading;  // one count per drawing
};
struct RestPart {
  const std::vector<std::size_t>* leading;  // one count per drawing
};
using FigurePart = std::variant<WholeFigure, BackdropPart, RestPart>;

// Paints the figure (background, titles, panels) on `cr`, whose user units are
// canvas pixels.
void paint_figure(cairo_t* cr, const scene::Scene& scene, const Figure& figure, const FigurePart& part = WholeFigure{});

// The checks render_figure makes before painting a PNG (the scale, the side
// limit, the pixel and ink budgets): its size in pixels. Throws RenderError.
std::pair<int, int> checked_png_size(const scene::Scene& scene, const Figure& figure, double scale,
                                     double budget = 1.0);

// The PNG file of a painted image surface. Throws RenderError.
std::string encode_png(const scene::Scene& scene, cairo_surface_t* surface);

// cairo numbers SVG surfaces and images with counters global to the process:
// renumbered 1, 2, ... in order of appearance, so that an SVG does not depend
// on what the process drew before it.
std::string canonical_svg_ids(const std::string& svg);

// The file's bytes. `scale` multiplies the PNG's pixel size (SVG and PDF are
// vector: 1 canvas pixel = 1 unit). The same scene gives the same bytes.
// Throws RenderError, also when a PNG has more pixels than `budget` times the
// default pixel budget.
std::string render_figure(const scene::Scene& scene, const Figure& figure, Format format, double scale = 1.0,
                          double budget = 1.0);

}  // namespace pita::render
