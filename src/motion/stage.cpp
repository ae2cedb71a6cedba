#include "motion/stage.hpp"

#include <string>
#include <utility>

#include "core/overloaded.hpp"
#include "core/pitas/registry.hpp"

namespace pita::motion {

namespace {

// A pose panel without poses has no motion (its layers draw none; building
// it gives the NoMotion that says so); every other panel has one, or the
// NoMotion that says why not.
bool draws_a_motion(const scene::Panel& panel) { return scene::has_motion_keys(panel.keys); }

// The panel's keyframes or points; NoMotion for a panel of poses.
scene::TrackMethod& track_of(const scene::Scene& scene, scene::Panel& panel) {
  if (scene::TrackMethod* track = scene::track_method(panel.keys)) return *track;
  throw NoMotion(scene.path, "/method", "a method of arrows was asked for a panel of poses");
}

}  // namespace

Stage::Stage(const scene::Scene& scene) : scene_(&scene) {
  for (const scene::Panel& panel : scene.panels) panels_.push_back(&panel);
  build();
}

Stage::Stage(const scene::Scene& scene, const scene::Panel& panel) : scene_(&scene), panels_{&panel} { build(); }

void Stage::build() {
  for (const scene::Panel* panel : panels_) {
    drawn_.push_back(draws_a_motion(*panel));
    try {
      motions_.emplace_back(build_motion(*scene_, *panel));
    } catch (const NoMotion& error) {
      motions_.emplace_back(error);
    }
  }
}

bool Stage::has_motion(std::size_t index) const { return drawn_.at(index); }

const SceneMotion& Stage::motion(std::size_t index) const {
  const Built& built = motions_.at(index);
  if (const auto* error = std::get_if<NoMotion>(&built)) throw *error;
  return std::get<SceneMotion>(built);
}

void Stage::check() const {
  for (std::size_t i = 0; i < motions_.size(); ++i) {
    if (drawn_[i]) (void)motion(i);
  }
}

bool own_is_first_panel(const scene::Scene& scene) {
  return scene.panels.size() == 1 && scene.panels.front().pointer.empty();
}

SceneMotion with_method(const scene::Scene& scene, const scene::Panel& panel, const AnyMethod& method) {
  scene::Panel other = panel;
  const auto arrows_asked = [&] {
    throw NoMotion(scene.path, "/method", "a method of poses was asked for a panel of arrows");
  };
  std::visit(overloaded{[&](Method arrow_method) { track_of(scene, other).method = arrow_method; },
                        [&](PoseMethod pose_method) {
                          std::visit(overloaded{[&](scene::KeyframeKeys&) { arrows_asked(); },
                                                [&](scene::PointKeys&) { arrows_asked(); },
                                                [&](scene::PlanePoseKeys& given) { given.method = pose_method; },
                                                [&](scene::SpacePoseKeys& given) { given.method = pose_method; }},
                                     other.keys);
                        }},
             method);
  return build_motion(scene, other);
}

scene::Panel layer_panel(const scene::Panel& panel, std::optional<Method> method, const MethodOptions& options) {
  scene::Panel own = panel;
  if (scene::TrackMethod* track = scene::track_method(own.keys)) {
    if (method) track->method = *method;
    track->options = options;
  }
  return own;
}

SceneMotion with_layer_method(const scene::Scene& scene, const scene::Panel& panel, std::optional<Method> method,
                              const MethodOptions& options) {
  return build_motion(scene, layer_panel(panel, method, options));
}

SceneMotion untimed_with_keyframes(const scene::Scene& scene, const scene::Panel& panel,
                                   std::vector<Keyframe> keyframes) {
  scene::Panel moved = panel;
  moved.timing = scene::Timing{};
  auto* arrows = std::get_if<scene::KeyframeKeys>(&moved.keys);
  if (arrows == nullptr) throw NoMotion(scene.path, panel.motion_pointer, "the panel has no keyframes to move");
  arrows->keyframes = std::move(keyframes);
  return build_motion(scene, moved);
}

SceneMotion with_scene_keyframes(const scene::Scene& scene, const scene::Panel& panel, scene::Panel* reference) {
  scene::Panel own = scene::scene_panel(scene);
  const scene::TrackMethod* given = scene::track_method(panel.keys);
  if (given == nullptr) throw NoMotion(scene.path, "/method", "a method of arrows was asked for a panel of poses");
  track_of(scene, own) = *given;
  own.timing = panel.timing;
  SceneMotion motion = build_motion(scene, own);
  if (reference != nullptr) *reference = std::move(own);
  return motion;
}

}  // namespace pita::motion
