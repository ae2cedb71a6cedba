// A scene read once and its motion built once, kept alive by the Python
// objects that use them (pita.Motion, pita.Scene).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "motion/evaluation.hpp"
#include "python/bindings.hpp"
#include "scene/scene.hpp"

namespace pita::python {

struct HeldMotion {
  scene::Scene scene;
  std::unique_ptr<motion::Evaluation> evaluation;  // refers to `scene`: this object does not move
};

// The motion of `scene` (its own, or panel `panel`'s), built once and kept
// with a copy of the scene. Throws scene::SceneError for a scene without a
// motion, motion::NoMotion, and ValueError for a panel it does not have.
std::shared_ptr<HeldMotion> hold_motion(scene::Scene scene, std::optional<int> panel = std::nullopt);

// The frames of `motion` at `times`, as pita.Motion returns them.
py::object sample(const motion::SceneMotion& motion, const Times& times);

}  // namespace pita::python
