// Reading what only 3D pose scenes have ("dimension": 3; docs/reference/pose-scenes.md "3D
// pose scenes"): the solids ("shapes") and the camera. The scene itself, its
// reference tetrahedron and its poses are read as in the plane, by one reader
// over the pose (pose_scene_reader.cpp, pose_reader.hpp). Internal to
// src/scene/; errors are SceneErrors naming the JSON Pointer of the bad value.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "scene/figure.hpp"
#include "scene/json_reader.hpp"

namespace pita::scene::detail {

// "shapes" of a 3D scene: 1 to kMaxSolids {"solid": "cube" | "tetrahedron" |
// "F" | "house"} or {"polyhedron": {"vertices", "faces"}}, each with an
// optional "color"; the builtin tetrahedron is the reference one.
std::vector<Solid> read_solids(const JsonReader& reader, const Json& value, const std::string& pointer,
                               const std::array<Eigen::Vector3d, 4>& reference);

// The solids of a 3D scene without "shapes": the reference tetrahedron.
std::vector<Solid> default_solids(const std::array<Eigen::Vector3d, 4>& reference);

// "camera": {"azimuth", "elevation", "distance", "projection", "target", "auto", "shadow"}.
Camera read_camera(const JsonReader& reader, const Json& value, const std::string& pointer);

}  // namespace pita::scene::detail
