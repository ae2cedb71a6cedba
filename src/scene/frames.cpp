#include "scene/frames.hpp"

#include <cmath>
#include <iterator>
#include <stdexcept>
#include <type_traits>

#include <fmt/compile.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace pita::scene {

namespace {

using Json = nlohmann::ordered_json;
using Buffer = FramesBuffer;

// CSV rows use FMT_COMPILE: their format strings are parsed when pita is
// built, not once per row (about a quarter of the time of a million rows).

// Appends text to a printer's buffer.
void append_text(Buffer& out, std::string_view text) { out.append(text.data(), text.data() + text.size()); }

// nlohmann's number form: shortest round-trip digits, "0.0" for zero.
std::string json_number(double x) { return Json(x).dump(); }

std::string json_point(Point point) {
  return fmt::format("[{}, {}]", json_number(point.real()), json_number(point.imag()));
}

// What each kind of row prints, one overload per row type (a type without
// them does not compile): its CSV header, what its JSON head adds after the
// method, whether the frame is finite, and the row itself.
using ArrowRow = std::type_identity<Frame>;
using PointRow = std::type_identity<PointFrame>;
template <class Pose>
using PoseRow = std::type_identity<PoseFrame<Pose>>;

std::string_view csv_header(ArrowRow) { return "t,px,py,m,w,qx,qy\n"; }
std::string_view csv_header(PointRow) { return "t,x,y\n"; }
template <class Pose>
std::string_view csv_header(PoseRow<Pose>) {
  return PoseTraits<Pose>::csv_header;
}

// Arrows and points name their chain; points say which curve they are on.
std::string json_head_extra(ArrowRow, std::string_view chain) {
  return chain.empty() ? "" : ", \"chain\": " + Json(std::string(chain)).dump();
}
std::string json_head_extra(PointRow, std::string_view chain) {
  return json_head_extra(ArrowRow{}, chain) + ", \"curve\": \"pita\"";
}
template <class Pose>
std::string json_head_extra(PoseRow<Pose>, std::string_view) {
  return "";
}

bool is_finite_frame(const Frame& frame) {
  return std::isfinite(frame.t) && is_finite(frame.arrow) && std::isfinite(frame.arrow.q().real()) &&
         std::isfinite(frame.arrow.q().imag());
}
bool is_finite_frame(const PointFrame& frame) {
  return std::isfinite(frame.t) && std::isfinite(frame.p.real()) && std::isfinite(frame.p.imag());
}
template <class Pose>
bool is_finite_frame(const PoseFrame<Pose>& frame) {
  return std::isfinite(frame.t) && frame.pose.L.allFinite() && frame.pose.b.allFinite();
}

// "frame at t = 0.5 is not finite", "point at t = ...": what a row is called.
std::string_view row_noun(const PointFrame&) { return "point"; }
template <class Row>
std::string_view row_noun(const Row&) {
  return "frame";
}

void csv_row(Buffer& out, const Frame& frame) {
  const Point q = frame.arrow.q();
  fmt::format_to(fmt::appender(out), FMT_COMPILE("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n"), frame.t,
                 frame.arrow.p.real(), frame.arrow.p.imag(), frame.arrow.m, frame.arrow.w, q.real(), q.imag());
}
void csv_row(Buffer& out, const PointFrame& frame) {
  fmt::format_to(fmt::appender(out), FMT_COMPILE("{:.17g},{:.17g},{:.17g}\n"), frame.t, frame.p.real(), frame.p.imag());
}
// A pose's matrix row by row: the plane's in one formatting call (the
// million-frame stream of `pita eval` is 2D as often as not), space's a row at a time.
void csv_row(Buffer& out, const PoseFrame<Affine2>& frame) {
  const Affine2& A = frame.pose;
  fmt::format_to(fmt::appender(out), FMT_COMPILE("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n"), frame.t,
                 A.L(0, 0), A.L(0, 1), A.b(0), A.L(1, 0), A.L(1, 1), A.b(1));
}
void csv_row(Buffer& out, const PoseFrame<Affine3>& frame) {
  fmt::format_to(fmt::appender(out), FMT_COMPILE("{:.17g}"), frame.t);
  for (int row = 0; row < 3; ++row) {
    fmt::format_to(fmt::appender(out), FMT_COMPILE(",{:.17g},{:.17g},{:.17g},{:.17g}"), frame.pose.L(row, 0),
                   frame.pose.L(row, 1), frame.pose.L(row, 2), frame.pose.b(row));
  }
  append_text(out, "\n");
}

void json_row(Buffer& out, const Frame& frame) {
  append_text(out, "{\"t\": " + json_number(frame.t));
  append_text(out, ", \"p\": " + json_point(frame.arrow.p));
  append_text(out, ", \"m\": " + json_number(frame.arrow.m));
  append_text(out, ", \"w\": " + json_number(frame.arrow.w));
  append_text(out, ", \"q\": " + json_point(frame.arrow.q()) + "}");
}
void json_row(Buffer& out, const PointFrame& frame) {
  append_text(out, "{\"t\": " + json_number(frame.t) + ", \"p\": " + json_point(frame.p) + "}");
}
// "matrix": the rows [L(r, 0), ..., b(r)] of the pose, in either dimension.
template <class Pose>
void json_row(Buffer& out, const PoseFrame<Pose>& frame) {
  constexpr int n = PoseTraits<Pose>::dimension;
  std::string text = "{\"t\": " + json_number(frame.t) + ", \"matrix\": [";
  for (int row = 0; row < n; ++row) {
    text += row == 0 ? "[" : ", [";
    for (int column = 0; column < n; ++column) text += json_number(frame.pose.L(row, column)) + ", ";
    text += json_number(frame.pose.b(row)) + "]";
  }
  append_text(out, text + "]}");
}

// The whole document of `frames` through a printer.
template <class Row>
std::string whole_text(FramesPrinter<Row> printer, std::span<const Row> frames) {
  Buffer text;
  printer.head(text);
  for (const Row& frame : frames) printer.row(text, frame);
  printer.tail(text);
  return fmt::to_string(text);
}

}  // namespace

template <class Row>
void FramesPrinter<Row>::require_finite(const Row& frame) {
  if (!is_finite_frame(frame)) {
    throw std::invalid_argument(fmt::format("{} at t = {} is not finite", row_noun(frame), frame.t));
  }
}

template <class Row>
FramesPrinter<Row>::FramesPrinter(FramesFormat format, std::string_view method_id, std::string_view chain)
    : format_(format), method_id_(method_id), chain_(chain) {}

template <class Row>
void FramesPrinter<Row>::head(Buffer& out) const {
  if (format_ == FramesFormat::csv) {
    append_text(out, csv_header(std::type_identity<Row>{}));
    return;
  }
  // Written by hand around nlohmann's scalars so that keys keep this order and
  // each frame gets a line of its own (nlohmann prints either one line or one
  // value per line).
  append_text(out, "{\"method\": " + Json(method_id_).dump());
  append_text(out, json_head_extra(std::type_identity<Row>{}, chain_));
  append_text(out, ", \"frames\": [");
}

template <class Row>
void FramesPrinter<Row>::separate(Buffer& out) {
  append_text(out, any_row_ ? ",\n  " : "\n  ");
  any_row_ = true;
}

template <class Row>
void FramesPrinter<Row>::row(Buffer& out, const Row& frame) {
  require_finite(frame);
  if (format_ == FramesFormat::csv) {
    csv_row(out, frame);
    return;
  }
  separate(out);
  json_row(out, frame);
}

template <class Row>
void FramesPrinter<Row>::tail(Buffer& out) const {
  if (format_ == FramesFormat::json) append_text(out, any_row_ ? "\n]}\n" : "]}\n");
}

template class FramesPrinter<Frame>;
template class FramesPrinter<PointFrame>;
template class FramesPrinter<PoseFrame<Affine2>>;
template class FramesPrinter<PoseFrame<Affine3>>;

std::string frames_to_json(std::string_view method_id, std::span<const Frame> frames, std::string_view chain) {
  return whole_text(FramesPrinter<Frame>(FramesFormat::json, method_id, chain), frames);
}

std::string frames_to_csv(std::span<const Frame> frames) {
  return whole_text(FramesPrinter<Frame>(FramesFormat::csv, ""), frames);
}

std::string point_frames_to_json(std::string_view method_id, std::span<const PointFrame> frames,
                                 std::string_view chain) {
  return whole_text(FramesPrinter<PointFrame>(FramesFormat::json, method_id, chain), frames);
}

std::string pose_frames_to_json(std::string_view method_id, std::span<const PoseFrame<Affine2>> frames) {
  return whole_text(FramesPrinter<PoseFrame<Affine2>>(FramesFormat::json, method_id), frames);
}
std::string pose_frames_to_json(std::string_view method_id, std::span<const PoseFrame<Affine3>> frames) {
  return whole_text(FramesPrinter<PoseFrame<Affine3>>(FramesFormat::json, method_id), frames);
}

std::string pose_frames_to_csv(std::span<const PoseFrame<Affine2>> frames) {
  return whole_text(FramesPrinter<PoseFrame<Affine2>>(FramesFormat::csv, ""), frames);
}
std::string pose_frames_to_csv(std::span<const PoseFrame<Affine3>> frames) {
  return whole_text(FramesPrinter<PoseFrame<Affine3>>(FramesFormat::csv, ""), frames);
}

}  // namespace pita::scene
