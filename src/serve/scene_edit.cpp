#include "serve/scene_edit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <regex>
#include <stdexcept>
#include <variant>

#include <Eigen/Dense>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/affine2.hpp"
#include "core/overloaded.hpp"
#include "serve/camera_edit.hpp"
#include "serve/json_edit.hpp"

namespace pita::serve {

namespace {

using Json = nlohmann::ordered_json;

// Where the keys a panel draws are given in the file: its own "keyframes" or
// "poses", else the scene's.
std::string keys_pointer(const std::string& text, const scene::Scene& scene, const scene::Panel& panel) {
  const std::string field = scene::keys_field(panel.keys);
  if (!panel.pointer.empty()) {
    try {
      value_span(text, panel.pointer + field);
      return panel.pointer + field;
    } catch (const std::invalid_argument&) {
      // the panel draws the scene's
    }
  }
  return scene::keys_field(scene.keys);
}

// The canvas point of a world point, and back.
Point world_of(const render::ViewTransform& view, Point canvas) {
  const Point d = canvas - view.canvas_center;
  return view.world_center + Point{d.real(), view.y_up ? -d.imag() : d.imag()} / view.scale;
}

// A dragged point, each coordinate to a tenth of the pixel (`step`, in world units).
std::string point_json(Point p, double step) {
  return fmt::format("[{}, {}]", rounded_json(p.real(), step), rounded_json(p.imag(), step));
}

// The reference triangle's corners moved by a pose of the scene's.
std::array<Point, 3> corners(const scene::Scene& scene, const scene::PlanePoseKeys& keys, const Affine2& pose) {
  const std::array<Point, 3>& reference = scene::figure_of(scene, keys).reference;
  std::array<Point, 3> out;
  for (int j = 0; j < 3; ++j) out[j] = apply(pose, reference[j]);
  return out;
}

}  // namespace

void check_change(const std::string& text, const Change& change) {
  if (is_camera_pointer(change.pointer)) return check_camera_change(change);
  if (change.remove) throw std::invalid_argument("\"" + change.pointer + "\" is not a member an edit may remove");
  // /keyframes/K/(p|q|m|w|t), /poses/K/(triangle/J|matrix|t), /points/K/t, or the same under /panels/N.
  static const std::regex editable(
      R"(^(/panels/[0-9]+)?/(keyframes/[0-9]+/(p|q|m|w|t)|poses/[0-9]+/(t|triangle/[0-2]|matrix(/[01]/[0-2])?)|points/[0-9]+/t)$)");
  if (!std::regex_match(change.pointer, editable)) {
    throw std::invalid_argument("\"" + change.pointer + "\" is not a value a drag writes");
  }
  try {
    const Json parsed = Json::parse(change.value);  // exactly one JSON value, nothing after it
    if (parsed.is_discarded()) throw std::invalid_argument("not JSON");
  } catch (const Json::exception&) {
    throw std::invalid_argument("the value for " + change.pointer + " is not one JSON value");
  }
  value_span(text, change.pointer);  // and it is there to be replaced
}

std::vector<KeyRow> key_rows(const std::string& text, const scene::Scene& scene) {
  std::vector<KeyRow> rows;
  for (std::size_t i = 0; i < scene.panels.size(); ++i) {
    const scene::Panel& panel = scene.panels[i];
    const std::string keys = keys_pointer(text, scene, panel);
    const auto same = std::find_if(rows.begin(), rows.end(), [&](const KeyRow& row) { return row.keys == keys; });
    if (same != rows.end()) {
      same->panels.push_back(i);
      continue;
    }
    KeyRow row{keys, {i}, {}};
    const auto add = [&](const auto& items) {
      for (std::size_t k = 0; k < items.size(); ++k) row.times.push_back({fmt::format("{}/{}", keys, k), items[k].t});
    };
    std::visit(overloaded{[&](const scene::KeyframeKeys& given) { add(given.keyframes); },
                          [&](const scene::PointKeys& given) { add(given.points); },
                          [&](const scene::PlanePoseKeys& given) { add(given.poses); },
                          [&](const scene::SpacePoseKeys& given) { add(given.poses); }},
               panel.keys);
    rows.push_back(std::move(row));
  }
  return rows;
}

Change time_change(const std::string& text, const scene::Scene& scene, const std::string& pointer, double t,
                   double step) {
  if (!std::isfinite(t)) throw std::invalid_argument("the time must be a finite number");
  for (const KeyRow& row : key_rows(text, scene)) {
    for (const KeyTime& time : row.times) {
      if (time.pointer == pointer) return {pointer + "/t", rounded_json(t, step)};
    }
  }
  throw std::invalid_argument(fmt::format("\"{}\" is not a keyframe, point or pose of the timeline", pointer));
}

std::string number_json(double x) { return fmt::format("{}", x == 0.0 ? 0.0 : x); }

std::string rounded_json(double x, double step) {
  if (!(step > 0.0) || !std::isfinite(step) || !std::isfinite(x)) return number_json(x);
  const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(step))), 0, 15);
  const double unit = std::pow(10.0, decimals);
  const double rounded = std::round(x * unit) / unit;
  return number_json(std::abs(rounded - x) <= step ? rounded : x);  // x * unit beyond a double's digits: x
}

std::vector<Handle> handles(const std::string& text, const scene::Scene& scene,
                            const std::vector<render::PanelPlacement>& placements) {
  std::vector<Handle> all;
  for (std::size_t i = 0; i < scene.panels.size() && i < placements.size(); ++i) {
    const scene::Panel& panel = scene.panels[i];
    const render::ViewTransform& view = placements[i].transform;
    const std::string keys = keys_pointer(text, scene, panel);
    const auto arrow_handles = [&](const scene::KeyframeKeys& arrows) {
      if (!arrows.keyframes_to.empty()) return;  // moving keyframes: two arrows each, not dragged
      for (std::size_t k = 0; k < arrows.keyframes.size(); ++k) {
        const Arrow& a = arrows.keyframes[k].arrow;
        const std::string pointer = fmt::format("{}/{}", keys, k);
        all.push_back({i, pointer, "tail", view(a.p)});
        all.push_back({i, pointer, "tip", view(a.q())});
      }
    };
    const auto corner_handles = [&](const scene::PlanePoseKeys& poses) {
      for (std::size_t k = 0; k < poses.poses.size(); ++k) {
        const auto points = corners(scene, poses, poses.poses[k].pose);
        for (int j = 0; j < 3; ++j) {
          all.push_back({i, fmt::format("{}/{}", keys, k), fmt::format("corner{}", j), view(points[j])});
        }
      }
    };
    // Timed points and poses of space have no handles yet: a point's drag and
    // a drag through the 3D camera are not written (docs/reference/serve.md).
    std::visit(
        overloaded{[&](const scene::KeyframeKeys& given) { arrow_handles(given); }, [](const scene::PointKeys&) {},
                   [&](const scene::PlanePoseKeys& given) { corner_handles(given); },
                   [](const scene::SpacePoseKeys&) {}},
        panel.keys);
  }
  return all;
}

std::vector<Change> drag(const std::string& text, const scene::Scene& scene,
                         const std::vector<render::PanelPlacement>& placements, std::size_t panel,
                         const std::string& pointer, const std::string& part, Point to) {
  if (panel >= scene.panels.size() || panel >= placements.size()) throw std::invalid_argument("no such panel");
  bool found = false;
  for (const Handle& handle : handles(text, scene, placements)) {
    found = found || (handle.panel == panel && handle.pointer == pointer && handle.part == part);
  }
  if (!found) throw std::invalid_argument(fmt::format("{} has no handle \"{}\" in panel {}", pointer, part, panel));
  const render::ViewTransform& view = placements[panel].transform;
  const Point world = world_of(view, to);
  // What a drag resolves: a tenth of the pixel, in world units.
  const double step = 0.1 / view.scale;
  const TextSpan span = value_span(text, pointer);
  const Json given = Json::parse(text.substr(span.begin, span.end - span.begin));
  const scene::Panel& drawn = scene.panels[panel];
  const std::size_t index = std::stoul(pointer.substr(pointer.rfind('/') + 1));

  if (const auto* arrows = std::get_if<scene::KeyframeKeys>(&drawn.keys)) {
    const Arrow& arrow = arrows->keyframes.at(index).arrow;
    if (part == "tail") return {{pointer + "/p", point_json(world, step)}};
    if (given.contains("q")) return {{pointer + "/q", point_json(world, step)}};
    // The winding that was, turned by the least angle to the new direction.
    const Point v = world - arrow.p;
    const double turn = std::remainder(std::arg(v) - arrow.w, 2.0 * std::numbers::pi);
    const double turns = given.contains("turns") ? given["turns"].get<double>() : 0.0;
    // The winding to the angle a tenth of a pixel makes at the tip.
    const double angle_step = step / std::max(std::abs(v), step);
    return {{pointer + "/m", rounded_json(std::abs(v), step)},
            {pointer + "/w", rounded_json(arrow.w + turn - 2.0 * std::numbers::pi * turns, angle_step)}};
  }
  const auto& poses = std::get<scene::PlanePoseKeys>(drawn.keys);
  const int corner = part.back() - '0';
  if (given.contains("triangle")) {
    return {{fmt::format("{}/triangle/{}", pointer, corner), point_json(world, step)}};
  }
  auto moved = corners(scene, poses, poses.poses.at(index).pose);
  moved[static_cast<std::size_t>(corner)] = world;
  // The affinity that maps the reference triangle r onto `moved`.
  const auto& r = scene::figure_of(scene, poses).reference;
  Eigen::Matrix2d R, M;
  R << (r[1] - r[0]).real(), (r[2] - r[0]).real(), (r[1] - r[0]).imag(), (r[2] - r[0]).imag();
  M << (moved[1] - moved[0]).real(), (moved[2] - moved[0]).real(), (moved[1] - moved[0]).imag(),
      (moved[2] - moved[0]).imag();
  Affine2 A;
  A.L = M * R.inverse();
  A.b = Eigen::Vector2d(moved[0].real(), moved[0].imag()) - A.L * Eigen::Vector2d(r[0].real(), r[0].imag());
  // Each entry that moved by more than what the drag resolves, rounded to
  // that: the others keep their text (0.4 stays 0.4, never 0.39999999999999997).
  const double extent = std::max(std::abs(r[1] - r[0]), std::abs(r[2] - r[0]));
  const double linear_step = step / std::max(extent, 1e-300);
  std::vector<Change> changes;
  for (int row = 0; row < 2; ++row) {
    for (int column = 0; column < 3; ++column) {
      const double now = column < 2 ? A.L(row, column) : A.b(row);
      const double entry_step = column < 2 ? linear_step : step;
      const double was = given.at("matrix").at(row).at(column).get<double>();
      if (std::abs(now - was) <= entry_step) continue;
      changes.push_back({fmt::format("{}/matrix/{}/{}", pointer, row, column), rounded_json(now, entry_step)});
    }
  }
  return changes;
}

}  // namespace pita::serve
