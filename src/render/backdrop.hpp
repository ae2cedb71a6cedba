// The backdrop of an animation's raster frames (issue 37; docs/reference/animate.md
// "Animation"): what every frame shares, the background, the titles and each
// panel's items before its first moving one (the layers that do not move,
// drawn under those that do), is painted once; each frame copies those pixels
// and paints only the rest. The animated SVG shares the same part by nesting
// it once (animate/svg_animation.cpp).
//
// The backdrop is used only where it gives the very pixels of painting the
// frame whole (frame k of `pita animate` is byte for byte `pita render --at
// t_k`): cairo composites pixel by pixel, so painting a panel's rest later
// changes nothing as long as no pixel is painted by two panels, or by one
// panel and another's title. It is so with one panel, or when the pixels that
// the panels' clip rectangles touch (even partly, at the frame's scale) are
// disjoint and no panel title's ink reaches another panel's. Otherwise every
// frame is painted whole, as before.
#pragma once

#include <cstddef>
#include <vector>

#include "render/cairo_handles.hpp"
#include "render/figure.hpp"
#include "scene/scene.hpp"

namespace pita::render {

class FrameBackdrop {
 public:
  // The backdrop of frames like `first` (same placements), painted on a
  // width x height ARGB surface at `scale`, when that is exact (above).
  // Throws RenderError when cairo fails.
  FrameBackdrop(const scene::Scene& scene, const Figure& first, int width, int height, double scale);

  // Whether frames are painted over the backdrop.
  bool active() const { return surface_ != nullptr; }

  // An image surface with `frame` painted: over a copy of the backdrop when
  // active and every panel of the frame begins with the very items of the
  // backdrop, else whole. (Items that do not move may still differ between
  // frames: labels placed around the data, a trail of "compare" frames,
  // shadows on a ground set by moving solids; the comparison catches them.)
  // Safe to call from several threads at once.
  SurfacePtr paint(const Figure& frame) const;

 private:
  const scene::Scene& scene_;
  int width_ = 0, height_ = 0;
  double scale_ = 1.0;
  std::vector<std::size_t> leading_;              // per drawing: the items in the backdrop
  std::vector<std::vector<Item>> leading_items_;  // and those items, as frames must begin
  SurfacePtr surface_;                            // null: every frame is painted whole
};

// Per drawing, the number of leading items that do not move.
std::vector<std::size_t> leading_static_items(const Figure& figure);

// Whether painting each panel's rest after every panel's backdrop gives the
// pixels of painting the figure whole (the conditions above).
bool backdrop_is_exact(const scene::Scene& scene, const Figure& figure, double scale);

}  // namespace pita::render
