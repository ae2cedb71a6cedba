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
#include "core/pose_traits.hpp"

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
// (the CSV, printed by FramesPrinter<PointFrame>, is "t,x,y"). Throws
// std::invalid_argument if a point is not finite.
struct PointFrame {
  double t = 0.0;
  Point p;
};
std::string point_frames_to_json(std::string_view method_id, std::span<const PointFrame> frames,
                                 std::string_view chain = "");

// The pose A(t) of a pose scene's motion at time t: an affinity of the plane
// (Affine2) or of space (Affine3).
template <class Pose>
struct PoseFrame {
  double t = 0.0;
  Pose pose;
};

// {"method": "SAM", "frames": [
//   {"t": 0.0, "matrix": [[a, b, tx], [c, d, ty]]},
//   ...
// ]}
// (x -> [[a, b], [c, d]] x + [tx, ty]), one frame per line, shortest
// round-trip numbers; in space the rows are [a, b, c, tx], [d, e, f, ty],
// [g, h, i, tz]. Throws std::invalid_argument if a frame is not finite.
// (One template inside, FramesPrinter<PoseFrame<Pose>>; an overload per
// dimension here, so that a vector of frames converts to the span.)
std::string pose_frames_to_json(std::string_view method_id, std::span<const PoseFrame<Affine2>> frames);
std::string pose_frames_to_json(std::string_view method_id, std::span<const PoseFrame<Affine3>> frames);

// The header PoseTraits<Pose>::csv_header ("t,a,b,tx,c,d,ty" in the plane,
// "t,a,b,c,tx,d,e,f,ty,g,h,i,tz" in space), then one line per frame ("{:.17g}").
std::string pose_frames_to_csv(std::span<const PoseFrame<Affine2>> frames);
std::string pose_frames_to_csv(std::span<const PoseFrame<Affine3>> frames);

enum class FramesFormat { json, csv };

// The documents above, printed piece by piece: head(), then row() for each
// frame in order, then tail(); each appends its text to `out` (fmt's buffer:
// formatting into it is about twice as fast as into a std::string). The
// concatenation is byte for byte the text of the matching *_to_json or
// *_to_csv function. row() throws std::invalid_argument, as they do, for a
// frame that is not finite, and appends nothing then. What the rows hold is
// the type Row: Frame (arrows), PointFrame (the points of a curve), or
// PoseFrame<Affine2> and PoseFrame<Affine3> (poses); instantiated for those.
template <class Row>
class FramesPrinter {
 public:
  // `chain` is printed for arrows and points only (poses have no chain).
  FramesPrinter(FramesFormat format, std::string_view method_id, std::string_view chain = "");

  using Buffer = fmt::memory_buffer;
  void head(Buffer& out) const;
  void row(Buffer& out, const Row& frame);
  void tail(Buffer& out) const;

  // What row() checks first, alone: throws std::invalid_argument, with the
  // same message, for a frame that is not finite.
  static void require_finite(const Row& frame);

 private:
  void separate(Buffer& out);  // JSON: the text before a row

  FramesFormat format_;
  std::string method_id_;
  std::string chain_;
  bool any_row_ = false;
};

// The buffer every printer appends to.
using FramesBuffer = fmt::memory_buffer;

}  // namespace pita::scene
