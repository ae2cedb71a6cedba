// Reading the parts of a pose scene (docs/reference/pose-scenes.md "Pose scenes"): the reference
// triangle, the poses (2x3 matrices or triangles), the shapes. Internal to
// src/scene/; errors are SceneErrors naming the JSON Pointer of the bad value.
#pragma once

#include <Eigen/Core>

#include "core/affine2.hpp"
#include "core/affine3.hpp"

#include <array>
#include <string>
#include <vector>

#include "core/pose_motion.hpp"
#include "scene/figure.hpp"
#include "scene/json_reader.hpp"

namespace pita::scene::detail {

// A number of a pose or point: within +-kMaxKeyframeValue.
double bounded(const JsonReader& reader, const Json& value, const std::string& pointer);

// "reference_triangle": three points, not collinear.
std::array<Point, 3> read_reference_triangle(const JsonReader& reader, const Json& value,
                                             const std::string& pointer);

// How a pose of the plane (Affine2) or of space (Affine3) is given: a matrix,
// or the images of the reference simplex's points (a triangle, a
// tetrahedron). The one reader of "poses", read_poses<Pose>, is written once
// over this trait.
template <class Pose>
struct PoseSpace;

template <>
struct PoseSpace<Affine2> {
  using Simplex = std::array<Point, 3>;
  static constexpr const char* kSimplex = "triangle";
  static constexpr const char* kFlat = "collinear";  // what a degenerate simplex's points are
  static constexpr const char* kMatrixShape = "[[a, b, tx], [c, d, ty]]";
  static constexpr const char* kPointsShape = "[[x, y], [x, y], [x, y]]";
  static Simplex read_simplex(const JsonReader& reader, const Json& value, const std::string& pointer);
  static bool degenerate(const Simplex& points);
  static Affine2 frame_of(const Simplex& points);  // the unit simplex onto `points`
  static Affine2 read_matrix(const JsonReader& reader, const Json& value, const std::string& pointer);
  // A pose given as the other dimension's simplex (none is refused here: the
  // field check names it).
  static void refuse_other_simplex(const JsonReader&, const Json&, const std::string&) {}
};

template <>
struct PoseSpace<Affine3> {
  using Simplex = std::array<Eigen::Vector3d, 4>;
  static constexpr const char* kSimplex = "tetrahedron";
  static constexpr const char* kFlat = "coplanar";
  static constexpr const char* kMatrixShape = "[[a, b, c, tx], [d, e, f, ty], [g, h, i, tz]]";
  static constexpr const char* kPointsShape = "[[x, y, z] x 4]";
  static Simplex read_simplex(const JsonReader& reader, const Json& value, const std::string& pointer);
  static bool degenerate(const Simplex& points);
  static Affine3 frame_of(const Simplex& points);
  static Affine3 read_matrix(const JsonReader& reader, const Json& value, const std::string& pointer);
  // A "triangle" in a 3D scene: a pose of the plane, said so.
  static void refuse_other_simplex(const JsonReader& reader, const Json& item, const std::string& pointer);
};

// "poses": an array of {"t", and "matrix" or the simplex ("triangle" in the
// plane, "tetrahedron" in space)}, knots strictly increasing, each pose
// invertible; as many as `method` takes (at most kMaxPoses).
template <class Pose>
std::vector<TimedPoseOf<Pose>> read_poses(const JsonReader& reader, const Json& value, const std::string& pointer,
                                          const typename PoseSpace<Pose>::Simplex& reference, PoseMethod method);

// "shapes": an array of {"polygon": points} | {"polyline": points} |
// {"triangle": "reference"} | {"outline": "F" | "house" | "square" |
// "picture"} | {"image": path, "box": [[x0, y0], [x1, y1]]}, each with an
// optional "color". A "picture" is several outlines; an image's file is
// checked by check_image_file (image_file.hpp).
std::vector<ShapeOutline> read_shapes(const JsonReader& reader, const Json& value,
                                      const std::string& pointer,
                                      const std::array<Point, 3>& reference);

// The builtin outlines, in the unit box [0, 1]^2; "picture" has several parts.
std::vector<ShapeOutline> builtin_outline(std::string_view name);

// "method SAM takes exactly 2 poses (got 3)", "method polySAM takes 2 to 1000 poses (got 1)".
std::string pose_count_reason(PoseMethod method, std::size_t count);

// The method of a pose scene or panel ("SAM", "polySAM", ...).
PoseMethod read_pose_method(const JsonReader& reader, const Json& value,
                            const std::string& pointer);

}  // namespace pita::scene::detail
