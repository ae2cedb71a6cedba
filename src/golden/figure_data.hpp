// The numbers a figure draws, as JSON, in full precision: the golden data
// file (golden/<scene>/<scene>.data.json) and what `pita check` compares
// first. One object per panel, one item per shape, in drawing order:
//
// {"scene": "fig01-eight-pitas", "panels": [
//   {"pointer": "/panels/0", "title": "P1 Pa-Ca", "extent": 7.21, "items": [
//     {"layer": "/layers/0", "index": 0, "polyline": [[x, y], [x, y]]},
//     {"layer": "/layers/1", "index": -1, "filled": [[[x, y], ...], ...]},
//     {"layer": "/layers/2", "index": 3, "circle": {"center": [x, y], "radius": r}},
//     {"layer": "/layers/3", "index": 1, "arrow": [[x, y], [x, y]]},
//     {"layer": "/layers/4", "index": -1, "label": {"text": "...", "at": [x, y]}}]}]}
//
// "extent" is the diagonal of the panel's drawing (world units): the scale
// against which number tolerances are relative.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "render/figure.hpp"
#include "scene/scene.hpp"

namespace pita::golden {

using Json = nlohmann::ordered_json;

Json figure_data(const std::string& scene_name, const scene::Scene& scene,
                 const render::Figure& figure);

// The data as text: one item per line, numbers in the shortest form that
// reads back exactly, ending with a newline.
std::string figure_data_text(const Json& data);

}  // namespace pita::golden
