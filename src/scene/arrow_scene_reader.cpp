// Arrow scenes: timed keyframes (the PITA paper; README "Scene format").
#include "scene/scene_readers.hpp"

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "scene/figure_reader.hpp"
#include "scene/timing_reader.hpp"

namespace pita::scene::detail {

namespace {
constexpr std::array<std::string_view, 13> kSceneFields = {
    "$schema", "description", "method", "keyframes", "chain",  "samples", "options",
    "title",   "canvas",      "layers", "panels",    "golden", "timing"};
}  // namespace

Scene read_arrow_scene(const JsonReader& reader, const Json& document) {
  reader.check_fields(document, "", kSceneFields);

  Scene scene;
  scene.path = reader.file();
  if (const Json* schema = JsonReader::member(document, "$schema")) reader.string(*schema, "/$schema");
  if (const Json* description = JsonReader::member(document, "description")) {
    scene.description = reader.string(*description, "/description");
  }

  const Json* method = JsonReader::member(document, "method");
  if (method == nullptr) reader.fail("/method", "missing required field (a method such as \"P6\")");
  scene.method = reader.method(*method, "/method");
  scene.method_name = std::string(info(scene.method).id);

  if (const Json* options = JsonReader::member(document, "options")) {
    scene.options = reader.options(*options, "/options", MethodOptions{});
  }

  const Json* keyframes = JsonReader::member(document, "keyframes");
  if (keyframes == nullptr) reader.fail("/keyframes", "missing required field (an array of keyframes)");
  scene.keyframes = reader.keyframes(*keyframes, "/keyframes", scene.method);
  if (const Json* chain = JsonReader::member(document, "chain")) {
    scene.chain = reader.chain(*chain, "/chain");
    reader.check_chain(scene.method, scene.chain, scene.keyframes.size(), "/chain");
  }

  if (const Json* samples = JsonReader::member(document, "samples")) {
    scene.samples = reader.integer(*samples, "/samples", kMinSamples, kMaxSamples);
  }
  if (const Json* timing = JsonReader::member(document, "timing")) {
    scene.timing = detail::read_timing(reader, *timing, "/timing");
  }

  // The figure (README "Figures"); `pita eval` ignores it.
  if (const Json* title = JsonReader::member(document, "title")) {
    scene.title = reader.string(*title, "/title");
  }
  if (const Json* canvas = JsonReader::member(document, "canvas")) {
    scene.canvas = detail::read_canvas(reader, *canvas, "/canvas");
  }
  if (const Json* layers = JsonReader::member(document, "layers")) {
    scene.layers = detail::read_layers(reader, *layers, "/layers");
  } else {
    scene.layers = {PatternLayer{}, KeyframesLayer{}};
  }
  if (const Json* panels = JsonReader::member(document, "panels")) {
    scene.panels = read_panels(reader, *panels, "/panels", scene);
  } else {
    scene.panels = {scene_panel(scene, "")};
  }
  if (const Json* golden = JsonReader::member(document, "golden")) read_golden(reader, *golden, scene.golden);
  return scene;
}

}  // namespace pita::scene::detail
