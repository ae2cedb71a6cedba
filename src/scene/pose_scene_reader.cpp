// Pose scenes: timed affine poses (the SAM paper; docs/reference/pose-scenes.md "Pose scenes").
#include "scene/scene_readers.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "scene/animation_reader.hpp"
#include "scene/figure_reader.hpp"
#include "scene/pose_reader.hpp"
#include "scene/space_pose_reader.hpp"
#include "scene/timing_reader.hpp"

namespace pita::scene::detail {

namespace {
constexpr std::array<std::string_view, 18> kPoseSceneFields = {
    "$schema", "description", "method", "poses",  "reference_triangle", "shapes",
    "samples", "title",       "canvas", "layers", "panels",             "golden", "claims", "lint",
    "subdivisions", "timing", "animation", "dimension"};

}  // namespace

// Whether a layer needs the motion (every one but "existence",
// "sam3d-existence", "label" and "patch").
bool needs_motion(const std::vector<PoseLayer>& layers) {
  return std::any_of(layers.begin(), layers.end(), [](const PoseLayer& layer) {
    return !std::holds_alternative<ExistenceLayer>(layer) && !std::holds_alternative<LabelLayer>(layer) &&
           !std::holds_alternative<PatchLayer>(layer) && !std::holds_alternative<Sam3dExistenceLayer>(layer);
  });
}

// A pose scene has "poses", or a pose method such as "SAM".
bool is_pose_scene(const Json& document) {
  if (JsonReader::member(document, "poses") != nullptr) return true;
  if (JsonReader::member(document, "dimension") != nullptr) return true;
  const Json* method = JsonReader::member(document, "method");
  return method != nullptr && method->is_string() &&
         find_method_of<PoseMethod>(method->get<std::string>()) != nullptr &&
         JsonReader::member(document, "keyframes") == nullptr;
}


Scene read_pose_scene(const JsonReader& reader, const Json& document) {
  // "dimension": 2 (the default) or 3 (space_pose_reader.hpp).
  if (const Json* dimension = JsonReader::member(document, "dimension")) {
    if (reader.integer(*dimension, "/dimension", 2, 3) == 3) return read_space_pose_scene(reader, document);
  }
  reader.check_fields(document, "", kPoseSceneFields);
  Scene scene;
  PlanePoseKeys keys;
  scene.path = reader.file();
  if (const Json* schema = JsonReader::member(document, "$schema")) reader.string(*schema, "/$schema");
  if (const Json* description = JsonReader::member(document, "description")) {
    scene.description = reader.string(*description, "/description");
  }
  const Json* method = JsonReader::member(document, "method");
  if (method == nullptr) {
    reader.fail("/method", "missing required field (a pose method such as \"SAM\")");
  }
  keys.method = detail::read_pose_method(reader, *method, "/method");
  if (const Json* reference = JsonReader::member(document, "reference_triangle")) {
    scene.reference_triangle =
        detail::read_reference_triangle(reader, *reference, "/reference_triangle");
  }
  if (const Json* shapes = JsonReader::member(document, "shapes")) {
    scene.shapes = detail::read_shapes(reader, *shapes, "/shapes", scene.reference_triangle);
  } else {
    scene.shapes = {ShapeOutline{std::vector<Point>(scene.reference_triangle.begin(),
                                                    scene.reference_triangle.end()),
                                 true, std::nullopt, std::nullopt}};
  }
  if (const Json* samples = JsonReader::member(document, "samples")) {
    scene.samples = reader.integer(*samples, "/samples", kMinSamples, kMaxSamples);
  }
  if (const Json* subdivisions = JsonReader::member(document, "subdivisions")) {
    keys.subdivisions = reader.integer(*subdivisions, "/subdivisions", 0, kMaxSubdivisions);
  }
  if (const Json* timing = JsonReader::member(document, "timing")) {
    scene.timing = detail::read_timing(reader, *timing, "/timing");
  }
  if (const Json* title = JsonReader::member(document, "title")) scene.title = reader.string(*title, "/title");
  if (const Json* canvas = JsonReader::member(document, "canvas")) {
    scene.canvas = detail::read_canvas(reader, *canvas, "/canvas");
  }
  if (const Json* layers = JsonReader::member(document, "layers")) {
    scene.pose_layers = detail::read_pose_layers(reader, *layers, "/layers");
  } else {
    scene.pose_layers = {ShapesLayer{}, PosesLayer{}};
  }
  const Json* panels = JsonReader::member(document, "panels");
  const Json* poses = JsonReader::member(document, "poses");
  if (poses != nullptr) {
    keys.poses = detail::read_poses<Affine2>(reader, *poses, "/poses", scene.reference_triangle, keys.method);
  } else if (panels == nullptr && needs_motion(scene.pose_layers)) {
    reader.fail("/poses", "missing required field (an array of poses {\"t\": ..., \"matrix\": [[a, b, "
                   "tx], [c, d, ty]]} or {\"t\": ..., \"triangle\": [[x, y], [x, y], [x, y]]})");
  }
  scene.keys = std::move(keys);
  if (panels != nullptr) {
    scene.panels = read_pose_panels(reader, *panels, "/panels", scene);
  } else {
    scene.panels = {scene_panel(scene, "")};
  }
  if (const Json* golden = JsonReader::member(document, "golden")) read_golden(reader, *golden, scene.golden);
  if (const Json* claims = JsonReader::member(document, "claims")) {
    scene.claims = read_claims<PoseLayer>(reader, *claims, scene);
  }
  if (const Json* lint = JsonReader::member(document, "lint")) scene.lint = read_lint(reader, *lint);
  if (const Json* animation = JsonReader::member(document, "animation")) {
    scene.animation = detail::read_animation<PoseLayer>(reader, *animation, "/animation", false);
    scene.has_animation = true;
  }
  return scene;
}

}  // namespace pita::scene::detail
