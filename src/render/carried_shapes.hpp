// The shapes of a scene ("shapes": outlines and images in the shapes' own
// frame) mapped onto the plane by one affinity: the pose A(t) of a pose scene,
// or the carrier similarity taking the handle onto D(t) in an arrow scene
// (PITA Sec. 7.1, core/carrier.hpp). Shared by both kinds of panels.
#pragma once

#include <vector>

#include "core/affine2.hpp"
#include "render/drawing.hpp"
#include "scene/figure.hpp"

namespace pita::render {

// The drawn shapes of `shapes` under `map`, styled by `layer`, every opacity
// multiplied by `fade` (1: as given; the older frames of an animation's trail
// fade). An image is drawn upright in its box: its top row along the box's top
// edge (the larger y when `y_up`, else the smaller).
std::vector<Shape> carried_shapes(const std::vector<scene::ShapeOutline>& shapes, const Affine2& map,
                                  const scene::ShapesLayer& layer, bool y_up, double fade = 1.0);

// Pixel coordinates of `image` (its PNG, v down) -> the shapes' frame.
Affine2 image_placement(const scene::ShapeOutline& image, bool y_up);

}  // namespace pita::render
