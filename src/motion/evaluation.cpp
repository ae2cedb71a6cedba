#include "motion/evaluation.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace pita::motion {

Evaluation::Evaluation(const scene::Scene& scene, std::optional<int> panel)
    : stage_(scene), own_(scene::scene_panel(scene)) {
  stage_.check();  // every panel's motion must exist, as for `pita render`
  if (panel) {
    if (*panel < 0 || static_cast<std::size_t>(*panel) >= scene.panels.size()) {
      throw std::out_of_range(fmt::format("{} has {} panel{} (0 to {}); got {}", scene.path, scene.panels.size(),
                                          scene.panels.size() == 1 ? "" : "s", scene.panels.size() - 1, *panel));
    }
    index_ = static_cast<std::size_t>(*panel);
  } else if (!own_is_first_panel(scene)) {
    own_stage_.emplace(scene, own_);
  }
}

}  // namespace pita::motion
