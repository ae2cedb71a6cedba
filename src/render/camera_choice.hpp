// "camera": {"auto": true} (scene/figure.hpp): the direction from which no
// pose of a 3D figure is seen edge-on (docs/reference/pose-scenes.md "3D pose scenes").
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/affine3.hpp"
#include "scene/figure.hpp"

namespace pita::render {

// The unit vector from the target towards a camera at `azimuth` (about z,
// from +x) and `elevation` (above the xy plane), in degrees.
Eigen::Vector3d towards_eye(double azimuth, double elevation);

// How open `solid` at `pose` looks from the unit direction `d`: the area its
// faces show, sum |a_f . d|, over their area, sum |a_f|, where a_f is a
// face's area vector. For a closed solid the first sum is twice the area of
// its outline on the image. 0 for a flat solid seen edge-on; from 1/3 (along
// an axis) to 1/sqrt(3) (along a diagonal) for a cube.
double openness(const scene::Solid& solid, const Affine3& pose, const Eigen::Vector3d& d);

// The directions tried: azimuth every kAzimuthStep degrees, elevation from
// kLowestElevation to kHighestElevation (z up: from above, never from below).
inline constexpr double kAzimuthStep = 5.0;
inline constexpr double kLowestElevation = 10.0, kHighestElevation = 75.0;
// A direction is good enough when its least open pose is at least this
// share of the best direction's: no pose much flatter than it could be.
inline constexpr double kNearBest = 0.8;

// How much of the posed solids' images those nearer the camera cover: the
// largest share, over the posed solids (every solid at every pose, a pose
// given twice counted once), of a solid's image (its faces, orthographic from
// the unit direction `d`) that the solids painted after it cover, painting
// solid by solid back to front by their mean depth as the figure does
// (render/solid_faces.hpp), on a raster of kHiddenRaster cells along the
// longer side of the image. 0 for one solid alone; near 1 for a solid behind
// another (SAM 3D Fig. 13's middle span, seen along it).
double most_hidden(const std::vector<scene::Solid>& solids, const std::vector<Affine3>& poses,
                   const Eigen::Vector3d& d);
inline constexpr int kHiddenRaster = 160;
// A direction hides too much when some posed solid is hidden by more than
// this share: the default "max_hidden_share" of the lint's "hidden-copy"
// check (docs/reference/lint.md), which the choice thereby avoids.
inline constexpr double kMostHidden = 0.5;

// A direction's score is the openness of its least open pose (of `poses`,
// every solid); it is good enough when that is at least kNearBest of the best
// direction's. The given camera when its direction is good enough and hides
// no solid by more than kMostHidden (most_hidden), else the given camera turned
// to the good enough direction tried, hiding none so, that is nearest the given
// one; when every good enough direction hides some solid, the one that hides
// least. Distance, projection and target are kept. With no solid or no pose,
// the given camera.
scene::Camera chosen_camera(const scene::Camera& given, const std::vector<scene::Solid>& solids,
                            const std::vector<Affine3>& poses);

}  // namespace pita::render
