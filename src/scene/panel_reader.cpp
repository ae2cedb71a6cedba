// "panels": the grid of a figure, each panel overriding the scene's method,
// keyframes or poses, options, shapes, timing, samples and layers.
#include <array>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <fmt/format.h>

#include "core/overloaded.hpp"
#include "core/pose_traits.hpp"
#include "scene/figure_reader.hpp"
#include "scene/pose_reader.hpp"
#include "scene/scene_readers.hpp"
#include "scene/timing_reader.hpp"

namespace pita::scene::detail {

namespace {
constexpr std::array<std::string_view, 10> kPanelFields = {"method", "options", "keyframes", "points", "chain",
                                                           "title",  "samples", "layers",    "timing", "handle"};
constexpr std::array<std::string_view, 8> kPosePanelFields = {"method",  "poses",  "shapes",       "title",
                                                              "samples", "layers", "subdivisions", "timing"};

// ------------------------------------------------------------ JSON parsing

// 1-based line and column of the byte at `index` (columns count bytes, as
// nlohmann's own messages do).

// The panel's arrow keys: the scene's, which a panel of an arrow scene
// always has (keyframes or points).
TrackMethod& track_of(Panel& panel) {
  if (TrackMethod* track = track_method(panel.keys)) return *track;
  throw std::logic_error("a pose panel in an arrow scene");
}

// The panel draws the scene's keyframes with `method`, which must take as many.
void set_method(const JsonReader& reader, Panel& panel, Method method, const std::string& pointer) {
  if (const auto* arrows = std::get_if<KeyframeKeys>(&panel.keys);
      arrows != nullptr && arrows->keyframes.size() < static_cast<std::size_t>(info(method).keyframe_count)) {
    reader.fail(pointer, keyframe_count_reason(method, arrows->keyframes.size()) +
                             " from the scene; give the panel its own \"keyframes\"");
  }
  track_of(panel).method = method;
  panel.title = method_name(method);
}

// The panel's own "keyframes" or "points", under its method and options (set
// before), and the pointer its motion's errors name.
void read_own_keys(const JsonReader& reader, const Json& value, const std::string& pointer, const Scene& scene,
                   Panel& panel) {
  const Json* keyframes = JsonReader::member(value, "keyframes");
  const Json* points = JsonReader::member(value, "points");
  if (keyframes != nullptr && points != nullptr) {
    reader.fail(pointer + "/points", "give either \"keyframes\" (arrows) or \"points\" (timed points), not both");
  }
  if (keyframes != nullptr) {
    KeyframeKeys arrows;
    static_cast<TrackMethod&>(arrows) = track_of(panel);
    arrows.keyframes =
        reader.keyframes(*keyframes, pointer + "/keyframes", arrows.method, &arrows.keyframes_to, arrows.options.knots);
    if (const auto* own = std::get_if<KeyframeKeys>(&scene.keys)) arrows.given_handle = own->given_handle;
    panel.keys = std::move(arrows);
    panel.motion_pointer = pointer + "/keyframes";
  } else if (points != nullptr) {
    PointKeys curve;
    static_cast<TrackMethod&>(curve) = track_of(panel);
    curve.points = reader.points(*points, pointer + "/points");
    panel.keys = std::move(curve);
    panel.motion_pointer = pointer + "/points";
  } else if (JsonReader::member(value, "method") != nullptr || JsonReader::member(value, "options") != nullptr) {
    panel.motion_pointer = pointer;  // the scene's keyframes, the panel's method
  }
}

// A panel is a method name ("P2") or an object whose fields override the scene's.
Panel read_panel(const JsonReader& reader, const Json& value, const std::string& pointer, const Scene& scene) {
  Panel panel = scene_panel(scene, pointer);
  if (value.is_string()) {
    set_method(reader, panel, reader.method(value, pointer), pointer);
    check_track_chain(reader, panel.keys, pointer);
    panel.motion_pointer = pointer;
    return panel;
  }
  if (!value.is_object()) {
    reader.fail(pointer, "a panel must be a method name or an object (got " + value_text(value) + ")");
  }
  reader.check_fields(value, pointer, kPanelFields);
  const Json* keyframes = JsonReader::member(value, "keyframes");
  if (const Json* method = JsonReader::member(value, "method")) {
    const std::string at = pointer + "/method";
    const Method found = reader.method(*method, at);
    if (keyframes == nullptr) {
      set_method(reader, panel, found, at);
    } else {
      track_of(panel).method = found;
      panel.title = method_name(found);
    }
  }
  if (const Json* options = JsonReader::member(value, "options")) {
    TrackMethod& track = track_of(panel);
    const TrackMethod* own = track_method(scene.keys);
    track.options = reader.options(*options, pointer + "/options", own != nullptr ? own->options : MethodOptions{});
  }
  read_own_keys(reader, value, pointer, scene, panel);
  if (const Json* chain = JsonReader::member(value, "chain")) {
    track_of(panel).chain = reader.chain(*chain, pointer + "/chain");
  }
  // The panel's method, chain and keyframes together (any of them may be the
  // scene's): the pointer names the panel's own field when it has one.
  {
    const Json* chain = JsonReader::member(value, "chain");
    const std::string at = chain != nullptr                                 ? pointer + "/chain"
                           : JsonReader::member(value, "method") != nullptr ? pointer + "/method"
                           : keyframes != nullptr                           ? pointer + "/keyframes"
                                                                            : pointer;
    check_track_chain(reader, panel.keys, at);
  }
  if (const Json* handle = JsonReader::member(value, "handle")) {
    auto* arrows = std::get_if<KeyframeKeys>(&panel.keys);
    if (arrows == nullptr)
      reader.fail(pointer + "/handle", "a handle carries shapes with keyframe arrows; this panel has \"points\"");
    arrows->given_handle = reader.arrow(*handle, pointer + "/handle");
  }
  if (const Json* title = JsonReader::member(value, "title")) {
    panel.title = reader.string(*title, pointer + "/title");
  }
  if (const Json* samples = JsonReader::member(value, "samples")) {
    panel.samples = reader.integer(*samples, pointer + "/samples", kMinSamples, kMaxFigureSamples);
    panel.samples_pointer = pointer + "/samples";
  }
  if (const Json* layers = JsonReader::member(value, "layers")) {
    figure_of<KeyframeKeys>(panel).layers = detail::read_layers(reader, *layers, pointer + "/layers");
  }
  if (const Json* timing = JsonReader::member(value, "timing")) {
    panel.timing = detail::read_timing(reader, *timing, pointer + "/timing");
  }
  return panel;
}

}  // namespace

void check_track_chain(const JsonReader& reader, const TrackMethod& track, std::size_t length,
                       const std::string& pointer) {
  reader.check_chain(track.method, track.chain, length, pointer);
}

void check_track_chain(const JsonReader& reader, const MotionKeys& keys, const std::string& pointer) {
  std::visit(
      overloaded{[&](const KeyframeKeys& given) { check_track_chain(reader, given, given.track_length(), pointer); },
                 [&](const PointKeys& given) { check_track_chain(reader, given, given.track_length(), pointer); },
                 [](const PlanePoseKeys&) {}, [](const SpacePoseKeys&) {}},
      keys);
}

std::vector<Panel> read_panels(const JsonReader& reader, const Json& value, const std::string& pointer,
                               const Scene& scene) {
  if (!value.is_array()) {
    reader.fail(pointer, "must be an array of panels, each a method name or an object (got " + value_text(value) + ")");
  }
  if (value.empty() || value.size() > static_cast<std::size_t>(kMaxPanels)) {
    reader.fail(pointer, fmt::format("must have between 1 and {} panels (got {})", kMaxPanels, value.size()));
  }
  std::vector<Panel> panels;
  for (std::size_t i = 0; i < value.size(); ++i) {
    panels.push_back(read_panel(reader, value[i], element_pointer(pointer, i), scene));
  }
  return panels;
}

namespace {

// What differs between the panels of a pose scene of the plane and of space:
// their fields (solids are the scene's: a panel of space has no "shapes"),
// and the layers they draw (the methods they take: read_pose_method_of; the
// reference simplex: the scene's figure).
template <class Pose>
struct PosePanelSpace;
template <>
struct PosePanelSpace<Affine2> {
  static constexpr std::array<std::string_view, 8> kFields = kPosePanelFields;
  static std::vector<PoseLayer> layers(const JsonReader& reader, const Json& value, const std::string& pointer) {
    return read_pose_layers(reader, value, pointer);
  }
};
template <>
struct PosePanelSpace<Affine3> {
  static constexpr std::array<std::string_view, 7> kFields = {"method", "poses",        "title", "samples",
                                                              "layers", "subdivisions", "timing"};
  static std::vector<PoseLayer> layers(const JsonReader& reader, const Json& value, const std::string& pointer) {
    return read_space_pose_layers(reader, value, pointer);
  }
};

// Panel `at` of a pose scene: a method name, or an object whose fields
// override the scene's.
template <class Pose>
Panel read_pose_panel(const JsonReader& reader, const Json& item, const std::string& at, const Scene& scene) {
  using Space = PosePanelSpace<Pose>;
  Panel panel = scene_panel(scene, at);
  PoseKeys<Pose>& keys = std::get<PoseKeys<Pose>>(panel.keys);
  const auto& reference = figure_of<PoseKeys<Pose>>(scene).reference;
  bool own_method = false, own_poses = false;
  if (item.is_string()) {
    keys.method = read_pose_method_of<Pose>(reader, item, at);
    own_method = true;
  } else {
    reader.object(item, at, "a panel (a pose method name or an object)");
    if constexpr (in_space_v<Pose>) {
      if (JsonReader::member(item, "shapes") != nullptr) {
        reader.fail(at + "/shapes",
                    "the solids are the scene's \"shapes\": a panel of a 3D scene moves them by its "
                    "own method, poses or timing");
      }
    }
    reader.check_fields(item, at, Space::kFields);
    if (const Json* method = JsonReader::member(item, "method")) {
      keys.method = read_pose_method_of<Pose>(reader, *method, at + "/method");
      own_method = true;
    }
    if (const Json* title = JsonReader::member(item, "title")) panel.title = reader.string(*title, at + "/title");
    if (const Json* timing = JsonReader::member(item, "timing")) {
      panel.timing = detail::read_timing(reader, *timing, at + "/timing");
    }
    if (const Json* samples = JsonReader::member(item, "samples")) {
      panel.samples = reader.integer(*samples, at + "/samples", kMinSamples, kMaxFigureSamples);
      panel.samples_pointer = at + "/samples";
    }
    if (const Json* subdivisions = JsonReader::member(item, "subdivisions")) {
      keys.subdivisions = reader.integer(*subdivisions, at + "/subdivisions", 0, kMaxSubdivisions);
      own_method = true;  // the motion changes: check it again
    }
    if constexpr (!in_space_v<Pose>) {
      if (const Json* shapes = JsonReader::member(item, "shapes")) {
        figure_of<PoseKeys<Pose>>(panel).shapes = detail::read_shapes(reader, *shapes, at + "/shapes", reference);
      }
    }
    if (const Json* layers = JsonReader::member(item, "layers")) {
      figure_of<PoseKeys<Pose>>(panel).layers = Space::layers(reader, *layers, at + "/layers");
    }
    if (const Json* poses = JsonReader::member(item, "poses")) {
      keys.poses = detail::read_poses<Pose>(reader, *poses, at + "/poses", reference, keys.method);
      own_poses = true;
    }
  }
  const std::vector<PoseLayer>& layers = layers_of<PoseLayer>(scene, panel).layers;
  if (needs_motion(layers)) {
    const PoseMethodInfo& about = info(keys.method);
    const std::string poses_at = own_poses ? at + "/poses" : std::string("/poses");
    const auto count = static_cast<int>(keys.poses.size());
    if (keys.poses.empty()) {
      reader.fail(at,
                  "the panel draws a motion but has no poses: give it \"poses\" or give the "
                  "scene \"poses\"");
    }
    if (count < about.min_poses || count > about.max_poses) {
      reader.fail(own_method ? at : poses_at,
                  detail::pose_count_reason(keys.method, keys.poses.size()) + "; give the panel its own \"poses\"");
    }
    panel.motion_pointer = own_poses ? poses_at : own_method ? at : std::string("/poses");
  }
  if (panel.title.empty() && own_method) panel.title = std::string(info(keys.method).id);
  return panel;
}

}  // namespace

std::vector<Panel> read_pose_panels(const JsonReader& reader, const Json& value, const std::string& pointer,
                                    const Scene& scene) {
  if (!value.is_array() || value.empty() || value.size() > static_cast<std::size_t>(kMaxPanels)) {
    reader.fail(pointer, fmt::format("must be an array of 1 to {} panels (got {})", kMaxPanels, value_text(value)));
  }
  std::vector<Panel> panels;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string at = element_pointer(pointer, i);
    panels.push_back(std::visit(
        overloaded{[&](const PlanePoseKeys&) { return read_pose_panel<Affine2>(reader, value[i], at, scene); },
                   [&](const SpacePoseKeys&) { return read_pose_panel<Affine3>(reader, value[i], at, scene); },
                   [&](const TrackMethod&) -> Panel { reader.fail(pointer, "panels of poses take a scene of poses"); }},
        scene.keys));
  }
  return panels;
}

}  // namespace pita::scene::detail
