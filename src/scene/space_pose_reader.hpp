// Reading 3D pose scenes ("dimension": 3; docs/reference/pose-scenes.md "3D pose scenes"): the
// reference tetrahedron, the poses (3x4 matrices or tetrahedra), and the
// scene itself. Internal to src/scene/; errors are SceneErrors naming the
// JSON Pointer of the bad value.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/sam_family_motion.hpp"
#include "scene/json_reader.hpp"
#include "scene/scene.hpp"

namespace pita::scene::detail {

// "reference_tetrahedron": four points [x, y, z], not coplanar.
std::array<Eigen::Vector3d, 4> read_reference_tetrahedron(const JsonReader& reader, const Json& value,
                                                          const std::string& pointer);

// "poses" of space: read_poses<Affine3> (pose_reader.hpp).

// The method of a 3D scene or panel: one of the SAM family (in_space).
PoseMethod read_space_pose_method(const JsonReader& reader, const Json& value, const std::string& pointer);

// The whole 3D pose scene (the document has "dimension": 3). Refused at
// /dimension unless the reader's options allow 3D scenes.
Scene read_space_pose_scene(const JsonReader& reader, const Json& document);

}  // namespace pita::scene::detail
