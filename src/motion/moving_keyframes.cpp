#include "motion/moving_keyframes.hpp"

#include <algorithm>

#include "core/steady_morph.hpp"

namespace pita::motion {

namespace {

// Moves the keyframes of arrow keys to tau; the handle stays where it was
// (the first keyframe's "from" arrow when none was given).
void move(scene::MotionKeys& keys, double tau) {
  auto* arrows = std::get_if<scene::KeyframeKeys>(&keys);
  if (arrows == nullptr || arrows->keyframes_to.empty()) return;
  arrows->given_handle = arrows->handle();
  for (std::size_t i = 0; i < arrows->keyframes.size(); ++i) {
    arrows->keyframes[i].arrow = steady_morph(arrows->keyframes[i].arrow, arrows->keyframes_to[i], tau);
  }
  arrows->keyframes_to.clear();
}

bool moves(const scene::MotionKeys& keys) {
  const auto* arrows = std::get_if<scene::KeyframeKeys>(&keys);
  return arrows != nullptr && !arrows->keyframes_to.empty();
}

}  // namespace

bool has_moving_keyframes(const scene::Scene& scene) {
  return moves(scene.keys) || std::any_of(scene.panels.begin(), scene.panels.end(),
                                          [](const scene::Panel& panel) { return moves(panel.keys); });
}

scene::Scene scene_at(const scene::Scene& scene, double tau) {
  scene::Scene moved = scene;
  move(moved.keys, tau);
  for (scene::Panel& panel : moved.panels) move(panel.keys, tau);
  return moved;
}

}  // namespace pita::motion
