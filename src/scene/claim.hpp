// "claims": what a figure's caption says, as predicates over the measures of
// its panels (docs/reference/check.md "Claims"), checked by `pita check` and warned about by
// `pita render` (analysis/claims.hpp). For example
//   {"says": "P8 changes the scale between frames less than P1",
//    "panel": 3, "measure": "scale-step", "below": {"panel": 0}}
//   {"says": "moving B.q turns D(1/4) around",
//    "panel": 1, "measure": "angle:/panels/0@0.25", "above": 1.5708, "absolute": true}
#pragma once

#include <cstddef>
#include <string>
#include <variant>
#include <vector>

#include "scene/measure_name.hpp"

namespace pita::scene {

// A measure of a panel, scaled and shifted: times x measure + plus.
struct ClaimOperand {
  std::size_t panel = 0;  // index into Scene::panels
  MeasureName measure;
  double times = 1.0;
  double plus = 0.0;
};

// The bound of "below" and "above": a number, or a measure of a panel.
using ClaimBound = std::variant<double, ClaimOperand>;

struct Below {  // value < bound
  ClaimBound bound;
};
struct Above {  // value > bound
  ClaimBound bound;
};
struct Near {  // |value - target| <= within
  ClaimBound target;
  double within = 0.0;
};
struct Is {  // a yes-or-no measure ("pop"): 1 for yes, 0 for no
  bool yes = true;
};
using ClaimTest = std::variant<Below, Above, Near, Is>;

struct Claim {
  std::string pointer;  // "/claims/2"
  std::string says;     // the caption's statement, in words
  std::size_t panel = 0;
  // "layer": a frame-distance claim measures the motion this layer of the
  // panel draws (its own method or options, N57) instead of the panel's.
  std::optional<std::size_t> layer;
  MeasureName measure;
  bool absolute = false;  // compare |value| (a signed angle turned either way)
  ClaimTest test;
};

}  // namespace pita::scene
