// The motion stage of a scene: the motion of each panel, built once, for the
// commands to consume (render and animate draw it, eval prints it, measure and
// sweep weigh it), and the motions derived from a panel's that figures and
// measures compare it with (another method, other options, moved keyframes).
// Outside src/motion/, motions come from here: nothing else calls
// build_motion.
#pragma once

#include <cstddef>
#include <optional>
#include <variant>
#include <vector>

#include "core/keyframe.hpp"
#include "core/methods.hpp"
#include "core/pitas/method_options.hpp"
#include "motion/no_motion.hpp"
#include "motion/scene_motion.hpp"
#include "scene/scene.hpp"

namespace pita::motion {

class Stage {
 public:
  // Every panel of `scene` (scene.panels). The scene must outlive the stage.
  explicit Stage(const scene::Scene& scene);
  // One panel of `scene` (the scene's own, scene::scene_panel, or a panel
  // of it); both must outlive the stage.
  Stage(const scene::Scene& scene, const scene::Panel& panel);

  const scene::Scene& scene() const { return *scene_; }
  std::size_t size() const { return panels_.size(); }
  const scene::Panel& panel(std::size_t index) const { return *panels_.at(index); }

  // False for a panel without a motion: a pose panel without poses, whose
  // layers (an "existence" map) draw none.
  bool has_motion(std::size_t index) const;
  // The motion of panel `index`, built when the stage was made. Throws the
  // NoMotion its building raised (a layer that does not draw the motion
  // never asks), also for a panel that has none.
  const SceneMotion& motion(std::size_t index) const;
  // Throws the NoMotion of the first panel with a motion (has_motion) that
  // does not exist, so that a scene is judged alike by every command.
  void check() const;

 private:
  using Built = std::variant<SceneMotion, NoMotion>;
  void build();

  const scene::Scene* scene_;
  std::vector<const scene::Panel*> panels_;
  std::vector<Built> motions_;  // the motion, or why there is none
  std::vector<bool> drawn_;     // has_motion
};

// Whether the scene's own motion (scene::scene_panel) is its first panel:
// a scene without "panels" has only that one. Then a Stage of the scene
// holds it already, and building it again would be work done twice.
bool own_is_first_panel(const scene::Scene& scene);

// Motions derived from a panel's, built on demand (not kept): the same
// keyframes or poses, timing and chain, with what the name says changed.
// Each throws NoMotion when the changed motion does not exist.
//
// Another method of the panel's kind: of its keyframes (an arrow method: a
// "compare" layer, analysis/comparison) or of its poses (a pose method: a
// "versus" layer, the area chart of SAM Fig. 3). A method of the other kind
// throws NoMotion at /method.
SceneMotion with_method(const scene::Scene& scene, const scene::Panel& panel, const AnyMethod& method);
// A method and options of a layer's own (a "pattern" layer with "method" or
// "options", docs/paper-notes.md N57): the method when given, the options
// over the panel's.
SceneMotion with_layer_method(const scene::Scene& scene, const scene::Panel& panel, std::optional<Method> method,
                              const MethodOptions& options);
// Other keyframes under the panel's method, options and chain, without its
// timing (the tweaks of analysis/measure: the method's own response, which
// the timing only paces, docs/paper-notes.md N37).
SceneMotion untimed_with_keyframes(const scene::Scene& scene, const scene::Panel& panel,
                                   std::vector<Keyframe> keyframes);
// The scene's own keyframes (and handle) under the panel's method, options,
// chain and timing (analysis::handle_shift); the panel it builds is returned
// through `reference` when asked.
SceneMotion with_scene_keyframes(const scene::Scene& scene, const scene::Panel& panel,
                                 scene::Panel* reference = nullptr);

// The panel that with_layer_method builds: its method and options (render
// checks that the layer's options are read by its method on it).
scene::Panel layer_panel(const scene::Panel& panel, std::optional<Method> method, const MethodOptions& options);

}  // namespace pita::motion
