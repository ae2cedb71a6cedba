// What `pita eval` evaluates in a scene: the scene's own motion (its method,
// keyframes or poses and timing), or the motion of one of its panels. The
// CLI's eval and the Python module's Scene.eval both start here, so that the
// same scene gives the same frames through either.
#pragma once

#include <cstddef>
#include <optional>

#include "motion/stage.hpp"
#include "scene/scene.hpp"

namespace pita::motion {

class Evaluation {
 public:
  // Builds every panel's motion and checks that each exists (Stage::check:
  // a scene is judged alike by every command), then the motion evaluated:
  // panel `panel` (0 = the first entry of "panels"), else the scene's own.
  // Throws NoMotion, then std::out_of_range ("SCENE has 2 panels (0 to 1);
  // got 5") for a panel the scene does not have. The scene must have a
  // motion (scene::has_motion_keys) and outlive the evaluation.
  Evaluation(const scene::Scene& scene, std::optional<int> panel);
  Evaluation(const Evaluation&) = delete;
  Evaluation& operator=(const Evaluation&) = delete;

  const scene::Panel& panel() const { return chosen().panel(index_); }
  const SceneMotion& motion() const { return chosen().motion(index_); }

 private:
  const Stage& chosen() const { return own_stage_ ? *own_stage_ : stage_; }

  Stage stage_;
  scene::Panel own_;                // the scene's own panel (scene::scene_panel)
  std::optional<Stage> own_stage_;  // its motion, unless it is the first panel's
  std::size_t index_ = 0;
};

}  // namespace pita::motion
