// "place": "auto" labels (scene "label" layers, and the labels pita puts
// beside data): each moved around its point to the first spot where its ink
// covers no data, no other text and no legend, and stays in its panel.
#pragma once

#include <array>
#include <vector>

#include "render/drawing.hpp"
#include "render/layout.hpp"
#include "scene/scene.hpp"

namespace pita::render {

// Where an auto label may go, in order: its ink's box beside its point, on
// the right (as an "at" label starts), above right, above, above left, left,
// below left, below, below right; each at a gap of kSpotGaps times its size,
// the nearer ring first.
enum class Spot { right, above_right, above, above_left, left, below_left, below, below_right };
inline constexpr std::array<Spot, 8> kSpots = {Spot::right, Spot::above_right, Spot::above, Spot::above_left,
                                               Spot::left,  Spot::below_left,  Spot::below, Spot::below_right};
inline constexpr std::array<double, 2> kSpotGaps = {0.3, 1.2};

// The box a text of ink box `ink` (canvas pixels, where it is drawn starting
// at its point `at`) takes at `spot`, `gap` pixels from `at`.
Rect spot_box(const Rect& ink, Point at, Spot spot, double gap);

// Sets the `shift` of every label of `drawings` with `avoid_data`, panel by
// panel under `placements`: the label's ink moves to the first spot (of the
// ring nearest first) where it meets no data shape, no text placed before
// it, no legend, and stays inside its panel's drawing area; if none is free,
// to the spot that meets the fewest; the label's point itself when that is
// free. Texts are measured as the painter draws them (`font`).
void place_labels(const scene::Scene& scene, std::vector<Drawing>& drawings,
                  const std::vector<PanelPlacement>& placements);

}  // namespace pita::render
