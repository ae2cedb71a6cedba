// Bytes -> an edit of `pita serve --edit` (POST /api/edit/N): the first byte
// chooses one of four scene files (keyframe arrows, panels with keyframes
// of their own, poses of the plane, poses of space), the rest is the request's body. The
// body is read as the server reads it (JSON; "drag": {"panel", "pointer",
// "part", "to", "version"} or "changes": [{"pointer", "value"} or {"pointer",
// "remove": true}], "Save view"'s camera members among them) and applied
// with the functions the server calls (serve/scene_edit.hpp, serve/json_edit.hpp):
// drag for a drag, check_change for each change, then value_span and
// replace_value (set_value and remove_member for the camera); the result is read as a scene and its figure built, as
// the server does before it writes anything. Refusals are the server's 400s (nlohmann's exceptions,
// std::invalid_argument) and the scene's own errors (scene::LocatedError: SceneError, motion::NoMotion, RenderError);
// nothing else may escape. A change that is applied must leave every other byte of the file as it was, and read back as
// the value written.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fuzz_support.hpp"
#include "motion/stage.hpp"
#include "render/figure.hpp"
#include "render/panel_drawing.hpp"
#include "scene/scene.hpp"
#include "serve/camera_edit.hpp"
#include "serve/json_edit.hpp"
#include "serve/scene_edit.hpp"

namespace {

using namespace pita;
using Json = nlohmann::json;

const char* const kScenes[] = {
    R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
  {"t": 1, "p": [4, 1], "m": 2, "w": 1}, {"t": 2, "p": [8, 0], "q": [9, 1]}]})",
    R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
  {"t": 1, "p": [4, 1], "m": 2, "w": 1}, {"t": 2, "p": [8, 0], "m": 1, "w": 3}],
  "panels": [{"title": "own", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
    {"t": 1, "p": [2, 2], "m": 1, "w": 0.5}, {"t": 2, "p": [4, 0], "m": 1, "w": 1, "turns": 1}]},
    {"title": "shared", "method": "P8"}]})",
    R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
  {"t": 1, "triangle": [[4, 0], [5, 0], [4, 1]]}]})",
    R"({"dimension": 3, "method": "polySAM", "samples": 3,
  "poses": [{"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
            {"t": 1, "matrix": [[0, -1, 0, 2], [1, 0, 0, 0], [0, 0, 1, 1]]}],
  "camera": {"shadow": true}})",
};

// The edit as server.cpp's edit() applies it, without the file.
void edit(const std::string& text, const Json& request) {
  std::vector<serve::Change> changes;
  if (request.contains("drag")) {
    const Json& d = request.at("drag");
    const scene::Scene scene = scene::parse_scene(text, "edit.json");
    const motion::Stage stage(scene);
    const render::Figure figure = render::build_figure(stage);
    const Json& panel = d.at("panel");
    if (!panel.is_number_unsigned() || panel.get<std::uint64_t>() >= figure.placements.size()) return;  // a 400
    changes = serve::drag(text, scene, figure.placements, panel.get<std::size_t>(), d.at("pointer").get<std::string>(),
                          d.at("part").get<std::string>(),
                          Point{d.at("to").at(0).get<double>(), d.at("to").at(1).get<double>()});
  } else {
    for (const Json& change : request.at("changes")) {
      const bool remove = change.contains("remove") && change.at("remove").get<bool>();
      changes.push_back(
          {change.at("pointer").get<std::string>(), remove ? "" : change.at("value").get<std::string>(), remove});
      serve::check_change(text, changes.back());
    }
  }
  std::string edited = text;
  for (const serve::Change& change : changes) {
    if (change.remove) {
      edited = serve::remove_member(edited, change.pointer);
      continue;
    }
    if (serve::is_camera_pointer(change.pointer)) {
      // "Save view": set, or added where missing; its undo gives the text back byte for byte.
      const std::string before = edited;
      serve::Undo undo;
      edited = serve::set_value(edited, change.pointer, change.value, &undo);
      PITA_FUZZ_CHECK((undo.value ? serve::set_value(edited, undo.pointer, *undo.value)
                                  : serve::remove_member(edited, undo.pointer)) == before);
      const serve::TextSpan now = serve::value_span(edited, change.pointer);
      PITA_FUZZ_CHECK(Json::parse(edited.substr(now.begin, now.end - now.begin)) == Json::parse(change.value));
      continue;
    }
    const serve::TextSpan span = serve::value_span(edited, change.pointer);
    PITA_FUZZ_CHECK(span.begin <= span.end && span.end <= edited.size());
    const std::string before = edited;
    edited = serve::replace_value(edited, change.pointer, change.value);
    // Every other byte as it was, the value as written.
    PITA_FUZZ_CHECK(edited.compare(0, span.begin, before, 0, span.begin) == 0);
    PITA_FUZZ_CHECK(edited.size() - span.begin >= before.size() - span.end);
    PITA_FUZZ_CHECK(edited.compare(edited.size() - (before.size() - span.end), std::string::npos, before, span.end,
                                   std::string::npos) == 0);
    const serve::TextSpan now = serve::value_span(edited, change.pointer);
    PITA_FUZZ_CHECK(Json::parse(edited.substr(now.begin, now.end - now.begin)) == Json::parse(change.value));
  }
  const scene::Scene checked = scene::parse_scene(edited, "edit.json");
  const motion::Stage stage(checked);
  (void)render::build_figure(stage);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text = kScenes[data[0] % 4];
  const std::string_view body = fuzz::text_of(data + 1, size - 1);
  Json request;
  try {
    request = Json::parse(body);
  } catch (const Json::exception&) {
    return 0;  // "the request is not JSON"
  }
  try {
    edit(text, request);
  } catch (const Json::exception&) {
  } catch (const std::invalid_argument&) {
  } catch (const scene::LocatedError&) {  // SceneError, motion::NoMotion, RenderError: the file's own errors
  }
  return 0;
}
