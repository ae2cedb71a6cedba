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
#include <string_view>

#include <nlohmann/json.hpp>

#include "render/figure.hpp"
#include "scene/scene.hpp"

namespace pita::golden {

using Json = nlohmann::ordered_json;

Json figure_data(const std::string& scene_name, const scene::Scene& scene, const render::Figure& figure);

// The data as text: one item per line, numbers in the shortest form that
// reads back exactly, ending with a newline.
std::string figure_data_text(const Json& data);

// A golden data file's text read back, as hostile input: the scene reader's
// JSON checks (nesting depth, NUL bytes, members given twice; SceneError at a
// line and column), then the shape above: "panels" an array of objects with a
// string "pointer", a finite "extent" >= 0 and an array of "items", each an
// object whose "layer" (if any) is a string and "index" (if any) an integer.
// A wrong shape throws GoldenError "FILE: POINTER: what is wrong".
Json read_figure_data(std::string_view text, const std::string& file);

}  // namespace pita::golden
