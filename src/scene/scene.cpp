#include "scene/scene.hpp"

#include <algorithm>
#include <array>
#include <set>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/overloaded.hpp"
#include "core/pose_traits.hpp"
#include "scene/json_reader.hpp"
#include "scene/json_text.hpp"
#include "scene/limits.hpp"
#include "scene/pose_reader.hpp"
#include "scene/scene_readers.hpp"

namespace pita::scene {

namespace {

using detail::element_pointer;
using detail::Json;
using detail::JsonReader;
using detail::keyframe_count_reason;
using detail::value_text;
using detail::Interval;
}  // namespace

Panel scene_panel(const Scene& scene, std::string pointer) {
  Panel panel;
  panel.keys = scene.keys;
  panel.shapes = scene.shapes;
  panel.timing = scene.timing;
  panel.samples = scene.samples.value_or(kDefaultFigureSamples);
  panel.samples_pointer = scene.samples ? "/samples" : "";
  panel.pointer = std::move(pointer);
  panel.motion_pointer = keys_field(scene.keys);
  return panel;
}

Scene load_scene(const std::filesystem::path& path, const ReadOptions& options) {
  return parse_scene(read_input_file(path, kMaxSceneFileBytes, "scene file"), path.string(), options);
}

Scene parse_scene(std::string_view text, std::string source_name, const ReadOptions& options) {
  const Json document = parse_json(text, source_name);
  const JsonReader reader(std::move(source_name), options);
  if (!document.is_object()) {
    reader.fail("", "a scene must be a JSON object (got " + value_text(document) + ")");
  }
  return detail::is_pose_scene(document) ? detail::read_pose_scene(reader, document)
                                         : detail::read_arrow_scene(reader, document);
}

Method resolve_method(std::string_view name) {
  if (const Method* method = find_method_of<Method>(name)) return *method;
  throw std::invalid_argument(pita::unknown_method_reason(name, is_method_of<Method>));
}

namespace {

// The arrow method of `keys` replaced by `method` (the scene's keyframes or
// points must be enough for it); pose keys are refused.
void replace_method(const Scene& scene, MotionKeys& keys, Method method) {
  const auto arrows = [&](TrackMethod& track, std::size_t count, bool keyframes) {
    if (keyframes && count < static_cast<std::size_t>(info(method).keyframe_count)) {
      throw SceneError(scene.path, "/keyframes", keyframe_count_reason(method, count));
    }
    const JsonReader reader(scene.path);
    reader.check_chain(method, track.chain, count, "/chain");
    track.method = method;
  };
  const auto poses = [&](const auto&) {
    throw SceneError(scene.path, "/method",
                     fmt::format("method {} interpolates arrows; this is a pose scene (methods: {})",
                                 info(method).id, method_ids(is_method_of<PoseMethod>)));
  };
  std::visit(overloaded{[&](KeyframeKeys& given) { arrows(given, given.track_length(), true); },
                        [&](PointKeys& given) { arrows(given, given.track_length(), false); },
                        [&](PlanePoseKeys& given) { poses(given); },
                        [&](SpacePoseKeys& given) { poses(given); }},
             keys);
}

// The pose method of `keys` replaced by `method`; arrow keys are refused.
template <class Pose>
void replace_pose_method(const Scene& scene, PoseKeys<Pose>& keys, PoseMethod method) {
  const PoseMethodInfo& about = info(method);
  if (in_space_v<Pose> && !about.in_space) {
    throw SceneError(scene.path, "/dimension",
                     fmt::format("method {} moves poses of the plane only; this is a 3D scene", about.id));
  }
  if (keys.poses.empty()) throw SceneError(scene.path, "/poses", "the scene has no poses to interpolate");
  const auto count = static_cast<int>(keys.poses.size());
  if (count < about.min_poses || count > about.max_poses) {
    throw SceneError(scene.path, "/poses", detail::pose_count_reason(method, keys.poses.size()));
  }
  keys.method = method;
}

// The pose method of `keys` replaced by `method`; arrow keys are refused.
void replace_method(const Scene& scene, MotionKeys& keys, PoseMethod method) {
  const auto arrows = [&](const auto&) {
    throw SceneError(scene.path, "/method",
                     fmt::format("method {} interpolates poses; this scene has keyframes (arrows)",
                                 info(method).id));
  };
  std::visit(overloaded{[&](KeyframeKeys& given) { arrows(given); },
                        [&](PointKeys& given) { arrows(given); },
                        [&](PlanePoseKeys& given) { replace_pose_method(scene, given, method); },
                        [&](SpacePoseKeys& given) { replace_pose_method(scene, given, method); }},
             keys);
}

}  // namespace

std::string no_sam_reason(const NoSamBetweenPoses& error, PoseMethod method) {
  if (!error.where().empty()) {
    return fmt::format("{} ({}, method {})", error.what(), error.where(), info(method).id);
  }
  return fmt::format("{} (poses {} and {}, method {})", error.what(), error.first(),
                     error.first() + 1, info(method).id);
}

namespace {

// The panel's own layers of each family, when it gives "layers".
const std::optional<std::vector<Layer>>& own_layers(const Panel& panel, std::type_identity<Layer>) {
  return panel.layers;
}
const std::optional<std::vector<PoseLayer>>& own_layers(const Panel& panel, std::type_identity<PoseLayer>) {
  return panel.pose_layers;
}
const std::vector<Layer>& scene_layers(const Scene& scene, std::type_identity<Layer>) { return scene.layers; }
const std::vector<PoseLayer>& scene_layers(const Scene& scene, std::type_identity<PoseLayer>) {
  return scene.pose_layers;
}

}  // namespace

template <class LayerType>
LayersOf<LayerType> layers_of(const Scene& scene, const Panel& panel) {
  const auto& own = own_layers(panel, std::type_identity<LayerType>{});
  if (own) return {*own, true, panel.pointer};
  return {scene_layers(scene, std::type_identity<LayerType>{}), false, ""};
}
template LayersOf<Layer> layers_of(const Scene&, const Panel&);
template LayersOf<PoseLayer> layers_of(const Scene&, const Panel&);

Scene with_method(Scene scene, const AnyMethod& method) {
  std::visit([&](auto chosen) { replace_method(scene, scene.keys, chosen); }, method);
  // The panel that is the scene itself follows it; panels of their own keep theirs.
  for (Panel& panel : scene.panels) {
    if (panel.pointer.empty()) panel.keys = scene.keys;
  }
  return scene;
}

}  // namespace pita::scene
