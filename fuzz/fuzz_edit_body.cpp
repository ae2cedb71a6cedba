// Bytes -> an edit of `pita serve --edit` (POST /api/edit/N): the first byte
// chooses one of four scene files (keyframe arrows, panels with keyframes of
// their own, poses of the plane, poses of space), the rest is the request's
// body. The body is read as the server reads it (JSON; "drag": {"panel",
// "pointer", "part", "to", "version"}[, "views"], "time": {"pointer", "t",
// "step"}, or "changes": [{"pointer", "value"} or {"pointer", "remove":
// true}], "Save view"'s camera members among them) and made with the
// functions the server calls (serve/edit_request.hpp: request_changes, then
// apply_changes); the result is read as a scene and its figure built, as the
// server does before it writes anything. Refusals are the server's 400s
// (nlohmann's exceptions, std::invalid_argument) and the scene's own errors
// (scene::LocatedError: SceneError, motion::NoMotion, RenderError); nothing
// else may escape. A value written reads back as written, and the changes the
// edit answers (its undo) give the file back byte for byte.
#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fuzz_support.hpp"
#include "motion/stage.hpp"
#include "render/figure.hpp"
#include "render/panel_drawing.hpp"
#include "scene/scene.hpp"
#include "serve/edit_request.hpp"
#include "serve/json_edit.hpp"

namespace {

using namespace pita;
using Json = nlohmann::ordered_json;

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

// The edit as the server makes it (serve/edit_request.hpp: the changes a
// request asks, made in the text), without the file. Each value written reads
// back as written, and the changes it answers give the text back byte for
// byte (undo); the result is read and drawn as the server does before writing.
void edit(const std::string& text, const Json& request) {
  const scene::Scene scene = scene::parse_scene(text, "edit.json");
  const std::vector<serve::Change> changes = serve::request_changes(text, scene, request);
  const serve::Applied applied = serve::apply_changes(text, changes);
  std::set<std::string> pointers;
  for (const serve::Change& change : changes) pointers.insert(change.pointer);
  if (pointers.size() == changes.size()) {  // a pointer changed twice holds its last value only
    for (const serve::Change& change : changes) {
      if (change.remove) continue;
      const serve::TextSpan now = serve::value_span(applied.text, change.pointer);
      PITA_FUZZ_CHECK(Json::parse(applied.text.substr(now.begin, now.end - now.begin)) == Json::parse(change.value));
    }
  }
  std::vector<serve::Change> back;
  for (const auto& undo : applied.previous) {
    const bool remove = undo.contains("remove");
    back.push_back({undo.at("pointer").get<std::string>(), remove ? "" : undo.at("value").get<std::string>(), remove});
  }
  PITA_FUZZ_CHECK(serve::apply_changes(applied.text, back).text == text);
  const scene::Scene checked = scene::parse_scene(applied.text, "edit.json");
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
