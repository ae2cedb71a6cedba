// The one error of the motion stage: no motion exists for these keyframes or
// poses (or it is undefined, or not finite, at a requested time). Like a
// scene error it is a located error (scene/located_error.hpp): it names the
// file and the JSON Pointer of what is at fault; what() is
// "FILE: POINTER: reason". The CLI maps it to exit code 2.
#pragma once

#include <string>
#include <utility>

#include "scene/located_error.hpp"

namespace pita::motion {

class NoMotion : public scene::LocatedError {
 public:
  NoMotion(std::string file, std::string pointer, std::string reason)
      : LocatedError(scene::LocatedKind::no_motion, std::move(file), std::move(pointer), std::move(reason)) {}
};

}  // namespace pita::motion
