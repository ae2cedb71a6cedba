#include "scene/frames.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace pita::scene {

namespace {

using Json = nlohmann::ordered_json;

void require_finite(const Frame& frame) {
  if (!std::isfinite(frame.t) || !is_finite(frame.arrow) || !std::isfinite(frame.arrow.q().real()) ||
      !std::isfinite(frame.arrow.q().imag())) {
    throw std::invalid_argument(fmt::format("frame at t = {} is not finite", frame.t));
  }
}

// nlohmann's number form: shortest round-trip digits, "0.0" for zero.
std::string json_number(double x) { return Json(x).dump(); }

std::string json_point(Point point) {
  return fmt::format("[{}, {}]", json_number(point.real()), json_number(point.imag()));
}

}  // namespace

std::string frames_to_json(std::string_view method_id, std::span<const Frame> frames, std::string_view chain) {
  // Written by hand around nlohmann's scalars so that keys keep this order and
  // each frame gets a line of its own (nlohmann prints either one line or one
  // value per line).
  std::string text = "{\"method\": " + Json(std::string(method_id)).dump();
  if (!chain.empty()) text += ", \"chain\": " + Json(std::string(chain)).dump();
  text += ", \"frames\": [";
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const Frame& frame = frames[i];
    require_finite(frame);
    text += i == 0 ? "\n  " : ",\n  ";
    text += "{\"t\": " + json_number(frame.t);
    text += ", \"p\": " + json_point(frame.arrow.p);
    text += ", \"m\": " + json_number(frame.arrow.m);
    text += ", \"w\": " + json_number(frame.arrow.w);
    text += ", \"q\": " + json_point(frame.arrow.q()) + "}";
  }
  text += frames.empty() ? "]}\n" : "\n]}\n";
  return text;
}

std::string frames_to_csv(std::span<const Frame> frames) {
  std::string text = "t,px,py,m,w,qx,qy\n";
  for (const Frame& frame : frames) {
    require_finite(frame);
    const Point q = frame.arrow.q();
    text += fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", frame.t,
                        frame.arrow.p.real(), frame.arrow.p.imag(), frame.arrow.m, frame.arrow.w,
                        q.real(), q.imag());
  }
  return text;
}

namespace {

void require_finite(const PointFrame& frame) {
  if (!std::isfinite(frame.t) || !std::isfinite(frame.p.real()) || !std::isfinite(frame.p.imag())) {
    throw std::invalid_argument(fmt::format("point at t = {} is not finite", frame.t));
  }
}

}  // namespace

std::string point_frames_to_json(std::string_view method_id, std::span<const PointFrame> frames,
                                 std::string_view chain) {
  std::string text = "{\"method\": " + Json(std::string(method_id)).dump();
  if (!chain.empty()) text += ", \"chain\": " + Json(std::string(chain)).dump();
  text += ", \"curve\": \"pita\", \"frames\": [";
  for (std::size_t i = 0; i < frames.size(); ++i) {
    require_finite(frames[i]);
    text += i == 0 ? "\n  " : ",\n  ";
    text += "{\"t\": " + json_number(frames[i].t) + ", \"p\": " + json_point(frames[i].p) + "}";
  }
  text += frames.empty() ? "]}\n" : "\n]}\n";
  return text;
}

std::string point_frames_to_csv(std::span<const PointFrame> frames) {
  std::string text = "t,x,y\n";
  for (const PointFrame& frame : frames) {
    require_finite(frame);
    text += fmt::format("{:.17g},{:.17g},{:.17g}\n", frame.t, frame.p.real(), frame.p.imag());
  }
  return text;
}

namespace {

template <class Frame>
void require_finite(const Frame& frame) {
  if (!std::isfinite(frame.t) || !frame.pose.L.allFinite() || !frame.pose.b.allFinite()) {
    throw std::invalid_argument(fmt::format("frame at t = {} is not finite", frame.t));
  }
}

}  // namespace

std::string pose_frames_to_json(std::string_view method_id, std::span<const PoseFrame> frames) {
  std::string text = "{\"method\": " + Json(std::string(method_id)).dump() + ", \"frames\": [";
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const PoseFrame& frame = frames[i];
    require_finite(frame);
    const Affine2& A = frame.pose;
    text += i == 0 ? "\n  " : ",\n  ";
    text += "{\"t\": " + json_number(frame.t);
    text += fmt::format(", \"matrix\": [[{}, {}, {}], [{}, {}, {}]]}}", json_number(A.L(0, 0)),
                        json_number(A.L(0, 1)), json_number(A.b(0)), json_number(A.L(1, 0)),
                        json_number(A.L(1, 1)), json_number(A.b(1)));
  }
  text += frames.empty() ? "]}\n" : "\n]}\n";
  return text;
}

std::string pose_frames_to_csv(std::span<const PoseFrame> frames) {
  std::string text = "t,a,b,tx,c,d,ty\n";
  for (const PoseFrame& frame : frames) {
    require_finite(frame);
    const Affine2& A = frame.pose;
    text += fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", frame.t,
                        A.L(0, 0), A.L(0, 1), A.b(0), A.L(1, 0), A.L(1, 1), A.b(1));
  }
  return text;
}

// The rows of a 3D pose: [a, b, c, tx] and so on.
static std::string pose_rows3(const Affine3& A) {
  std::string text = "[";
  for (int row = 0; row < 3; ++row) {
    text += fmt::format("{}[{}, {}, {}, {}]", row == 0 ? "" : ", ", json_number(A.L(row, 0)), json_number(A.L(row, 1)),
                        json_number(A.L(row, 2)), json_number(A.b(row)));
  }
  return text + "]";
}

std::string pose_frames_to_json(std::string_view method_id, std::span<const PoseFrame3> frames) {
  std::string text = "{\"method\": " + Json(std::string(method_id)).dump() + ", \"frames\": [";
  for (std::size_t i = 0; i < frames.size(); ++i) {
    require_finite(frames[i]);
    text += i == 0 ? "\n  " : ",\n  ";
    text += "{\"t\": " + json_number(frames[i].t) + ", \"matrix\": " + pose_rows3(frames[i].pose) + "}";
  }
  text += frames.empty() ? "]}\n" : "\n]}\n";
  return text;
}

std::string pose_frames_to_csv(std::span<const PoseFrame3> frames) {
  std::string text = "t,a,b,c,tx,d,e,f,ty,g,h,i,tz\n";
  for (const PoseFrame3& frame : frames) {
    require_finite(frame);
    text += fmt::format("{:.17g}", frame.t);
    for (int row = 0; row < 3; ++row) {
      text += fmt::format(",{:.17g},{:.17g},{:.17g},{:.17g}", frame.pose.L(row, 0), frame.pose.L(row, 1),
                          frame.pose.L(row, 2), frame.pose.b(row));
    }
    text += "\n";
  }
  return text;
}

}  // namespace pita::scene
