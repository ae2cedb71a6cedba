#include "scene/space_pose_reader.hpp"

#include <cmath>
#include <string_view>

#include <Eigen/LU>
#include <fmt/format.h>

#include "scene/pose_reader.hpp"
#include "scene/scene_readers.hpp"

namespace pita::scene::detail {

namespace {

constexpr std::array<std::string_view, 9> kSpaceSceneFields = {
    "$schema", "description", "dimension", "method", "poses", "reference_tetrahedron", "samples", "subdivisions",
    "golden"};
constexpr std::array<std::string_view, 3> kSpacePoseFields = {"t", "matrix", "tetrahedron"};

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

// Whether the tetrahedron is flat: its volume (times 6) below 1e-12 of the
// product of its three edge lengths from p0.
bool degenerate(const std::array<Eigen::Vector3d, 4>& p) {
  const Affine3 frame = frame_of(p);
  const double volume = frame.L.determinant();
  const double edges = frame.L.col(0).norm() * frame.L.col(1).norm() * frame.L.col(2).norm();
  return !(std::abs(volume) > 1e-12 * edges) || !std::isfinite(volume);
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
  // Invertible, numerically: |det| above 1e-16 of |L|_F^3 (as in 2D with
  // |L|_F^2: about the ratio of the smallest singular value to the largest
  // times that of the middle one). A mirrored pose is allowed; the SAM
  // between two poses needs C o B^-1 to preserve orientation, which the
  // motion checks.
  const double det = A.L.determinant();
  const double norm = A.L.norm();
  if (!(std::abs(det) > 1e-16 * norm * norm * norm) || !std::isfinite(det)) {
    reader.fail(pointer, fmt::format("the linear part [[a, b, c], [d, e, f], [g, h, i]] has determinant {}: the "
                                     "pose is singular, it flattens space onto a plane, a line or a point",
                                     number_text(det)));
  }
  return A;
}

}  // namespace

std::array<Eigen::Vector3d, 4> read_reference_tetrahedron(const JsonReader& reader, const Json& value,
                                                          const std::string& pointer) {
  const std::array<Eigen::Vector3d, 4> points = read_four_points(reader, value, pointer);
  if (degenerate(points)) reader.fail(pointer, "the reference tetrahedron is degenerate (its points are coplanar)");
  return points;
}

std::vector<TimedPose3> read_space_poses(const JsonReader& reader, const Json& value, const std::string& pointer,
                                         const std::array<Eigen::Vector3d, 4>& reference, PoseMethod method) {
  if (!value.is_array()) {
    reader.fail(pointer, fmt::format("must be an array of poses {{\"t\": ..., \"matrix\": {}}} or {{\"t\": ..., "
                                     "\"tetrahedron\": [[x, y, z] x 4]}} (got {})",
                                     kMatrixShape, value_text(value)));
  }
  const PoseMethodInfo& about = info(method);
  if (value.size() < static_cast<std::size_t>(about.min_poses) ||
      value.size() > static_cast<std::size_t>(std::min(about.max_poses, kMaxPoses))) {
    reader.fail(pointer, pose_count_reason(method, value.size()));
  }
  const Affine3 reference_frame = frame_of(reference);
  std::vector<TimedPose3> poses;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string at = element_pointer(pointer, i);
    const Json& item = value[i];
    reader.object(item, at, "a pose");
    if (JsonReader::member(item, "triangle") != nullptr) {
      reader.fail(at + "/triangle", "a triangle is a pose of the plane; a 3D scene (\"dimension\": 3) gives "
                                    "\"tetrahedron\": four points [x, y, z], or a 3x4 \"matrix\"");
    }
    reader.check_fields(item, at, kSpacePoseFields);
    const Json* t = JsonReader::member(item, "t");
    if (t == nullptr) reader.fail(at + "/t", "missing required field (the pose's time)");
    TimedPose3 pose;
    pose.t = bounded(reader, *t, at + "/t");
    if (!poses.empty() && !(pose.t > poses.back().t)) {
      reader.fail(at + "/t", fmt::format("times must increase strictly: {} follows {}", number_text(pose.t),
                                         number_text(poses.back().t)));
    }
    const Json* matrix = JsonReader::member(item, "matrix");
    const Json* tetrahedron = JsonReader::member(item, "tetrahedron");
    if (matrix != nullptr && tetrahedron != nullptr) {
      reader.fail(at + "/tetrahedron", "give either \"matrix\" or \"tetrahedron\", not both");
    }
    if (matrix != nullptr) {
      pose.pose = read_matrix3(reader, *matrix, at + "/matrix");
    } else if (tetrahedron != nullptr) {
      const std::array<Eigen::Vector3d, 4> points = read_four_points(reader, *tetrahedron, at + "/tetrahedron");
      if (degenerate(points)) {
        reader.fail(at + "/tetrahedron", "the tetrahedron is degenerate (its points are coplanar)");
      }
      pose.pose = compose(frame_of(points), inverse(reference_frame));
    } else {
      reader.fail(at, fmt::format("a pose needs \"matrix\": {} or \"tetrahedron\": [[x, y, z] x 4] (the images "
                                  "of the reference tetrahedron's points)",
                                  kMatrixShape));
    }
    poses.push_back(pose);
  }
  return poses;
}

Scene read_space_pose_scene(const JsonReader& reader, const Json& document) {
  if (!reader.options().allow_space) {
    reader.fail("/dimension", "3D pose scenes are evaluated by `pita eval` only: drawing them (camera, "
                              "polyhedra) is not built yet");
  }
  reader.check_fields(document, "", kSpaceSceneFields);
  Scene scene;
  scene.kind = SceneKind::poses;
  scene.dimension = 3;
  scene.path = reader.file();
  scene.shapes.clear();
  if (const Json* schema = JsonReader::member(document, "$schema")) reader.string(*schema, "/$schema");
  if (const Json* description = JsonReader::member(document, "description")) {
    scene.description = reader.string(*description, "/description");
  }
  const Json* method = JsonReader::member(document, "method");
  if (method == nullptr) reader.fail("/method", "missing required field (a pose method such as \"SAM\")");
  scene.pose_method = read_pose_method(reader, *method, "/method");
  if (!info(scene.pose_method).in_space) {
    std::vector<std::string_view> ids;
    for (const PoseMethodInfo& entry : all_pose_methods()) {
      if (entry.in_space) ids.push_back(entry.id);
    }
    reader.fail("/method", fmt::format("method {} moves poses of the plane only; 3D scenes take {}",
                                       info(scene.pose_method).id, quoted_choices(ids)));
  }
  scene.method_name = std::string(info(scene.pose_method).id);
  if (const Json* reference = JsonReader::member(document, "reference_tetrahedron")) {
    scene.reference_tetrahedron = read_reference_tetrahedron(reader, *reference, "/reference_tetrahedron");
  }
  if (const Json* samples = JsonReader::member(document, "samples")) {
    scene.samples = reader.integer(*samples, "/samples", kMinSamples, kMaxSamples);
  }
  if (const Json* subdivisions = JsonReader::member(document, "subdivisions")) {
    scene.subdivisions = reader.integer(*subdivisions, "/subdivisions", 0, kMaxSubdivisions);
  }
  const Json* poses = JsonReader::member(document, "poses");
  if (poses == nullptr) {
    reader.fail("/poses", fmt::format("missing required field (an array of poses {{\"t\": ..., \"matrix\": {}}})",
                                      kMatrixShape));
  }
  scene.poses3 = read_space_poses(reader, *poses, "/poses", scene.reference_tetrahedron, scene.pose_method);
  scene.pose_layers = {};
  scene.panels = {scene_panel(scene, "")};
  if (const Json* golden = JsonReader::member(document, "golden")) read_golden(reader, *golden, scene.golden);
  return scene;
}

}  // namespace pita::scene::detail
