#include "motion/moving_keyframes.hpp"

#include <algorithm>

#include "core/steady_morph.hpp"

namespace pita::motion {

namespace {

void move(std::vector<Keyframe>& keyframes, std::vector<Arrow>& targets, double tau) {
  if (targets.empty()) return;
  for (std::size_t i = 0; i < keyframes.size(); ++i) {
    keyframes[i].arrow = steady_morph(keyframes[i].arrow, targets[i], tau);
  }
  targets.clear();
}

}  // namespace

bool has_moving_keyframes(const scene::Scene& scene) {
  return !scene.keyframes_to.empty() ||
         std::any_of(scene.panels.begin(), scene.panels.end(),
                     [](const scene::Panel& panel) { return !panel.keyframes_to.empty(); });
}

scene::Scene scene_at(const scene::Scene& scene, double tau) {
  scene::Scene moved = scene;
  move(moved.keyframes, moved.keyframes_to, tau);
  for (scene::Panel& panel : moved.panels) move(panel.keyframes, panel.keyframes_to, tau);
  return moved;
}

}  // namespace pita::motion
