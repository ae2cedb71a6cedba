#include "scene/frames.hpp"

#include <cmath>
#include <iterator>
#include <stdexcept>

#include <fmt/compile.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace pita::scene {

namespace {

using Json = nlohmann::ordered_json;

template <class PoseFrameType>
void require_pose_finite(const PoseFrameType& frame) {
  if (!std::isfinite(frame.t) || !frame.pose.L.allFinite() || !frame.pose.b.allFinite()) {
    throw std::invalid_argument(fmt::format("frame at t = {} is not finite", frame.t));
  }
}

// CSV rows use FMT_COMPILE: their format strings are parsed when pita is
// built, not once per row (about a quarter of the time of a million rows).

// Appends text to a printer's buffer.
void append_text(FramesPrinter::Buffer& out, std::string_view text) {
  out.append(text.data(), text.data() + text.size());
}

// nlohmann's number form: shortest round-trip digits, "0.0" for zero.
std::string json_number(double x) { return Json(x).dump(); }

std::string json_point(Point point) {
  return fmt::format("[{}, {}]", json_number(point.real()), json_number(point.imag()));
}

// The rows of a 3D pose: [a, b, c, tx] and so on.
std::string pose_rows3(const Affine3& A) {
  std::string text = "[";
  for (int row = 0; row < 3; ++row) {
    text += fmt::format("{}[{}, {}, {}, {}]", row == 0 ? "" : ", ", json_number(A.L(row, 0)), json_number(A.L(row, 1)),
                        json_number(A.L(row, 2)), json_number(A.b(row)));
  }
  return text + "]";
}

const char* csv_header(FramesPrinter::Rows rows) {
  switch (rows) {
    case FramesPrinter::Rows::arrows: return "t,px,py,m,w,qx,qy\n";
    case FramesPrinter::Rows::points: return "t,x,y\n";
    case FramesPrinter::Rows::poses: return "t,a,b,tx,c,d,ty\n";
    case FramesPrinter::Rows::poses3: return "t,a,b,c,tx,d,e,f,ty,g,h,i,tz\n";
  }
  return "";
}

// The whole document of `frames` through a printer.
template <class FrameType>
std::string whole_text(FramesPrinter printer, std::span<const FrameType> frames) {
  FramesPrinter::Buffer text;
  printer.head(text);
  for (const FrameType& frame : frames) printer.row(text, frame);
  printer.tail(text);
  return fmt::to_string(text);
}

}  // namespace

void FramesPrinter::require_finite(const Frame& frame) {
  if (!std::isfinite(frame.t) || !is_finite(frame.arrow) || !std::isfinite(frame.arrow.q().real()) ||
      !std::isfinite(frame.arrow.q().imag())) {
    throw std::invalid_argument(fmt::format("frame at t = {} is not finite", frame.t));
  }
}

void FramesPrinter::require_finite(const PointFrame& frame) {
  if (!std::isfinite(frame.t) || !std::isfinite(frame.p.real()) || !std::isfinite(frame.p.imag())) {
    throw std::invalid_argument(fmt::format("point at t = {} is not finite", frame.t));
  }
}

void FramesPrinter::require_finite(const PoseFrame& frame) { require_pose_finite(frame); }
void FramesPrinter::require_finite(const PoseFrame3& frame) { require_pose_finite(frame); }

FramesPrinter::FramesPrinter(Rows rows, FramesFormat format, std::string_view method_id, std::string_view chain)
    : rows_(rows), format_(format), method_id_(method_id), chain_(chain) {}

void FramesPrinter::head(FramesPrinter::Buffer& out) const {
  if (format_ == FramesFormat::csv) {
    append_text(out, csv_header(rows_));
    return;
  }
  // Written by hand around nlohmann's scalars so that keys keep this order and
  // each frame gets a line of its own (nlohmann prints either one line or one
  // value per line).
  append_text(out, "{\"method\": " + Json(method_id_).dump());
  const bool has_chain = rows_ == Rows::arrows || rows_ == Rows::points;
  if (has_chain && !chain_.empty()) append_text(out, ", \"chain\": " + Json(chain_).dump());
  if (rows_ == Rows::points) append_text(out, ", \"curve\": \"pita\"");
  append_text(out, ", \"frames\": [");
}

void FramesPrinter::separate(FramesPrinter::Buffer& out) {
  append_text(out, any_row_ ? ",\n  " : "\n  ");
  any_row_ = true;
}

void FramesPrinter::row(FramesPrinter::Buffer& out, const Frame& frame) {
  require_finite(frame);
  const Point q = frame.arrow.q();
  if (format_ == FramesFormat::csv) {
    fmt::format_to(fmt::appender(out), FMT_COMPILE("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n"), frame.t,
                   frame.arrow.p.real(), frame.arrow.p.imag(), frame.arrow.m, frame.arrow.w, q.real(), q.imag());
    return;
  }
  separate(out);
  append_text(out, "{\"t\": " + json_number(frame.t));
  append_text(out, ", \"p\": " + json_point(frame.arrow.p));
  append_text(out, ", \"m\": " + json_number(frame.arrow.m));
  append_text(out, ", \"w\": " + json_number(frame.arrow.w));
  append_text(out, ", \"q\": " + json_point(q) + "}");
}

void FramesPrinter::row(FramesPrinter::Buffer& out, const PointFrame& frame) {
  require_finite(frame);
  if (format_ == FramesFormat::csv) {
    fmt::format_to(fmt::appender(out), FMT_COMPILE("{:.17g},{:.17g},{:.17g}\n"), frame.t, frame.p.real(), frame.p.imag());
    return;
  }
  separate(out);
  append_text(out, "{\"t\": " + json_number(frame.t) + ", \"p\": " + json_point(frame.p) + "}");
}

void FramesPrinter::row(FramesPrinter::Buffer& out, const PoseFrame& frame) {
  require_finite(frame);
  const Affine2& A = frame.pose;
  if (format_ == FramesFormat::csv) {
    fmt::format_to(fmt::appender(out), FMT_COMPILE("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n"), frame.t,
                   A.L(0, 0), A.L(0, 1), A.b(0), A.L(1, 0), A.L(1, 1), A.b(1));
    return;
  }
  separate(out);
  append_text(out, "{\"t\": " + json_number(frame.t));
  fmt::format_to(fmt::appender(out), ", \"matrix\": [[{}, {}, {}], [{}, {}, {}]]}}", json_number(A.L(0, 0)),
                 json_number(A.L(0, 1)), json_number(A.b(0)), json_number(A.L(1, 0)), json_number(A.L(1, 1)),
                 json_number(A.b(1)));
}

void FramesPrinter::row(FramesPrinter::Buffer& out, const PoseFrame3& frame) {
  require_finite(frame);
  if (format_ == FramesFormat::csv) {
    fmt::format_to(fmt::appender(out), FMT_COMPILE("{:.17g}"), frame.t);
    for (int row = 0; row < 3; ++row) {
      fmt::format_to(fmt::appender(out), FMT_COMPILE(",{:.17g},{:.17g},{:.17g},{:.17g}"), frame.pose.L(row, 0),
                     frame.pose.L(row, 1), frame.pose.L(row, 2), frame.pose.b(row));
    }
    append_text(out, "\n");
    return;
  }
  separate(out);
  append_text(out, "{\"t\": " + json_number(frame.t) + ", \"matrix\": " + pose_rows3(frame.pose) + "}");
}

void FramesPrinter::tail(FramesPrinter::Buffer& out) const {
  if (format_ == FramesFormat::json) append_text(out, any_row_ ? "\n]}\n" : "]}\n");
}

std::string frames_to_json(std::string_view method_id, std::span<const Frame> frames, std::string_view chain) {
  return whole_text(FramesPrinter(FramesPrinter::Rows::arrows, FramesFormat::json, method_id, chain), frames);
}

std::string frames_to_csv(std::span<const Frame> frames) {
  return whole_text(FramesPrinter(FramesPrinter::Rows::arrows, FramesFormat::csv, ""), frames);
}

std::string point_frames_to_json(std::string_view method_id, std::span<const PointFrame> frames,
                                 std::string_view chain) {
  return whole_text(FramesPrinter(FramesPrinter::Rows::points, FramesFormat::json, method_id, chain), frames);
}

std::string pose_frames_to_json(std::string_view method_id, std::span<const PoseFrame> frames) {
  return whole_text(FramesPrinter(FramesPrinter::Rows::poses, FramesFormat::json, method_id), frames);
}

std::string pose_frames_to_csv(std::span<const PoseFrame> frames) {
  return whole_text(FramesPrinter(FramesPrinter::Rows::poses, FramesFormat::csv, ""), frames);
}

std::string pose_frames_to_json(std::string_view method_id, std::span<const PoseFrame3> frames) {
  return whole_text(FramesPrinter(FramesPrinter::Rows::poses3, FramesFormat::json, method_id), frames);
}

std::string pose_frames_to_csv(std::span<const PoseFrame3> frames) {
  return whole_text(FramesPrinter(FramesPrinter::Rows::poses3, FramesFormat::csv, ""), frames);
}

}  // namespace pita::scene
