#include "motion/no_motion.hpp"

#include <utility>

#include "scene/scene.hpp"

namespace pita::motion {

NoMotion::NoMotion(std::string file, std::string pointer, std::string reason)
    : std::runtime_error(scene::located(file, pointer, reason)),
      file_(std::move(file)),
      pointer_(std::move(pointer)),
      reason_(std::move(reason)) {}

}  // namespace pita::motion
