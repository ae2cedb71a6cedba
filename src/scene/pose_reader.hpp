// Reading the parts of a pose scene (README "Pose scenes"): the reference
// triangle, the poses (2x3 matrices or triangles), the shapes. Internal to
// src/scene/; errors are SceneErrors naming the JSON Pointer of the bad value.
#pragma once

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

// "poses": an array of {"t", and "matrix": [[a, b, tx], [c, d, ty]] or
// "triangle": [[x, y], [x, y], [x, y]]}, knots strictly increasing, each pose
// orientation preserving; as many as `method` takes (at most kMaxPoses).
std::vector<TimedPose> read_poses(const JsonReader& reader, const Json& value,
                                  const std::string& pointer,
                                  const std::array<Point, 3>& reference, PoseMethod method);

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
