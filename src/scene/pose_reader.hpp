// Reading the parts of a pose scene (docs/reference/pose-scenes.md "Pose scenes"), once
// over the dimension: the reference simplex (a triangle in the plane, a
// tetrahedron in space), the poses (matrices or simplices), the method; and
// the shapes of the plane. Internal to src/scene/; errors are SceneErrors
// naming the JSON Pointer of the bad value.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/affine2.hpp"
#include "core/affine3.hpp"
#include "core/pose_motion.hpp"
#include "core/pose_traits.hpp"
#include "scene/figure.hpp"
#include "scene/json_reader.hpp"

namespace pita::scene::detail {

// A number of a pose or point: within +-kMaxKeyframeValue.
double bounded(const JsonReader& reader, const Json& value, const std::string& pointer);

// How a pose of the plane (Affine2) or of space (Affine3) is given in a
// scene: what the messages call its parts, and the few readings that differ
// by more than a size (a point of the plane is a complex number; a singular
// pose of space is told from an ill-conditioned one). The readers below are
// written once over this trait.
template <class Pose>
struct PoseSpace;

template <>
struct PoseSpace<Affine2> {
  using Traits = PoseTraits<Affine2>;
  using Simplex = Traits::Simplex;
  static constexpr const char* kSimplex = "triangle";
  static constexpr const char* kFlat = "collinear";  // what a degenerate simplex's points are
  static constexpr const char* kSimplexPoints = "three points [[x, y], [x, y], [x, y]]";
  static constexpr const char* kMatrixShape = "[[a, b, tx], [c, d, ty]]";
  static constexpr const char* kLinearShape = "[[a, b], [c, d]]";
  static constexpr const char* kTranslationShape = "[tx, ty]";
  static constexpr const char* kPointsShape = "[[x, y], [x, y], [x, y]]";
  // A point [x, y], each coordinate within +-kMaxKeyframeValue.
  static Point read_point(const JsonReader& reader, const Json& value, const std::string& pointer);
  static Eigen::Vector2d vector_of(const Point& p) { return Eigen::Vector2d(p.real(), p.imag()); }
  // |L|_F^2: what |det L| is compared with (scene/limits.hpp kSingularPose).
  static double singular_scale(const Traits::LinearPart& L) { return L.squaredNorm(); }
  [[noreturn]] static void refuse_singular(const JsonReader& reader, const std::string& pointer,
                                           const Traits::LinearPart& L, double det, double scale);
  // A pose given in the other dimension's form (none is refused here: the
  // field and shape checks name it).
  static void refuse_other_simplex(const JsonReader&, const Json&, const std::string&) {}
  static void refuse_other_matrix(const JsonReader&, const Json&, const std::string&) {}
};

template <>
struct PoseSpace<Affine3> {
  using Traits = PoseTraits<Affine3>;
  using Simplex = Traits::Simplex;
  static constexpr const char* kSimplex = "tetrahedron";
  static constexpr const char* kFlat = "coplanar";
  static constexpr const char* kSimplexPoints = "four points [[x, y, z], [x, y, z], [x, y, z], [x, y, z]]";
  static constexpr const char* kMatrixShape = "[[a, b, c, tx], [d, e, f, ty], [g, h, i, tz]]";
  static constexpr const char* kLinearShape = "[[a, b, c], [d, e, f], [g, h, i]]";
  static constexpr const char* kTranslationShape = "[tx, ty, tz]";
  static constexpr const char* kPointsShape = "[[x, y, z] x 4]";
  static Eigen::Vector3d read_point(const JsonReader& reader, const Json& value, const std::string& pointer);
  static const Eigen::Vector3d& vector_of(const Eigen::Vector3d& p) { return p; }
  // |L|_F^3 (as in the plane with |L|_F^2: about the ratio of the smallest
  // singular value to the largest times that of the middle one).
  static double singular_scale(const Traits::LinearPart& L) {
    const double norm = L.norm();
    return norm * norm * norm;
  }
  [[noreturn]] static void refuse_singular(const JsonReader& reader, const std::string& pointer,
                                           const Traits::LinearPart& L, double det, double scale);
  // A "triangle" or a 2x3 matrix in a 3D scene: a pose of the plane, said so.
  static void refuse_other_simplex(const JsonReader& reader, const Json& item, const std::string& pointer);
  static void refuse_other_matrix(const JsonReader& reader, const Json& value, const std::string& pointer);
};

// The simplex's points, as many as it has (three points [x, y], four [x, y, z]).
template <class Pose>
typename PoseSpace<Pose>::Simplex read_simplex(const JsonReader& reader, const Json& value, const std::string& pointer);

// The affinity [p1 - p0, p2 - p0 (, p3 - p0) | p0] that maps the unit simplex onto `p`.
template <class Pose>
Pose frame_of(const typename PoseSpace<Pose>::Simplex& p);

// Whether the simplex is flat: its volume (the determinant of frame_of, twice
// the area of a triangle, six times the volume of a tetrahedron) at most
// kDegenerateSimplex of the product of its edge lengths from p0.
template <class Pose>
bool degenerate(const typename PoseSpace<Pose>::Simplex& p);

// A pose given as a matrix: 2x3 [[a, b, tx], [c, d, ty]] in the plane, 3x4
// in space, invertible (|det L| above kSingularPose of singular_scale(L)).
template <class Pose>
Pose read_matrix(const JsonReader& reader, const Json& value, const std::string& pointer);

// "reference_triangle" or "reference_tetrahedron": the simplex, not flat.
template <class Pose>
typename PoseSpace<Pose>::Simplex read_reference(const JsonReader& reader, const Json& value,
                                                 const std::string& pointer);

// "poses": an array of {"t", and "matrix" or the simplex ("triangle" in the
// plane, "tetrahedron" in space)}, knots strictly increasing, each pose
// invertible; as many as `method` takes (at most kMaxPoses).
template <class Pose>
std::vector<TimedPoseOf<Pose>> read_poses(const JsonReader& reader, const Json& value, const std::string& pointer,
                                          const typename PoseSpace<Pose>::Simplex& reference, PoseMethod method);

// "missing required field (an array of poses ...)": the reason when a scene
// that needs poses has none.
template <class Pose>
std::string missing_poses_reason();

// "shapes": an array of {"polygon": points} | {"polyline": points} |
// {"triangle": "reference"} | {"outline": "F" | "house" | "square" |
// "picture"} | {"image": path, "box": [[x0, y0], [x1, y1]]}, each with an
// optional "color". A "picture" is several outlines; an image's file is
// checked by check_image_file (image_file.hpp).
std::vector<ShapeOutline> read_shapes(const JsonReader& reader, const Json& value, const std::string& pointer,
                                      const std::array<Point, 3>& reference);

// The builtin outlines, in the unit box [0, 1]^2; "picture" has several parts.
std::vector<ShapeOutline> builtin_outline(std::string_view name);

// "method SAM takes exactly 2 poses (got 3)", "method polySAM takes 2 to 1000 poses (got 1)".
std::string pose_count_reason(PoseMethod method, std::size_t count);

// The method of a pose scene or panel ("SAM", "polySAM", ...).
PoseMethod read_pose_method(const JsonReader& reader, const Json& value, const std::string& pointer);

// The method of a scene or panel of poses of `Pose`: of space, one of the
// SAM family that moves space (in_space).
template <class Pose>
PoseMethod read_pose_method_of(const JsonReader& reader, const Json& value, const std::string& pointer);

}  // namespace pita::scene::detail
