// What depends on the dimension of an affine pose, in one place: the point
// type it moves, its reference simplex (the triangle of a 2D pose scene, the
// tetrahedron of a 3D one: SAM paper Sec. 2.1), the name of its kind of scene
// in every output, and its row of frames in CSV. Code over the plane and space
// is one template over the pose that asks PoseTraits<Pose> instead of
// comparing the pose type (habit of Eigen's Transform<Scalar, Dim, Mode> and
// Sophus's common group API).
#pragma once

#include <array>
#include <string_view>

#include <Eigen/Core>

#include "core/affine2.hpp"
#include "core/affine3.hpp"
#include "core/arrow.hpp"

namespace pita {

class PoseMotion;  // core/pose_motion.hpp
template <class Pose>
class SamFamilyMotion;  // core/sam_family_motion.hpp

template <class Pose>
struct PoseTraits;

template <>
struct PoseTraits<Affine2> {
  static constexpr int dimension = 2;
  using Vector = Eigen::Vector2d;  // a point of the plane as Eigen has it
  using LinearPart = Eigen::Matrix2d;
  // A point of the body the pose moves, as the drawing layers hold it (the
  // plane's points are complex numbers).
  using BodyPoint = Point;
  // The reference simplex: a pose is the affinity that maps it onto the
  // pose's triangle (SAM paper Sec. 2.1).
  static constexpr int simplex_vertices = 3;
  using Simplex = std::array<BodyPoint, simplex_vertices>;
  // The motions through poses of the plane: the SAM family and the morphs of
  // Fig. 2 (core/pose_motion.hpp).
  using Motion = PoseMotion;
  // "poses": the kind of scene in pita measure's and Python's outputs.
  static constexpr std::string_view kind_name = "poses";
  // How messages name a motion of such poses.
  static constexpr std::string_view noun = "poses of the plane";
  // The CSV columns of one frame: t, then the 2x3 matrix row by row.
  static constexpr std::string_view csv_header = "t,a,b,tx,c,d,ty\n";
};

template <>
struct PoseTraits<Affine3> {
  static constexpr int dimension = 3;
  using Vector = Eigen::Vector3d;
  using LinearPart = Eigen::Matrix3d;
  using BodyPoint = Eigen::Vector3d;
  static constexpr int simplex_vertices = 4;
  using Simplex = std::array<BodyPoint, simplex_vertices>;
  using Motion = SamFamilyMotion<Affine3>;  // the SAM family (core/sam_family_motion.hpp)
  static constexpr std::string_view kind_name = "poses3d";
  static constexpr std::string_view noun = "poses of space";
  static constexpr std::string_view csv_header = "t,a,b,c,tx,d,e,f,ty,g,h,i,tz\n";
};

// Whether a pose moves space (a 3D scene) rather than the plane.
template <class Pose>
inline constexpr bool in_space_v = PoseTraits<Pose>::dimension == 3;

}  // namespace pita
