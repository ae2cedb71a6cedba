// Pose scenes: timed affine poses (the SAM paper; docs/reference/pose-scenes.md "Pose scenes"),
// of the plane or of space ("dimension": 3), read by one reader over the pose.
#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "scene/figure_reader.hpp"
#include "scene/pose_reader.hpp"
#include "scene/scene_readers.hpp"
#include "scene/space_pose_reader.hpp"
#include "scene/timing_reader.hpp"

namespace pita::scene::detail {

namespace {

// What the scene reader does differently in the plane and in space: the
// fields it takes, the shapes (outlines of the plane; solids and a camera in
// space), the layers it draws, and whether
// the scene itself must have poses (a scene of the plane may leave them to
// its panels, or draw only figures that need none).
template <class Pose>
struct PoseSceneSpace;

template <>
struct PoseSceneSpace<Affine2> {
  static constexpr std::array<std::string_view, 18> kFields = {
      "$schema", "description", "method",   "poses",  "reference_triangle",
      "shapes",  "samples",     "title",    "canvas", "layers",
      "panels",  "golden",      "claims",   "lint",   "subdivisions",
      "timing",  "animation",   "dimension"};
  static constexpr bool kPosesRequired = false;
  static void read_shapes(const JsonReader& reader, const Json& document, PoseFigure<Affine2>& figure) {
    if (const Json* shapes = JsonReader::member(document, "shapes")) {
      figure.shapes = detail::read_shapes(reader, *shapes, "/shapes", figure.reference);
    } else {
      figure.shapes = {ShapeOutline{std::vector<Point>(figure.reference.begin(), figure.reference.end()), true,
                                    std::nullopt, std::nullopt}};
    }
  }
  static std::vector<PoseLayer> read_layers(const JsonReader& reader, const Json& value, const std::string& pointer) {
    return read_pose_layers(reader, value, pointer);
  }
};

template <>
struct PoseSceneSpace<Affine3> {
  static constexpr std::array<std::string_view, 19> kFields = {
      "$schema",  "description",  "dimension", "method", "poses",  "reference_tetrahedron",
      "samples",  "subdivisions", "timing",    "golden", "claims", "lint",
      "shapes",   "camera",       "layers",    "title",  "canvas", "panels",
      "animation"};
  static constexpr bool kPosesRequired = true;
  static void read_shapes(const JsonReader& reader, const Json& document, PoseFigure<Affine3>& figure) {
    if (const Json* shapes = JsonReader::member(document, "shapes")) {
      figure.shapes = read_solids(reader, *shapes, "/shapes", figure.reference);
    } else {
      figure.shapes = default_solids(figure.reference);
    }
    if (const Json* camera = JsonReader::member(document, "camera")) {
      figure.camera = read_camera(reader, *camera, "/camera");
    }
  }
  static std::vector<PoseLayer> read_layers(const JsonReader& reader, const Json& value, const std::string& pointer) {
    return read_space_pose_layers(reader, value, pointer);
  }
};

// The pose scene of `Pose`: method, reference simplex, shapes, samples,
// subdivisions and timing, the figure, the poses, the panels, then what every
// scene ends with (read_scene_tail). "timing" is as in the plane
// (docs/reference/scene-format.md "Timing"); in space arc_length follows the
// image of the reference tetrahedron's first point ("p"), second point ("q")
// or their midpoint ("mid").
template <class Pose>
Scene read_pose_scene_of(const JsonReader& reader, const Json& document) {
  using Space = PoseSceneSpace<Pose>;
  reader.check_fields(document, "", Space::kFields);
  Scene scene;
  PoseKeys<Pose> keys;
  PoseFigure<Pose> figure;
  scene.path = reader.file();
  if (const Json* schema = JsonReader::member(document, "$schema")) reader.string(*schema, "/$schema");
  if (const Json* description = JsonReader::member(document, "description")) {
    scene.description = reader.string(*description, "/description");
  }
  const Json* method = JsonReader::member(document, "method");
  if (method == nullptr) reader.fail("/method", "missing required field (a pose method such as \"SAM\")");
  keys.method = read_pose_method_of<Pose>(reader, *method, "/method");
  const std::string reference_field = std::string("reference_") + PoseSpace<Pose>::kSimplex;
  if (const Json* reference = JsonReader::member(document, reference_field)) {
    figure.reference = read_reference<Pose>(reader, *reference, "/" + reference_field);
  }
  Space::read_shapes(reader, document, figure);
  if (const Json* samples = JsonReader::member(document, "samples")) {
    scene.samples = reader.integer(*samples, "/samples", kMinSamples, kMaxSamples);
  }
  if (const Json* subdivisions = JsonReader::member(document, "subdivisions")) {
    keys.subdivisions = reader.integer(*subdivisions, "/subdivisions", 0, kMaxSubdivisions);
  }
  if (const Json* timing = JsonReader::member(document, "timing")) {
    scene.timing = read_timing(reader, *timing, "/timing");
  }
  if (const Json* title = JsonReader::member(document, "title")) scene.title = reader.string(*title, "/title");
  if (const Json* canvas = JsonReader::member(document, "canvas")) {
    scene.canvas = read_canvas(reader, *canvas, "/canvas");
  }
  if (const Json* layers = JsonReader::member(document, "layers")) {
    figure.layers = Space::read_layers(reader, *layers, "/layers");
  } else {
    figure.layers = {ShapesLayer{}, PosesLayer{}};
  }
  const Json* panels = JsonReader::member(document, "panels");
  if (const Json* poses = JsonReader::member(document, "poses")) {
    keys.poses = read_poses<Pose>(reader, *poses, "/poses", figure.reference, keys.method);
  } else if (Space::kPosesRequired || (panels == nullptr && needs_motion(figure.layers))) {
    reader.fail("/poses", missing_poses_reason<Pose>());
  }
  scene.keys = std::move(keys);
  scene.figure = std::move(figure);
  if (panels != nullptr) {
    scene.panels = read_pose_panels(reader, *panels, "/panels", scene);
  } else {
    scene.panels = {scene_panel(scene, "")};
  }
  read_scene_tail<PoseLayer>(reader, document, scene, false);
  return scene;
}

}  // namespace

// Whether a layer needs the motion (every one but "existence",
// "sam3d-existence", "label" and "patch").
bool needs_motion(const std::vector<PoseLayer>& layers) {
  return std::any_of(layers.begin(), layers.end(), [](const PoseLayer& layer) {
    return !std::holds_alternative<ExistenceLayer>(layer) && !std::holds_alternative<LabelLayer>(layer) &&
           !std::holds_alternative<PatchLayer>(layer) && !std::holds_alternative<Sam3dExistenceLayer>(layer);
  });
}

// A pose scene has "poses", or a method of poses only such as "SAM" (a name
// both kinds share, such as "P6", is read as the arrow method).
bool is_pose_scene(const Json& document) {
  if (JsonReader::member(document, "poses") != nullptr) return true;
  if (JsonReader::member(document, "dimension") != nullptr) return true;
  const Json* method = JsonReader::member(document, "method");
  if (method == nullptr || !method->is_string()) return false;
  const std::string name = method->get<std::string>();
  return find_method_of<PoseMethod>(name) != nullptr && find_method_of<Method>(name) == nullptr &&
         JsonReader::member(document, "keyframes") == nullptr;
}

Scene read_pose_scene(const JsonReader& reader, const Json& document) {
  // "dimension": 2 (the default) or 3.
  if (const Json* dimension = JsonReader::member(document, "dimension")) {
    if (reader.integer(*dimension, "/dimension", 2, 3) == 3) return read_pose_scene_of<Affine3>(reader, document);
  }
  return read_pose_scene_of<Affine2>(reader, document);
}

}  // namespace pita::scene::detail
