// Frames of a motion and the writers that print them (JSON and CSV). They live
// in the scene layer because it is the only one that includes nlohmann-json.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "core/arrow.hpp"

namespace pita::scene {

// The arrow D(t) of a motion at time t.
struct Frame {
  double t = 0.0;
  Arrow arrow;
};

// {"method": "P6", "frames": [
//   {"t": 0.0, "p": [x, y], "m": 1.5, "w": 0.3, "q": [x, y]},
//   ...
// ]}
// One frame per line, keys in that order, every number in the shortest form
// that reads back to the same double. Ends with a newline. Throws
// std::invalid_argument if a frame is not finite (JSON has no NaN or inf).
std::string frames_to_json(std::string_view method_id, std::span<const Frame> frames);

// The header "t,px,py,m,w,qx,qy", then one line per frame, numbers written
// with "{:.17g}" (17 significant digits read back exactly). Throws
// std::invalid_argument if a frame is not finite.
std::string frames_to_csv(std::span<const Frame> frames);

}  // namespace pita::scene
