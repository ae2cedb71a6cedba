// Scenes for the lint tests, written as a user writes them (JSON), and their
// lint (src/lint/lint.hpp).
#pragma once

#include <string>

#include "lint/lint.hpp"
#include "render/figure.hpp"
#include "scene/scene.hpp"

namespace pita::lint::test {

// Three keyframes from (0, 0) to (6, 0); `rest` adds members ("layers", "canvas", ...).
// `canvas` is the "canvas" object.
inline std::string arrow_scene(const std::string& rest,
                               const std::string& canvas = R"({"width": 600, "height": 400})") {
  return R"({"method": "P6", "samples": 9,
    "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 1.2}, {"t": 0.5, "p": [3, 1.5], "m": 0.7, "w": 2},
                  {"t": 1, "p": [6, 0], "m": 1.3, "w": 1.9}],
    "canvas": )" +
         canvas + (rest.empty() ? std::string() : ", " + rest) + "}";
}

inline Report lint_text(const std::string& json) {
  const scene::Scene scene = scene::parse_scene(json, "test.json");
  const motion::Stage stage(scene);
  return lint_figure(stage, render::build_figure(stage), analysis::check_claims(stage));
}

inline int count(const Report& report, const std::string& check) {
  int n = 0;
  for (const Finding& f : report.findings) n += f.check == check ? 1 : 0;
  return n;
}

inline std::string listed(const Report& report) {
  std::string out;
  for (const Finding& f : report.findings) out += describe(f) + "\n";
  return out;
}

}  // namespace pita::lint::test
