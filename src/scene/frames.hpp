// Frames of a motion and the writers that print them (JSON and CSV). They live
// in the scene layer because it is the only one that includes nlohmann-json.
// FramesPrinter prints a document row by row, for writers that stream it (a
// million frames of `pita eval` in flat memory); the *_to_json / *_to_csv
// functions build the whole text with it.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include <fmt/format.h>

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
// Throws std::invalid_argument if a point is not finite. (Their CSV, "t,x,y",
// is written by FramesPrinter, below.)
struct PointFrame {
  double t = 0.0;
  Point p;
};
std::string point_frames_to_json(std::string_view method_id, std::span<const PointFrame> frames,
                                 std::string_view chain = "");

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

enum class FramesFormat { json, csv };

// The documents above, printed piece by piece: head(), then row() for each
// frame in order, then tail(); each appends its text to `out` (fmt's buffer:
// formatting into it is about twice as fast as into a std::string). The
// concatenation is byte for byte the text of the matching *_to_json or
// *_to_csv function. row() throws std::invalid_argument, as they do, for a
// frame that is not finite, and appends nothing then.
class FramesPrinter {
 public:
  // What the rows hold: arrows, the points of a curve, poses of the plane or of space.
  enum class Rows { arrows, points, poses, poses3 };

  // `chain` is printed for arrows and points only (the others have no chain).
  FramesPrinter(Rows rows, FramesFormat format, std::string_view method_id, std::string_view chain = "");

  using Buffer = fmt::memory_buffer;
  void head(Buffer& out) const;
  void row(Buffer& out, const Frame& frame);
  void row(Buffer& out, const PointFrame& frame);
  void row(Buffer& out, const PoseFrame& frame);
  void row(Buffer& out, const PoseFrame3& frame);
  void tail(Buffer& out) const;

  // What row() checks first, alone: throws std::invalid_argument, with the
  // same message, for a frame that is not finite.
  static void require_finite(const Frame& frame);
  static void require_finite(const PointFrame& frame);
  static void require_finite(const PoseFrame& frame);
  static void require_finite(const PoseFrame3& frame);

 private:
  void separate(Buffer& out);  // JSON: the text before a row

  Rows rows_;
  FramesFormat format_;
  std::string method_id_;
  std::string chain_;
  bool any_row_ = false;
};

}  // namespace pita::scene
