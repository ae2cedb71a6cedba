#include "serve/edit_request.hpp"

#include <cmath>
#include <stdexcept>
#include <variant>

#include <fmt/format.h>

#include "render/pose_panel.hpp"
#include "serve/camera_edit.hpp"
#include "serve/json_edit.hpp"

namespace pita::serve {

namespace {

using Json = nlohmann::ordered_json;

std::string shown(const Json& value) { return value.dump(-1, ' ', false, Json::error_handler_t::replace); }

// One view: [xmin, ymin, xmax, ymax], finite, each side positive.
scene::Box view_of(const Json& given, std::size_t i) {
  const std::string where = fmt::format("views/{}", i);
  if (!given.is_array() || given.size() != 4) {
    throw std::invalid_argument(where + " must be [xmin, ymin, xmax, ymax] (got " + shown(given) + ")");
  }
  double v[4];
  for (std::size_t k = 0; k < 4; ++k) {
    if (!given[k].is_number() || !std::isfinite(given[k].get<double>()) || std::abs(given[k].get<double>()) > 1e12) {
      throw std::invalid_argument(where + " must hold finite numbers (got " + shown(given) + ")");
    }
    v[k] = given[k].get<double>();
  }
  if (!(v[2] > v[0]) || !(v[3] > v[1])) {
    throw std::invalid_argument(where + " must have positive sizes, xmax > xmin and ymax > ymin (got " + shown(given) +
                                ")");
  }
  return {{v[0], v[1]}, {v[2], v[3]}};
}

// Where the world's origin is drawn in panel i's image plane, for an
// orthographic camera of space (views_json); else 0, the plane's views and
// a perspective camera's being as drawn.
Point image_origin(const motion::Stage& stage, std::size_t i) {
  const auto* keys = std::get_if<scene::SpacePoseKeys>(&stage.panel(i).keys);
  if (!keys || scene::figure_of(stage.scene(), *keys).camera.perspective) return {0.0, 0.0};
  return render::PosePanel<Affine3>(stage, i, nullptr).view().project(Eigen::Vector3d::Zero()).value_or(Point{});
}

}  // namespace

Json views_json(const motion::Stage& stage, const std::vector<render::PanelPlacement>& placements) {
  Json out = Json::array();
  for (std::size_t i = 0; i < placements.size(); ++i) {
    const Point origin = i < stage.size() ? image_origin(stage, i) : Point{};
    const scene::Box& b = placements[i].view;
    out.push_back({b.min.real() - origin.real(), b.min.imag() - origin.imag(), b.max.real() - origin.real(),
                   b.max.imag() - origin.imag()});
  }
  return out;
}

std::optional<std::vector<scene::Box>> views_of(const Json& request, std::size_t panels) {
  if (!request.is_object() || !request.contains("views") || request.at("views").is_null()) return std::nullopt;
  const Json& given = request.at("views");
  if (!given.is_array() || given.size() != panels) {
    throw std::invalid_argument(fmt::format("views must be one [xmin, ymin, xmax, ymax] per panel, {} of them (got {})",
                                            panels, given.is_array() ? fmt::format("{}", given.size()) : shown(given)));
  }
  std::vector<scene::Box> views;
  for (std::size_t i = 0; i < given.size(); ++i) views.push_back(view_of(given[i], i));
  return views;
}

render::Figure figure_in(const motion::Stage& stage, const std::optional<std::vector<scene::Box>>& views) {
  if (!views) return render::build_figure(stage);
  std::vector<scene::Box> drawn = *views;
  for (std::size_t i = 0; i < drawn.size() && i < stage.size(); ++i) {
    const Point origin = image_origin(stage, i);
    drawn[i] = {drawn[i].min + origin, drawn[i].max + origin};
  }
  return render::build_figure_in_views(stage, drawn);
}

std::optional<scene::Scene> held_camera(const scene::Scene& scene, const Json& request) {
  if (!request.is_object() || !request.contains("camera") || request.at("camera").is_null()) return std::nullopt;
  const Json& given = request.at("camera");
  if (!given.is_object() || !given.contains("azimuth") || !given.contains("elevation") ||
      !given.at("azimuth").is_number() || !given.at("elevation").is_number()) {
    throw std::invalid_argument("camera must be {\"azimuth\": A, \"elevation\": E} (got " + shown(given) + ")");
  }
  const CameraTurn turn =
      camera_parameter(fmt::format("{},{}", given.at("azimuth").get<double>(), given.at("elevation").get<double>()));
  return turned_scene(scene, turn);
}

std::vector<Change> request_changes(const std::string& text, const scene::Scene& file_scene, const Json& request) {
  std::vector<Change> changes;
  if (request.contains("drag")) {
    const Json& d = request.at("drag");
    // The figure the page showed: the file's scene, with the camera it holds.
    const std::optional<scene::Scene> held = held_camera(file_scene, request);
    const scene::Scene& scene = held ? *held : file_scene;
    const auto views = views_of(request, scene.panels.size());
    const motion::Stage stage(scene);
    const render::Figure figure = figure_in(stage, views);
    // An index of the figure's panels: 1e20 or -1 would be read as another panel.
    const Json& panel = d.at("panel");
    if (!panel.is_number_unsigned() || panel.get<std::uint64_t>() >= figure.placements.size()) {
      throw std::invalid_argument(fmt::format("\"panel\" must be the index of a panel of the figure, 0 to {} (got {})",
                                              figure.placements.size() - 1, shown(panel)));
    }
    const Point to{d.at("to").at(0).get<double>(), d.at("to").at(1).get<double>()};
    if (!std::isfinite(to.real()) || !std::isfinite(to.imag())) throw std::invalid_argument("\"to\" must be finite");
    return drag(text, stage, figure.placements, panel.get<std::size_t>(), d.at("pointer").get<std::string>(),
                d.at("part").get<std::string>(), to);
  }
  if (request.contains("time")) {
    const Json& time = request.at("time");
    const double step = time.contains("step") ? time.at("step").get<double>() : 0.0;
    return {time_change(text, file_scene, time.at("pointer").get<std::string>(), time.at("t").get<double>(), step)};
  }
  for (const Json& change : request.at("changes")) {
    const bool remove = change.contains("remove") && change.at("remove").get<bool>();
    changes.push_back(
        {change.at("pointer").get<std::string>(), remove ? "" : change.at("value").get<std::string>(), remove});
    check_change(text, changes.back());
  }
  return changes;
}

Applied apply_changes(const std::string& text, const std::vector<Change>& changes) {
  Applied applied{text};
  for (const Change& change : changes) {
    Json back;
    if (change.remove) {
      const TextSpan span = value_span(applied.text, change.pointer);
      back = {{"pointer", change.pointer}, {"value", applied.text.substr(span.begin, span.end - span.begin)}};
      applied.text = remove_member(applied.text, change.pointer);
    } else if (is_camera_pointer(change.pointer)) {
      // "Save view": added where the file has no such member yet.
      Undo undo;
      applied.text = set_value(applied.text, change.pointer, change.value, &undo);
      back = undo.value ? Json{{"pointer", undo.pointer}, {"value", *undo.value}}
                        : Json{{"pointer", undo.pointer}, {"remove", true}};
    } else {
      const TextSpan span = value_span(applied.text, change.pointer);
      back = {{"pointer", change.pointer}, {"value", applied.text.substr(span.begin, span.end - span.begin)}};
      applied.text = replace_value(applied.text, change.pointer, change.value);
    }
    // Last change first: its undo removes what it added before an earlier
    // one's removes the object it went into.
    applied.previous.insert(applied.previous.begin(), std::move(back));
  }
  return applied;
}

}  // namespace pita::serve
