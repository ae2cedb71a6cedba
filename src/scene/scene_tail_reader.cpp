// What every scene ends with, read once for arrow scenes and pose scenes of
// either dimension: "golden", "claims", "lint" and "animation".
#include "scene/animation_reader.hpp"
#include "scene/scene_readers.hpp"

namespace pita::scene::detail {

template <class LayerType>
void read_scene_tail(const JsonReader& reader, const Json& document, Scene& scene, bool moving) {
  if (const Json* golden = JsonReader::member(document, "golden")) read_golden(reader, *golden, scene.golden);
  if (const Json* claims = JsonReader::member(document, "claims")) {
    scene.claims = read_claims<LayerType>(reader, *claims, scene);
  }
  if (const Json* lint = JsonReader::member(document, "lint")) scene.lint = read_lint(reader, *lint);
  if (const Json* animation = JsonReader::member(document, "animation")) {
    scene.animation = read_animation<LayerType>(reader, *animation, "/animation", moving);
    scene.has_animation = true;
  } else {
    scene.animation = default_animation(moving);
  }
}

template void read_scene_tail<Layer>(const JsonReader&, const Json&, Scene&, bool);
template void read_scene_tail<PoseLayer>(const JsonReader&, const Json&, Scene&, bool);

}  // namespace pita::scene::detail
