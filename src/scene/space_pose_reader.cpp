#include "scene/animation_reader.hpp"
#include "scene/space_pose_reader.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

#include <Eigen/LU>
#include <Eigen/SVD>
#include <fmt/format.h>

#include "scene/pose_reader.hpp"
#include "scene/scene_readers.hpp"
#include "scene/figure_reader.hpp"
#include "scene/limits.hpp"
#include "scene/timing_reader.hpp"

namespace pita::scene::detail {

namespace {

constexpr std::array<std::string_view, 19> kSpaceSceneFields = {
    "$schema", "description", "dimension", "method",    "poses",  "reference_tetrahedron", "samples",
    "subdivisions", "timing", "golden",    "claims",    "lint",   "shapes",                "camera",
    "layers",  "title",       "canvas",    "panels",    "animation"};
constexpr std::array<std::string_view, 3> kSolidFields = {"solid", "polyhedron", "color"};
constexpr std::array<std::string_view, 2> kPolyhedronFields = {"vertices", "faces"};
constexpr std::array<std::string_view, 7> kCameraFields = {"azimuth", "elevation", "distance", "projection",
                                                          "target",  "auto",      "shadow"};
// "shadow": true: a light grey of the ground.
constexpr Color kDefaultShadow{0.0, 0.0, 0.0, 0.14};
constexpr std::array<std::string_view, 4> kSolidNames = {"cube", "tetrahedron", "F", "house"};
constexpr std::array<std::string_view, 2> kProjections = {"orthographic", "perspective"};

const char* const kMatrixShape = "[[a, b, c, tx], [d, e, f, ty], [g, h, i, tz]]";

Eigen::Vector3d read_point3(const JsonReader& reader, const Json& value, const std::string& pointer) {
  if (!value.is_array() || value.size() != 3) {
    reader.fail(pointer, "must be a point [x, y, z] of space (got " + value_text(value) + ")");
  }
  Eigen::Vector3d p;
  for (std::size_t axis = 0; axis < 3; ++axis) p(static_cast<Eigen::Index>(axis)) = bounded(reader, value[axis], element_pointer(pointer, axis));
  return p;
}

std::array<Eigen::Vector3d, 4> read_four_points(const JsonReader& reader, const Json& value,
                                                const std::string& pointer) {
  if (!value.is_array() || value.size() != 4) {
    reader.fail(pointer, "must be an array of four points [[x, y, z], [x, y, z], [x, y, z], [x, y, z]] (got " +
                             value_text(value) + ")");
  }
  std::array<Eigen::Vector3d, 4> points;
  for (std::size_t i = 0; i < 4; ++i) points[i] = read_point3(reader, value[i], element_pointer(pointer, i));
  return points;
}

// The affinity [p1 - p0, p2 - p0, p3 - p0 | p0] mapping the unit tetrahedron
// onto (p0, p1, p2, p3).
Affine3 frame_of(const std::array<Eigen::Vector3d, 4>& p) {
  Affine3 A;
  for (int i = 0; i < 3; ++i) A.L.col(i) = p[static_cast<std::size_t>(i) + 1] - p[0];
  A.b = p[0];
  return A;
}

// Whether the tetrahedron is flat: its volume (times 6) below kDegenerateSimplex (1e-12) of the
// product of its three edge lengths from p0.
bool degenerate(const std::array<Eigen::Vector3d, 4>& p) {
  const Affine3 frame = frame_of(p);
  const double volume = frame.L.determinant();
  const double edges = frame.L.col(0).norm() * frame.L.col(1).norm() * frame.L.col(2).norm();
  return !(std::abs(volume) > kDegenerateSimplex * edges) || !std::isfinite(volume);
}

Affine3 read_matrix3(const JsonReader& reader, const Json& value, const std::string& pointer) {
  const auto shape_error = [&] {
    if (value.is_array() && value.size() == 2) {
      reader.fail(pointer, fmt::format("a 2x3 matrix is a pose of the plane; the poses of a 3D scene (\"dimension\": "
                                       "3) are 3x4 matrices {} (got {})",
                                       kMatrixShape, value_text(value)));
    }
    reader.fail(pointer, fmt::format("must be a 3x4 matrix {} (x -> [[a, b, c], [d, e, f], [g, h, i]] x + "
                                     "[tx, ty, tz]; got {})",
                                     kMatrixShape, value_text(value)));
  };
  if (!value.is_array() || value.size() != 3) shape_error();
  Affine3 A;
  for (std::size_t row = 0; row < 3; ++row) {
    if (!value[row].is_array() || value[row].size() != 4) shape_error();
    const std::string at = element_pointer(pointer, row);
    for (std::size_t column = 0; column < 4; ++column) {
      const double x = bounded(reader, value[row][column], element_pointer(at, column));
      const auto r = static_cast<Eigen::Index>(row);
      if (column < 3) {
        A.L(r, static_cast<Eigen::Index>(column)) = x;
      } else {
        A.b(r) = x;
      }
    }
  }
  // Invertible, numerically: |det| above kSingularPose (1e-16) of |L|_F^3 (as in 2D with
  // |L|_F^2: about the ratio of the smallest singular value to the largest
  // times that of the middle one). A mirrored pose is allowed; the SAM
  // between two poses needs C o B^-1 to preserve orientation, which the
  // motion checks.
  const double det = A.L.determinant();
  const double norm = A.L.norm();
  if (!(std::abs(det) > kSingularPose * norm * norm * norm) || !std::isfinite(det)) {
    // Say which: singular (a singular value is zero to rounding), or only
    // ill-conditioned (a strong shear of determinant 1 fails the test too).
    const Eigen::Vector3d sigma = Eigen::JacobiSVD<Eigen::Matrix3d>(A.L).singularValues();
    if (!std::isfinite(det) || !(sigma(2) > kSingularValueRatio * sigma(0))) {
      reader.fail(pointer, fmt::format("the linear part [[a, b, c], [d, e, f], [g, h, i]] has determinant {}: the "
                                       "pose is singular, it flattens space onto a plane, a line or a point",
                                       number_text(det)));
    }
    reader.fail(pointer, fmt::format("the linear part [[a, b, c], [d, e, f], [g, h, i]] has determinant {}, below "
                                     "1e-16 of |L|_F^3 = {:.3g} (the test is relative to the matrix's norm): it is "
                                     "not singular, but too ill-conditioned to invert reliably (its singular values "
                                     "range from {:.3g} to {:.3g}: a shear or stretch this strong)",
                                     number_text(det), norm * norm * norm, sigma(2), sigma(0)));
  }
  return A;
}

// The builtin solids: the unit cube, the reference tetrahedron, an F of
// the unit square extruded to a depth of 0.25, and a house (a box with a
// gable roof) in [0, 1] x [0, 0.8] x [0, 1].
Solid builtin_solid(std::string_view name, const std::array<Eigen::Vector3d, 4>& reference) {
  Solid solid;
  if (name == "tetrahedron") {
    solid.vertices.assign(reference.begin(), reference.end());
    solid.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return solid;
  }
  if (name == "cube") {
    for (int i = 0; i < 8; ++i) solid.vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    solid.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    return solid;
  }
  // Prisms: an outline of the xy plane (counter-clockwise) extruded along z.
  std::vector<Eigen::Vector2d> outline;
  double depth = 0.25;
  if (name == "F") {
    outline = {{0.0, 0.0}, {0.25, 0.0}, {0.25, 0.4}, {0.6, 0.4}, {0.6, 0.6},
               {0.25, 0.6}, {0.25, 0.8}, {0.75, 0.8}, {0.75, 1.0}, {0.0, 1.0}};
  } else {  // house: the gable outline, 0.8 deep
    outline = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 0.6}, {0.5, 1.0}, {0.0, 0.6}};
    depth = 0.8;
  }
  const int n = static_cast<int>(outline.size());
  for (const Eigen::Vector2d& p : outline) solid.vertices.emplace_back(p.x(), p.y(), 0.0);
  for (const Eigen::Vector2d& p : outline) solid.vertices.emplace_back(p.x(), p.y(), depth);
  std::vector<int> front, back;
  for (int i = 0; i < n; ++i) {
    front.push_back(n - 1 - i);  // z = 0, seen from -z: clockwise in xy
    back.push_back(n + i);
    solid.faces.push_back({i, (i + 1) % n, n + (i + 1) % n, n + i});
  }
  solid.faces.push_back(front);
  solid.faces.push_back(back);
  return solid;
}

Solid read_polyhedron(const JsonReader& reader, const Json& value, const std::string& pointer) {
  reader.object(value, pointer, "a polyhedron {\"vertices\": [[x, y, z], ...], \"faces\": [[i, j, k, ...], ...]}");
  reader.check_fields(value, pointer, kPolyhedronFields);
  Solid solid;
  const Json* vertices = JsonReader::member(value, "vertices");
  if (vertices == nullptr) reader.fail(pointer + "/vertices", "missing required field (the points [x, y, z])");
  if (!vertices->is_array() || vertices->size() < 4 || vertices->size() > static_cast<std::size_t>(kMaxSolidVertices)) {
    reader.fail(pointer + "/vertices",
                fmt::format("must be an array of 4 to {} points [x, y, z] (got {})", kMaxSolidVertices,
                            value_text(*vertices)));
  }
  for (std::size_t i = 0; i < vertices->size(); ++i) {
    solid.vertices.push_back(read_point3(reader, (*vertices)[i], element_pointer(pointer + "/vertices", i)));
  }
  const Json* faces = JsonReader::member(value, "faces");
  if (faces == nullptr) reader.fail(pointer + "/faces", "missing required field (the faces, as lists of vertex indices)");
  if (!faces->is_array() || faces->empty() || faces->size() > static_cast<std::size_t>(kMaxSolidFaces)) {
    reader.fail(pointer + "/faces", fmt::format("must be an array of 1 to {} faces [i, j, k, ...] (got {})",
                                                kMaxSolidFaces, value_text(*faces)));
  }
  const int count = static_cast<int>(solid.vertices.size());
  for (std::size_t f = 0; f < faces->size(); ++f) {
    const std::string at = element_pointer(pointer + "/faces", f);
    const Json& face = (*faces)[f];
    if (!face.is_array() || face.size() < 3 || face.size() > static_cast<std::size_t>(kMaxSolidVertices)) {
      reader.fail(at, "must be an array of at least 3 vertex indices, in order around the face (got " +
                          value_text(face) + ")");
    }
    std::vector<int> indices;
    for (std::size_t k = 0; k < face.size(); ++k) {
      const std::string index_at = element_pointer(at, k);
      if (!face[k].is_number_integer() || face[k].get<long long>() < 0 || face[k].get<long long>() >= count) {
        reader.fail(index_at, fmt::format("must be the index of a vertex, 0 to {} (got {})", count - 1,
                                          value_text(face[k])));
      }
      indices.push_back(face[k].get<int>());
    }
    solid.faces.push_back(std::move(indices));
  }
  return solid;
}

std::vector<Solid> read_solids(const JsonReader& reader, const Json& value, const std::string& pointer,
                               const std::array<Eigen::Vector3d, 4>& reference) {
  if (!value.is_array() || value.empty() || value.size() > static_cast<std::size_t>(kMaxSolids)) {
    reader.fail(pointer, fmt::format("must be an array of 1 to {} solids {{\"solid\": {}}} or {{\"polyhedron\": "
                                     "{{...}}}} (got {})",
                                     kMaxSolids, quoted_choices(kSolidNames), value_text(value)));
  }
  std::vector<Solid> solids;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string at = element_pointer(pointer, i);
    const Json& item = value[i];
    reader.object(item, at, "a solid");
    reader.check_fields(item, at, kSolidFields);
    const Json* name = JsonReader::member(item, "solid");
    const Json* polyhedron = JsonReader::member(item, "polyhedron");
    Solid solid;
    if (name != nullptr && polyhedron != nullptr) {
      reader.fail(at + "/polyhedron", "give either \"solid\" or \"polyhedron\", not both");
    }
    if (name != nullptr) {
      const std::string text = name->is_string() ? name->get<std::string>() : std::string();
      if (std::find(kSolidNames.begin(), kSolidNames.end(), text) == kSolidNames.end()) {
        reader.fail(at + "/solid", "must be " + quoted_choices(kSolidNames) + " (got " + value_text(*name) + ")");
      }
      solid = builtin_solid(text, reference);
    } else if (polyhedron != nullptr) {
      solid = read_polyhedron(reader, *polyhedron, at + "/polyhedron");
    } else {
      reader.fail(at, "a solid needs \"solid\": " + quoted_choices(kSolidNames) +
                          " or \"polyhedron\": {\"vertices\": [...], \"faces\": [...]}");
    }
    if (const Json* color = JsonReader::member(item, "color")) solid.color = reader.color(*color, at + "/color");
    solids.push_back(std::move(solid));
  }
  return solids;
}

Camera read_camera(const JsonReader& reader, const Json& value, const std::string& pointer) {
  reader.object(value, pointer, "the camera");
  reader.check_fields(value, pointer, kCameraFields);
  Camera camera;
  if (const Json* azimuth = JsonReader::member(value, "azimuth")) {
    camera.azimuth = reader.number(*azimuth, pointer + "/azimuth", Interval{-360.0, 360.0});
  }
  if (const Json* elevation = JsonReader::member(value, "elevation")) {
    camera.elevation = reader.number(*elevation, pointer + "/elevation", Interval{-90.0, 90.0});
  }
  if (const Json* projection = JsonReader::member(value, "projection")) {
    const std::string text = projection->is_string() ? projection->get<std::string>() : std::string();
    if (std::find(kProjections.begin(), kProjections.end(), text) == kProjections.end()) {
      reader.fail(pointer + "/projection",
                  "must be " + quoted_choices(kProjections) + " (got " + value_text(*projection) + ")");
    }
    camera.perspective = text == "perspective";
  }
  if (const Json* distance = JsonReader::member(value, "distance")) {
    camera.distance = bounded(reader, *distance, pointer + "/distance");
    if (!(camera.distance > 0.0)) {
      reader.fail(pointer + "/distance",
                  fmt::format("must be > 0: the camera stands that far from the target (got {})",
                              number_text(camera.distance)));
    }
  }
  if (const Json* target = JsonReader::member(value, "target")) camera.target = read_point3(reader, *target, pointer + "/target");
  if (const Json* automatic = JsonReader::member(value, "auto")) camera.automatic = reader.boolean(*automatic, pointer + "/auto");
  if (const Json* shadow = JsonReader::member(value, "shadow")) {
    if (shadow->is_boolean()) {
      if (shadow->get<bool>()) camera.shadow = kDefaultShadow;
    } else {
      camera.shadow = reader.color(*shadow, pointer + "/shadow");
    }
  }
  return camera;
}

}  // namespace

std::array<Eigen::Vector3d, 4> read_reference_tetrahedron(const JsonReader& reader, const Json& value,
                                                          const std::string& pointer) {
  const std::array<Eigen::Vector3d, 4> points = read_four_points(reader, value, pointer);
  if (degenerate(points)) reader.fail(pointer, "the reference tetrahedron is degenerate (its points are coplanar)");
  return points;
}

PoseSpace<Affine3>::Simplex PoseSpace<Affine3>::read_simplex(const JsonReader& reader, const Json& value,
                                                             const std::string& pointer) {
  return read_four_points(reader, value, pointer);
}
bool PoseSpace<Affine3>::degenerate(const Simplex& points) { return detail::degenerate(points); }
Affine3 PoseSpace<Affine3>::frame_of(const Simplex& points) { return detail::frame_of(points); }
Affine3 PoseSpace<Affine3>::read_matrix(const JsonReader& reader, const Json& value, const std::string& pointer) {
  return read_matrix3(reader, value, pointer);
}
void PoseSpace<Affine3>::refuse_other_simplex(const JsonReader& reader, const Json& item, const std::string& pointer) {
  if (JsonReader::member(item, "triangle") != nullptr) {
    reader.fail(pointer + "/triangle", "a triangle is a pose of the plane; a 3D scene (\"dimension\": 3) gives "
                                       "\"tetrahedron\": four points [x, y, z], or a 3x4 \"matrix\"");
  }
}

PoseMethod read_space_pose_method(const JsonReader& reader, const Json& value, const std::string& pointer) {
  const PoseMethod method = read_pose_method(reader, value, pointer);
  if (!info(method).in_space) {
    std::vector<std::string_view> ids;
    for (const PoseMethodInfo& entry : all_pose_methods()) {
      if (entry.in_space) ids.push_back(entry.id);
    }
    reader.fail(pointer, fmt::format("method {} moves poses of the plane only; 3D scenes take {}", info(method).id,
                                     quoted_choices(ids)));
  }
  return method;
}

Scene read_space_pose_scene(const JsonReader& reader, const Json& document) {
  reader.check_fields(document, "", kSpaceSceneFields);
  Scene scene;
  SpacePoseKeys keys;
  scene.path = reader.file();
  scene.shapes.clear();
  if (const Json* schema = JsonReader::member(document, "$schema")) reader.string(*schema, "/$schema");
  if (const Json* description = JsonReader::member(document, "description")) {
    scene.description = reader.string(*description, "/description");
  }
  const Json* method = JsonReader::member(document, "method");
  if (method == nullptr) reader.fail("/method", "missing required field (a pose method such as \"SAM\")");
  keys.method = read_space_pose_method(reader, *method, "/method");
  if (const Json* reference = JsonReader::member(document, "reference_tetrahedron")) {
    scene.reference_tetrahedron = read_reference_tetrahedron(reader, *reference, "/reference_tetrahedron");
  }
  if (const Json* samples = JsonReader::member(document, "samples")) {
    scene.samples = reader.integer(*samples, "/samples", kMinSamples, kMaxSamples);
  }
  if (const Json* subdivisions = JsonReader::member(document, "subdivisions")) {
    keys.subdivisions = reader.integer(*subdivisions, "/subdivisions", 0, kMaxSubdivisions);
  }
  const Json* poses = JsonReader::member(document, "poses");
  if (poses == nullptr) {
    reader.fail("/poses", fmt::format("missing required field (an array of poses {{\"t\": ..., \"matrix\": {}}})",
                                      kMatrixShape));
  }
  keys.poses = read_poses<Affine3>(reader, *poses, "/poses", scene.reference_tetrahedron, keys.method);
  scene.keys = std::move(keys);
  // "timing" as in 2D (docs/reference/scene-format.md "Timing"); arc_length follows the image of the
  // reference tetrahedron's first point ("p"), second point ("q") or their
  // midpoint ("mid") through space.
  if (const Json* timing = JsonReader::member(document, "timing")) {
    scene.timing = read_timing(reader, *timing, "/timing");
  }
  if (const Json* shapes = JsonReader::member(document, "shapes")) {
    scene.solids = read_solids(reader, *shapes, "/shapes", scene.reference_tetrahedron);
  } else {
    scene.solids = {builtin_solid("tetrahedron", scene.reference_tetrahedron)};
  }
  if (const Json* camera = JsonReader::member(document, "camera")) {
    scene.camera = read_camera(reader, *camera, "/camera");
  }
  if (const Json* title = JsonReader::member(document, "title")) scene.title = reader.string(*title, "/title");
  if (const Json* canvas = JsonReader::member(document, "canvas")) {
    scene.canvas = read_canvas(reader, *canvas, "/canvas");
  }
  if (const Json* layers = JsonReader::member(document, "layers")) {
    scene.pose_layers = read_space_pose_layers(reader, *layers, "/layers");
  } else {
    scene.pose_layers = {ShapesLayer{}, PosesLayer{}};
  }
  if (const Json* panels = JsonReader::member(document, "panels")) {
    scene.panels = read_pose_panels(reader, *panels, "/panels", scene);
  } else {
    scene.panels = {scene_panel(scene, "")};
  }
  if (const Json* golden = JsonReader::member(document, "golden")) read_golden(reader, *golden, scene.golden);
  if (const Json* claims = JsonReader::member(document, "claims")) {
    scene.claims = read_claims<PoseLayer>(reader, *claims, scene);
  }
  if (const Json* lint = JsonReader::member(document, "lint")) scene.lint = read_lint(reader, *lint);
  // "animation", as a scene of poses of the plane reads it (poses do not move).
  if (const Json* animation = JsonReader::member(document, "animation")) {
    scene.animation = detail::read_animation<PoseLayer>(reader, *animation, "/animation", false);
    scene.has_animation = true;
  }
  return scene;
}

}  // namespace pita::scene::detail
