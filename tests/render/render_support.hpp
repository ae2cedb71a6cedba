// Scenes built in code for the render tests (independent of the JSON reader).
#pragma once

#include <cmath>

#include "core/pitas/registry.hpp"
#include "scene/scene.hpp"
#include "support/keys.hpp"

namespace pita::render::test {

inline scene::Panel panel(Method method, std::vector<Keyframe> keyframes, int samples = 9) {
  scene::Panel p;
  track_keys(p).method = method;
  arrow_keys(p).keyframes = std::move(keyframes);
  p.samples = samples;
  p.title = method_id(p.keys);
  return p;
}

inline std::vector<Keyframe> three_keyframes() {
  return {{0.0, Arrow{{0.0, 0.0}, 1.0, 1.2}}, {0.5, Arrow{{3.0, 1.5}, 0.7, 2.0}}, {1.0, Arrow{{6.0, 0.0}, 1.3, 1.9}}};
}

inline scene::Scene scene_with(std::vector<scene::Layer> layers, std::vector<scene::Panel> panels) {
  scene::Scene s;
  s.path = "test.json";
  s.keys = panels.front().keys;
  scene::figure_of<scene::KeyframeKeys>(s).layers = std::move(layers);
  s.panels = std::move(panels);
  return s;
}

// Eight panels (P1-P8) of the same keyframes, four columns, titled.
inline scene::Scene eight_panels() {
  std::vector<scene::Panel> panels;
  for (Method m : {Method::P1, Method::P2, Method::P3, Method::P4, Method::P5, Method::P6, Method::P7, Method::P8}) {
    panels.push_back(panel(m, three_keyframes()));
  }
  scene::Scene s = scene_with({scene::PatternLayer{}, scene::KeyframesLayer{}}, panels);
  s.title = "Eight PITAs";
  s.canvas.width = 1200;
  s.canvas.height = 900;
  s.canvas.columns = 4;
  return s;
}

}  // namespace pita::render::test
