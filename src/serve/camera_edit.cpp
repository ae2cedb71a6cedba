#include "serve/camera_edit.hpp"

#include <cmath>
#include <stdexcept>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "render/pose_panel.hpp"
#include "scene/limits.hpp"

namespace pita::serve {

namespace {

using Json = nlohmann::ordered_json;

// What each number of the camera may be, as the scene reader takes it
// (scene/space_pose_reader.cpp): "" when `x` is one, else why not.
std::string camera_number_fault(const std::string& name, double x) {
  if (!std::isfinite(x)) return fmt::format("{} must be a finite number", name);
  if (name == "azimuth" && std::abs(x) > scene::kMaxCameraAzimuth) {
    return fmt::format("azimuth must be within +-{:g} degrees (got {:g})", scene::kMaxCameraAzimuth, x);
  }
  if (name == "elevation" && std::abs(x) > scene::kMaxCameraElevation) {
    return fmt::format("elevation must be within +-{:g} degrees (got {:g})", scene::kMaxCameraElevation, x);
  }
  if (name == "distance" && !(x > 0.0 && x <= scene::kMaxKeyframeValue)) {
    return fmt::format("distance must be > 0 and at most {:g} (got {:g})", scene::kMaxKeyframeValue, x);
  }
  return "";
}

// One member of "camera" as "Save view" writes it: throws with the reason when it may not be.
void check_camera_member(const std::string& name, const Json& value) {
  if (name == "auto") {
    if (!value.is_boolean()) throw std::invalid_argument("/camera/auto must be true or false");
    return;
  }
  if (name != "azimuth" && name != "elevation" && name != "distance") {
    throw std::invalid_argument("\"" + name + "\" is not a member of the camera the page writes");
  }
  if (!value.is_number()) throw std::invalid_argument("/camera/" + name + " must be a number");
  const std::string fault = camera_number_fault(name, value.get<double>());
  if (!fault.empty()) throw std::invalid_argument("/camera/" + fault);
}

}  // namespace

CameraTurn camera_parameter(const std::string& text) {
  const auto refuse = [&](const std::string& why) {
    throw CameraRefused(fmt::format("camera: {} (got \"{}\"); camera=AZIMUTH,ELEVATION[,DISTANCE] in degrees", why,
                                    text.size() > 60 ? text.substr(0, 60) + "..." : text));
  };
  std::vector<double> numbers;
  std::size_t start = 0;
  while (numbers.size() < 4) {
    const std::size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    std::size_t used = 0;
    double x = 0.0;
    try {
      x = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (item.empty() || used != item.size()) refuse("\"" + item + "\" is not a number");
    numbers.push_back(x);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (numbers.size() < 2 || numbers.size() > 3) refuse("two or three numbers, please");
  static const char* const kNames[] = {"azimuth", "elevation", "distance"};
  for (std::size_t k = 0; k < numbers.size(); ++k) {
    const std::string fault = camera_number_fault(kNames[k], numbers[k]);
    if (!fault.empty()) refuse(fault);
  }
  CameraTurn turn{numbers[0], numbers[1], std::nullopt};
  if (numbers.size() == 3) turn.distance = numbers[2];
  return turn;
}

scene::Scene turned_scene(const scene::Scene& scene, const CameraTurn& turn) {
  if (!std::holds_alternative<scene::SpacePoseKeys>(scene.keys)) {
    throw CameraRefused("camera: only a 3D pose scene has a camera to turn");
  }
  scene::Scene turned = scene;
  scene::Camera& camera = scene::figure_of<scene::SpacePoseKeys>(turned).camera;
  camera.azimuth = turn.azimuth;
  camera.elevation = turn.elevation;
  if (turn.distance) camera.distance = *turn.distance;
  camera.automatic = false;
  return turned;
}

Json camera_json(const motion::Stage& stage) {
  const scene::Scene& scene = stage.scene();
  if (!std::holds_alternative<scene::SpacePoseKeys>(scene.keys)) return nullptr;
  const scene::Camera& camera = scene::figure_of<scene::SpacePoseKeys>(scene).camera;
  Json out{{"azimuth", camera.azimuth},         {"elevation", camera.elevation}, {"distance", camera.distance},
           {"perspective", camera.perspective}, {"auto", camera.automatic},      {"panels", Json::array()}};
  for (std::size_t i = 0; i < scene.panels.size(); ++i) {
    const scene::Camera drawn = camera.automatic ? render::drawn_camera(stage, i) : camera;
    out["panels"].push_back({{"azimuth", drawn.azimuth}, {"elevation", drawn.elevation}});
  }
  return out;
}

bool is_camera_pointer(const std::string& pointer) {
  return pointer == "/camera" || pointer == "/camera/azimuth" || pointer == "/camera/elevation" ||
         pointer == "/camera/distance" || pointer == "/camera/auto";
}

void check_camera_change(const Change& change) {
  if (!is_camera_pointer(change.pointer)) {
    throw std::invalid_argument("\"" + change.pointer + "\" is not a member of the camera the page writes");
  }
  if (change.remove) return;  // the undo of a member "Save view" added
  Json value;
  try {
    value = Json::parse(change.value);
  } catch (const Json::exception&) {
    throw std::invalid_argument("the value for " + change.pointer + " is not one JSON value");
  }
  if (change.pointer != "/camera") return check_camera_member(change.pointer.substr(8), value);
  if (!value.is_object()) throw std::invalid_argument("/camera must be an object");
  for (const auto& [name, member] : value.items()) check_camera_member(name, member);
}

}  // namespace pita::serve
