// What a 3D pose scene has that a scene of the plane has not: its solids and
// its camera (docs/reference/pose-scenes.md "3D pose scenes").
#include "scene/space_pose_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "scene/limits.hpp"
#include "scene/pose_reader.hpp"

namespace pita::scene::detail {

namespace {

constexpr std::array<std::string_view, 3> kSolidFields = {"solid", "polyhedron", "color"};
constexpr std::array<std::string_view, 2> kPolyhedronFields = {"vertices", "faces"};
constexpr std::array<std::string_view, 7> kCameraFields = {"azimuth", "elevation", "distance", "projection",
                                                           "target",  "auto",      "shadow"};
// "shadow": true: a light grey of the ground.
constexpr Color kDefaultShadow{0.0, 0.0, 0.0, 0.14};
constexpr std::array<std::string_view, 4> kSolidNames = {"cube", "tetrahedron", "F", "house"};
constexpr std::array<std::string_view, 2> kProjections = {"orthographic", "perspective"};

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
    outline = {{0.0, 0.0},  {0.25, 0.0}, {0.25, 0.4}, {0.6, 0.4},  {0.6, 0.6},
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
    reader.fail(pointer + "/vertices", fmt::format("must be an array of 4 to {} points [x, y, z] (got {})",
                                                   kMaxSolidVertices, value_text(*vertices)));
  }
  for (std::size_t i = 0; i < vertices->size(); ++i) {
    solid.vertices.push_back(
        PoseSpace<Affine3>::read_point(reader, (*vertices)[i], element_pointer(pointer + "/vertices", i)));
  }
  const Json* faces = JsonReader::member(value, "faces");
  if (faces == nullptr)
    reader.fail(pointer + "/faces", "missing required field (the faces, as lists of vertex indices)");
  if (!faces->is_array() || faces->empty() || faces->size() > static_cast<std::size_t>(kMaxSolidFaces)) {
    reader.fail(pointer + "/faces", fmt::format("must be an array of 1 to {} faces [i, j, k, ...] (got {})",
                                                kMaxSolidFaces, value_text(*faces)));
  }
  const int count = static_cast<int>(solid.vertices.size());
  for (std::size_t f = 0; f < faces->size(); ++f) {
    const std::string at = element_pointer(pointer + "/faces", f);
    const Json& face = (*faces)[f];
    if (!face.is_array() || face.size() < 3 || face.size() > static_cast<std::size_t>(kMaxSolidVertices)) {
      reader.fail(
          at, "must be an array of at least 3 vertex indices, in order around the face (got " + value_text(face) + ")");
    }
    std::vector<int> indices;
    for (std::size_t k = 0; k < face.size(); ++k) {
      const std::string index_at = element_pointer(at, k);
      if (!face[k].is_number_integer() || face[k].get<long long>() < 0 || face[k].get<long long>() >= count) {
        reader.fail(index_at,
                    fmt::format("must be the index of a vertex, 0 to {} (got {})", count - 1, value_text(face[k])));
      }
      indices.push_back(face[k].get<int>());
    }
    solid.faces.push_back(std::move(indices));
  }
  return solid;
}

}  // namespace

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
    camera.azimuth = reader.number(*azimuth, pointer + "/azimuth", Interval{-kMaxCameraAzimuth, kMaxCameraAzimuth});
  }
  if (const Json* elevation = JsonReader::member(value, "elevation")) {
    camera.elevation =
        reader.number(*elevation, pointer + "/elevation", Interval{-kMaxCameraElevation, kMaxCameraElevation});
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
      reader.fail(pointer + "/distance", fmt::format("must be > 0: the camera stands that far from the target (got {})",
                                                     number_text(camera.distance)));
    }
  }
  if (const Json* target = JsonReader::member(value, "target"))
    camera.target = PoseSpace<Affine3>::read_point(reader, *target, pointer + "/target");
  if (const Json* automatic = JsonReader::member(value, "auto"))
    camera.automatic = reader.boolean(*automatic, pointer + "/auto");
  if (const Json* shadow = JsonReader::member(value, "shadow")) {
    if (shadow->is_boolean()) {
      if (shadow->get<bool>()) camera.shadow = kDefaultShadow;
    } else {
      camera.shadow = reader.color(*shadow, pointer + "/shadow");
    }
  }
  return camera;
}

std::vector<Solid> default_solids(const std::array<Eigen::Vector3d, 4>& reference) {
  return {builtin_solid("tetrahedron", reference)};
}

}  // namespace pita::scene::detail
