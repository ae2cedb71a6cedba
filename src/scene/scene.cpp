#include "scene/scene.hpp"

#include <algorithm>
#include <array>
#include <set>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

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
using detail::unknown_method_reason;
using detail::value_text;
using detail::Interval;
}  // namespace

std::string located(const std::string& file, const std::string& pointer,
                    const std::string& reason) {
  return pointer.empty() ? file + ": " + reason : file + ": " + pointer + ": " + reason;
}

Panel scene_panel(const Scene& scene, std::string pointer) {
  Panel panel;
  panel.method = scene.method;
  panel.method_name = scene.method_name;
  panel.options = scene.options;
  panel.keyframes = scene.keyframes;
  panel.keyframes_to = scene.keyframes_to;
  if (!scene.keyframes.empty()) panel.handle = scene.handle.value_or(scene.keyframes.front().arrow);
  panel.chain = scene.chain;
  panel.points = scene.points;
  panel.pose_method = scene.pose_method;
  panel.poses = scene.poses;
  panel.dimension = scene.dimension;
  panel.poses3 = scene.poses3;
  panel.shapes = scene.shapes;
  panel.subdivisions = scene.subdivisions;
  panel.timing = scene.timing;
  panel.samples = scene.samples.value_or(kDefaultFigureSamples);
  panel.samples_pointer = scene.samples ? "/samples" : "";
  panel.pointer = std::move(pointer);
  panel.motion_pointer = scene.kind == SceneKind::poses ? "/poses" : !scene.points.empty() ? "/points" : "/keyframes";
  return panel;
}

SceneError::SceneError(std::string file, std::string pointer, std::string reason)
    : std::runtime_error(located(file, pointer, reason)),
      file_(std::move(file)),
      pointer_(std::move(pointer)),
      reason_(std::move(reason)) {}

SceneError::SceneError(std::string file, int line, int column, std::string reason)
    : std::runtime_error(fmt::format("{}:{}:{}: {}", file, line, column, reason)),
      file_(std::move(file)),
      reason_(std::move(reason)),
      line_(line),
      column_(column) {}

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
  if (const MethodEntry* entry = find_method_entry(name, MotionKind::arrows)) return entry->method;
  throw std::invalid_argument(pita::unknown_method_reason(name, MotionKind::arrows));
}

Scene with_method(Scene scene, Method method) {
  if (scene.kind == SceneKind::poses) {
    throw SceneError(scene.path, "/method",
                     fmt::format("method {} interpolates arrows; this is a pose scene (methods: {})",
                                 info(method).id, method_ids(MotionKind::poses)));
  }
  const MethodInfo& about = info(method);
  if (scene.points.empty() && scene.keyframes.size() < static_cast<std::size_t>(about.keyframe_count)) {
    throw SceneError(scene.path, "/keyframes", keyframe_count_reason(method, scene.keyframes.size()));
  }
  const JsonReader reader(scene.path);
  reader.check_chain(method, scene.chain, scene.points.empty() ? scene.keyframes.size() : scene.points.size() - 1,
                     "/chain");
  scene.method = method;
  scene.method_name = std::string(about.id);
  // The panel that is the scene itself follows it; panels of their own keep theirs.
  for (Panel& panel : scene.panels) {
    if (!panel.pointer.empty()) continue;
    panel.method = method;
    panel.method_name = scene.method_name;
  }
  return scene;
}

std::string no_sam_reason(const NoSamBetweenPoses& error, PoseMethod method) {
  if (!error.where().empty()) {
    return fmt::format("{} ({}, method {})", error.what(), error.where(), info(method).id);
  }
  return fmt::format("{} (poses {} and {}, method {})", error.what(), error.first(),
                     error.first() + 1, info(method).id);
}

Scene with_pose_method(Scene scene, PoseMethod method) {
  if (scene.kind != SceneKind::poses) {
    throw SceneError(scene.path, "/method",
                     fmt::format("method {} interpolates poses; this scene has keyframes (arrows)",
                                 info(method).id));
  }
  const PoseMethodInfo& about = info(method);
  if (scene.dimension == 3 && !about.in_space) {
    throw SceneError(scene.path, "/dimension",
                     fmt::format("method {} moves poses of the plane only; this is a 3D scene", about.id));
  }
  const std::size_t given = scene.dimension == 3 ? scene.poses3.size() : scene.poses.size();
  if (given == 0) {
    throw SceneError(scene.path, "/poses", "the scene has no poses to interpolate");
  }
  const auto count = static_cast<int>(given);
  if (count < about.min_poses || count > about.max_poses) {
    throw SceneError(scene.path, "/poses", detail::pose_count_reason(method, given));
  }
  scene.pose_method = method;
  scene.method_name = std::string(about.id);
  for (Panel& panel : scene.panels) {
    if (!panel.pointer.empty()) continue;
    panel.pose_method = method;
    panel.method_name = scene.method_name;
  }
  return scene;
}

}  // namespace pita::scene
