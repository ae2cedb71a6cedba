// Frames of a motion and the writers that print them (JSON and CSV). They live
// in the scene layer because it is the only one that includes nlohmann-json.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "core/affine2.hpp"
#include "core/affine3.hpp"
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
std::string frames_to_json(std::string_view method_id, std::span<const Frame> frames, std::string_view chain = "");

// The header "t,px,py,m,w,qx,qy", then one line per frame, numbers written
// with "{:.17g}" (17 significant digits read back exactly). Throws
// std::invalid_argument if a frame is not finite.
std::string frames_to_csv(std::span<const Frame> frames);

// The points of a curve through timed "points" (PITA Sec. 7.6):
//   {"method": "P6", "curve": "pita", "frames": [{"t": 0.0, "p": [x, y]}, ...]}
// and the CSV "t,x,y". Throw std::invalid_argument if a point is not finite.
struct PointFrame {
  double t = 0.0;
  Point p;
};
std::string point_frames_to_json(std::string_view method_id, std::span<const PointFrame> frames,
                                 std::string_view chain = "");
std::string point_frames_to_csv(std::span<const PointFrame> frames);

// The pose A(t) of a pose scene's motion at time t.
struct PoseFrame {
  double t = 0.0;
  Affine2 pose;
};

// {"method": "SAM", "frames": [
//   {"t": 0.0, "matrix": [[a, b, tx], [c, d, ty]]},
//   ...
// ]}
// (x -> [[a, b], [c, d]] x + [tx, ty]), one frame per line, shortest
// round-trip numbers. Throws std::invalid_argument if a frame is not finite.
std::string pose_frames_to_json(std::string_view method_id, std::span<const PoseFrame> frames);

// The header "t,a,b,tx,c,d,ty", then one line per frame ("{:.17g}").
std::string pose_frames_to_csv(std::span<const PoseFrame> frames);

// The pose A(t) of a 3D pose scene's motion at time t.
struct PoseFrame3 {
  double t = 0.0;
  Affine3 pose;
};

// {"method": "SAM", "frames": [
//   {"t": 0.0, "matrix": [[a, b, c, tx], [d, e, f, ty], [g, h, i, tz]]},
//   ...
// ]}
// (x -> [[a, b, c], [d, e, f], [g, h, i]] x + [tx, ty, tz]), as for 2D.
std::string pose_frames_to_json(std::string_view method_id, std::span<const PoseFrame3> frames);

// The header "t,a,b,c,tx,d,e,f,ty,g,h,i,tz", then one line per frame.
std::string pose_frames_to_csv(std::span<const PoseFrame3> frames);

}  // namespace pita::scene
