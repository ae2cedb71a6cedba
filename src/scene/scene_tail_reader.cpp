// What every scene ends with, read once for arrow scenes and pose scenes of
// either dimension: "golden", "claims", "lint" and "animation".
#include "scene/scene_readers.hpp"

#include "scene/animation_reader.hpp"

namespace pita::scene::detail {

void read_scene_tail(const JsonReader& reader, const Json& document, Scene& scene, bool moving) {
  const bool poses = track_method(scene.keys) == nullptr;
  if (const Json* golden = JsonReader::member(document, "golden")) read_golden(reader, *golden, scene.golden);
  if (const Json* claims = JsonReader::member(document, "claims")) {
    scene.claims = read_claims(reader, *claims, scene, poses);
  }
  if (const Json* lint = JsonReader::member(document, "lint")) scene.lint = read_lint(reader, *lint);
  if (const Json* animation = JsonReader::member(document, "animation")) {
    scene.animation = read_animation(reader, *animation, "/animation", moving, poses);
    scene.has_animation = true;
  } else {
    scene.animation = default_animation(moving);
  }
}

}  // namespace pita::scene::detail
