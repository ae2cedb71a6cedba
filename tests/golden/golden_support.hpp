// Shared by the golden tests: a P6 scene with two panels and its figure data.
#pragma once

#include <string>

#include "golden/figure_data.hpp"
#include "render/figure.hpp"
#include "scene/scene.hpp"

namespace pita::golden {

// Three keyframes, pattern, discrepancy and keyframes layers, panels P3 and P6.
inline const char* const kScene = R"({"method": "P6", "keyframes": [
  {"t": 0, "p": [0, 0], "m": 1, "w": 0.4}, {"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": 2.0},
  {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}],
  "layers": [{"type": "pattern"}, {"type": "discrepancy"}, {"type": "keyframes"}],
  "panels": ["P3", "P6"]})";

inline Json data_of(const std::string& text) {
  const scene::Scene s = scene::parse_scene(text, "s.json");
  return figure_data("s", s, render::build_figure(s));
}

// The scene with B.p.x written as `x` (instead of 3).
inline std::string with_moved_keyframe(const std::string& x) {
  std::string text = kScene;
  const std::string from = R"("p": [3, 1.5])";
  text.replace(text.find(from), from.size(), "\"p\": [" + x + ", 1.5]");
  return text;
}

}  // namespace pita::golden
