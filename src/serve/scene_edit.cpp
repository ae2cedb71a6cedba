#include "serve/scene_edit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <regex>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include <Eigen/Dense>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/affine2.hpp"
#include "core/affine3.hpp"
#include "core/overloaded.hpp"
#include "core/pose_traits.hpp"
#include "render/pose_panel.hpp"
#include "serve/camera_edit.hpp"
#include "serve/json_edit.hpp"

namespace pita::serve {

namespace {

using Json = nlohmann::ordered_json;
template <class Pose>
using Simplex = typename PoseTraits<Pose>::Simplex;
using render::BodyPoint;

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
std::string point_json(const Eigen::Vector3d& p, double step) {
  return fmt::format("[{}, {}, {}]", rounded_json(p.x(), step), rounded_json(p.y(), step), rounded_json(p.z(), step));
}

// A body point as Eigen holds it (the plane's are complex numbers).
Eigen::Vector2d vector_of(Point p) { return {p.real(), p.imag()}; }
const Eigen::Vector3d& vector_of(const Eigen::Vector3d& p) { return p; }

// How a panel shows the corners of its poses, and where a drag takes one:
// in the plane, the panel's view; in space, the camera as the panel draws it
// ("auto" included) and then the view, a corner moved in the plane through
// it parallel to the image (its depth kept).
template <class Pose>
struct CornerView {
  render::ViewTransform view;
  render::PoseView<Pose> camera;

  // The canvas point of corner x, or nullopt when a perspective camera cannot see it.
  std::optional<Point> canvas(const BodyPoint<Pose>& x) const {
    if constexpr (!in_space_v<Pose>) {
      return view(x);
    } else {
      const std::optional<Point> image = camera.project(x);
      return image ? std::optional<Point>(view(*image)) : std::nullopt;
    }
  }
  // Corner x dragged to the canvas point `to`.
  BodyPoint<Pose> dragged(const BodyPoint<Pose>& x, Point to) const {
    if constexpr (!in_space_v<Pose>) {
      (void)x;
      return world_of(view, to);
    } else {
      return camera.unproject(world_of(view, to), camera.depth(x));
    }
  }
  // What a drag resolves at corner x: a tenth of the pixel, in world units.
  double step(const BodyPoint<Pose>& x) const {
    const double image_step = 0.1 / view.scale;
    if constexpr (!in_space_v<Pose>) {
      (void)x;
      return image_step;
    } else {
      const double depth = camera.depth(x);
      return (camera.unproject({image_step, 0.0}, depth) - camera.unproject({0.0, 0.0}, depth)).norm();
    }
  }
};

template <class Pose>
CornerView<Pose> corner_view(const motion::Stage& stage, const std::vector<render::PanelPlacement>& placements,
                             std::size_t panel) {
  if constexpr (!in_space_v<Pose>) {
    return {placements[panel].transform, {}};
  } else {
    return {placements[panel].transform, render::PosePanel<Affine3>(stage, panel, nullptr).view()};
  }
}

// The reference simplex's corners moved by a pose of the scene's.
template <class Pose>
Simplex<Pose> corners(const scene::Scene& scene, const scene::PoseKeys<Pose>& keys, const Pose& pose) {
  Simplex<Pose> out = scene::figure_of(scene, keys).reference;
  for (BodyPoint<Pose>& x : out) x = apply(pose, x);
  return out;
}

// The field of a pose given by its points: "triangle", "tetrahedron".
template <class Pose>
constexpr const char* simplex_field() {
  return in_space_v<Pose> ? "tetrahedron" : "triangle";
}

template <class Pose>
void add_corner_handles(std::vector<Handle>& all, const scene::Scene& scene, const scene::PoseKeys<Pose>& poses,
                        const CornerView<Pose>& view, std::size_t panel, const std::string& keys) {
  for (std::size_t k = 0; k < poses.poses.size(); ++k) {
    const Simplex<Pose> points = corners(scene, poses, poses.poses[k].pose);
    for (std::size_t j = 0; j < points.size(); ++j) {
      if (const std::optional<Point> at = view.canvas(points[j])) {
        all.push_back({panel, fmt::format("{}/{}", keys, k), fmt::format("corner{}", j), *at});
      }
    }
  }
}

// Corner `corner` of pose `index` (given as `given`, at `pointer`) dragged to
// the canvas point `to`: that point of the simplex when the pose gives its
// points, else the entries of the matrix (of the affinity that maps the
// reference simplex onto the moved one) that changed by more than the drag
// resolves, each rounded to that; the others keep their text (0.4 stays
// 0.4, never 0.39999999999999997).
template <class Pose>
std::vector<Change> corner_drag(const scene::Scene& scene, const scene::PoseKeys<Pose>& poses,
                                const CornerView<Pose>& view, const std::string& pointer, const Json& given,
                                std::size_t corner, Point to) {
  const std::size_t index = std::stoul(pointer.substr(pointer.rfind('/') + 1));
  Simplex<Pose> moved = corners(scene, poses, poses.poses.at(index).pose);
  moved.at(corner) = view.dragged(moved[corner], to);
  const double step = view.step(moved[corner]);
  if (given.contains(simplex_field<Pose>())) {
    return {{fmt::format("{}/{}/{}", pointer, simplex_field<Pose>(), corner), point_json(moved[corner], step)}};
  }
  constexpr int n = PoseTraits<Pose>::dimension;
  const Simplex<Pose>& r = scene::figure_of(scene, poses).reference;
  typename PoseTraits<Pose>::LinearPart R, M;
  double extent = 0.0;
  for (int j = 1; j <= n; ++j) {
    R.col(j - 1) = vector_of(r[j]) - vector_of(r[0]);
    M.col(j - 1) = vector_of(moved[j]) - vector_of(moved[0]);
    extent = std::max(extent, R.col(j - 1).norm());
  }
  Pose A;
  A.L = M * R.inverse();
  A.b = vector_of(moved[0]) - A.L * vector_of(r[0]);
  const double linear_step = step / std::max(extent, 1e-300);
  std::vector<Change> changes;
  for (int row = 0; row < n; ++row) {
    for (int column = 0; column <= n; ++column) {
      const double now = column < n ? A.L(row, column) : A.b(row);
      const double entry_step = column < n ? linear_step : step;
      const double was = given.at("matrix").at(row).at(column).get<double>();
      if (std::abs(now - was) <= entry_step) continue;
      changes.push_back({fmt::format("{}/matrix/{}/{}", pointer, row, column), rounded_json(now, entry_step)});
    }
  }
  return changes;
}

}  // namespace

void check_change(const std::string& text, const Change& change) {
  // The value's bytes are written as given, and the undo gives back the
  // bytes the value replaced: JSON whitespace around it would be written and
  // never taken back (the undo's span is the value's, without it).
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  if (!change.remove && (change.value.empty() || space(change.value.front()) || space(change.value.back()))) {
    throw std::invalid_argument("the value for " + change.pointer + " must be one JSON value, with no space around it");
  }
  if (is_camera_pointer(change.pointer)) return check_camera_change(change);
  if (change.remove) throw std::invalid_argument("\"" + change.pointer + "\" is not a member an edit may remove");
  // /keyframes/K/(p|q|m|w|t), /poses/K/(triangle/J|tetrahedron/J|matrix|t), /points/K/t, or the same under /panels/N.
  static const std::regex editable(
      R"(^(/panels/[0-9]+)?/(keyframes/[0-9]+/(p|q|m|w|t)|poses/[0-9]+/(t|triangle/[0-2]|tetrahedron/[0-3]|matrix(/[0-2]/[0-3])?)|points/[0-9]+/t)$)");
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

std::vector<Handle> handles(const std::string& text, const motion::Stage& stage,
                            const std::vector<render::PanelPlacement>& placements) {
  const scene::Scene& scene = stage.scene();
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
    const auto corner_handles = [&](const auto& poses) {
      using Pose = std::remove_cvref_t<decltype(poses.poses[0].pose)>;
      add_corner_handles(all, scene, poses, corner_view<Pose>(stage, placements, i), i, keys);
    };
    // Timed points have no handles: a point's drag is not written (docs/reference/serve.md).
    std::visit(
        overloaded{[&](const scene::KeyframeKeys& given) { arrow_handles(given); }, [](const scene::PointKeys&) {},
                   [&](const scene::PlanePoseKeys& given) { corner_handles(given); },
                   [&](const scene::SpacePoseKeys& given) { corner_handles(given); }},
        panel.keys);
  }
  return all;
}

std::vector<Change> drag(const std::string& text, const motion::Stage& stage,
                         const std::vector<render::PanelPlacement>& placements, std::size_t panel,
                         const std::string& pointer, const std::string& part, Point to) {
  const scene::Scene& scene = stage.scene();
  if (panel >= scene.panels.size() || panel >= placements.size()) throw std::invalid_argument("no such panel");
  bool found = false;
  for (const Handle& handle : handles(text, stage, placements)) {
    found = found || (handle.panel == panel && handle.pointer == pointer && handle.part == part);
  }
  if (!found) throw std::invalid_argument(fmt::format("{} has no handle \"{}\" in panel {}", pointer, part, panel));
  const render::ViewTransform& view = placements[panel].transform;
  const TextSpan span = value_span(text, pointer);
  const Json given = Json::parse(text.substr(span.begin, span.end - span.begin));
  const scene::Panel& drawn = scene.panels[panel];
  if (const auto* arrows = std::get_if<scene::KeyframeKeys>(&drawn.keys)) {
    const std::size_t index = std::stoul(pointer.substr(pointer.rfind('/') + 1));
    const Point world = world_of(view, to);
    // What a drag resolves: a tenth of the pixel, in world units.
    const double step = 0.1 / view.scale;
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
  const std::size_t corner = static_cast<std::size_t>(part.back() - '0');
  if (const auto* poses = std::get_if<scene::PlanePoseKeys>(&drawn.keys)) {
    return corner_drag(scene, *poses, corner_view<Affine2>(stage, placements, panel), pointer, given, corner, to);
  }
  const auto& poses = std::get<scene::SpacePoseKeys>(drawn.keys);
  return corner_drag(scene, poses, corner_view<Affine3>(stage, placements, panel), pointer, given, corner, to);
}

}  // namespace pita::serve
