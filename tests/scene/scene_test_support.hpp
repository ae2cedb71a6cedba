// Helpers shared by the scene tests.
#pragma once

#include <string>

#include "scene/scene.hpp"

namespace pita::scene::test {

// The message of the SceneError that parsing `text` (as "s.json") throws, or "(no error)".
inline std::string error_of(const std::string& text) {
  try {
    parse_scene(text, "s.json");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "(no error)";
}

}  // namespace pita::scene::test
