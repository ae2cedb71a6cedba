// The camera of a 3D pose scene as `pita serve`'s page turns it: the route's
// `camera=AZ,EL[,DIST]` parameter, the scene drawn with that camera, what the
// page is told of the camera, and what "Save view" may write into the scene
// file (docs/reference/serve.md "Turning 3D scenes").
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "motion/stage.hpp"
#include "scene/scene.hpp"
#include "serve/scene_edit.hpp"

namespace pita::serve {

// A turn the server refuses (answered 400 with its reason).
struct CameraRefused : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// A camera the page turned to: degrees as "camera" gives them, and the
// distance when the page changed it.
struct CameraTurn {
  double azimuth = 0.0;
  double elevation = 0.0;
  std::optional<double> distance;
};

// `camera=AZ,EL[,DIST]`: two or three finite numbers, the azimuth within
// +-kMaxCameraAzimuth, the elevation within +-kMaxCameraElevation, the
// distance > 0 and within the reader's bound; as the scene reader would
// take them. Throws CameraRefused with the reason otherwise.
CameraTurn camera_parameter(const std::string& text);

// The scene with its camera turned: the azimuth, the elevation (and the
// distance) of `turn`, "auto" off (the view is drawn as turned, never turned
// again by pita), the rest as it was: what `pita render` draws of the file
// once "Save view" wrote the turn into it. Throws CameraRefused when
// the scene is not a 3D pose scene (it has no camera).
scene::Scene turned_scene(const scene::Scene& scene, const CameraTurn& turn);

// What the page knows of a scene's camera: null for a scene of the plane,
// else {"azimuth", "elevation", "distance", "perspective", "auto", "panels":
// [{"azimuth", "elevation"}, ...]}, the panels' as drawn ("auto" turns each
// panel on its own: render::drawn_camera).
nlohmann::ordered_json camera_json(const motion::Stage& stage);

// A pointer "Save view" writes: /camera, /camera/azimuth, /camera/elevation,
// /camera/distance or /camera/auto.
bool is_camera_pointer(const std::string& pointer);

// Such a change as the page may send it: azimuth, elevation and distance
// numbers within the reader's limits, auto a boolean; /camera an object of
// those members only (the undo of removing it), or any of them removed (the
// undo of adding it). Throws std::invalid_argument with the reason otherwise.
void check_camera_change(const Change& change);

}  // namespace pita::serve
