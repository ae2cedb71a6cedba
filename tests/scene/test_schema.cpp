// The published schema (schema/scene.schema.json, JSON Schema draft 7) against
// the parser (src/scene/), with an independent validator, Python's jsonschema (tests
// only: pita itself never reads the schema):
//  - every starter scene in scenes/ is valid;
//  - every bad scene of the corpus below is refused by both, and the parser
//    names the JSON Pointer of the bad value;
//  - good scenes that use every field are accepted by both.
// A few checks are the parser's alone, since a schema cannot express them
// (strictly increasing knots, the number of keyframes a panel's method takes
// with the scene's keyframes, method names, range and view ends in order):
// ParserOnlyChecks lists them, and checks that the schema lets them through.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "core/pitas/method_options.hpp"
#include "scene/color.hpp"
#include "scene/measure_name.hpp"
#include "scene/scene.hpp"
#include "scene_test_support.hpp"

namespace pita::scene {
namespace {

using test::p6_with;
using test::p6_with_middle;

using test::kSourceDir;
using test::read_json;

struct SchemaVerdict {
  bool valid = true;
  std::string errors;                 // one line per error: "POINTER: description"
  std::vector<std::string> pointers;  // where each error is
};

// The independent validator (Python's jsonschema, Draft 7:
// tests/scene/validate_schema.py), one process for the whole test run: a
// document per line in, a verdict per line out.
class Validator {
 public:
  Validator() {
    int to_child[2], from_child[2];
    if (::pipe(to_child) != 0 || ::pipe(from_child) != 0) throw std::runtime_error("pipe failed");
    const pid_t child = ::fork();
    if (child < 0) throw std::runtime_error("fork failed");
    if (child == 0) {
      ::dup2(to_child[0], 0);
      ::dup2(from_child[1], 1);
      ::close(to_child[1]);
      ::close(from_child[0]);
      const std::string script = (kSourceDir / "tests/scene/validate_schema.py").string();
      const std::string schema = (kSourceDir / "schema/scene.schema.json").string();
      ::execl(PITA_PYTHON, PITA_PYTHON, script.c_str(), schema.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(to_child[0]);
    ::close(from_child[1]);
    in_ = ::fdopen(to_child[1], "w");
    out_ = ::fdopen(from_child[0], "r");
  }
  // A verdict, or nullopt when the validator does not answer.
  std::optional<nlohmann::json> ask(const nlohmann::json& document) {
    const std::string line = document.dump() + "\n";
    if (std::fwrite(line.data(), 1, line.size(), in_) != line.size() || std::fflush(in_) != 0) return std::nullopt;
    std::string answer;
    int c = 0;
    while ((c = std::fgetc(out_)) != EOF && c != '\n') answer += static_cast<char>(c);
    nlohmann::json verdict = nlohmann::json::parse(answer, nullptr, false);
    if (!verdict.is_object()) return std::nullopt;
    return verdict;
  }

 private:
  FILE* in_ = nullptr;
  FILE* out_ = nullptr;
};

// What the validator finds wrong with `document`.
SchemaVerdict validate(const nlohmann::json& document) {
  static Validator validator;  // left running; it ends with the test process's pipe
  SchemaVerdict verdict;
  const std::optional<nlohmann::json> answer = validator.ask(document);
  if (!answer) {
    ADD_FAILURE() << "the schema validator did not answer (is python3-jsonschema installed? scripts/test.sh "
                     "installs it)";
    return {false, "no verdict", {}};
  }
  verdict.valid = answer->at("valid").get<bool>();
  for (const nlohmann::json& error : answer->at("errors")) {
    verdict.pointers.push_back(error.at("pointer").get<std::string>());
    verdict.errors += verdict.pointers.back() + ": " + error.at("message").get<std::string>() + "\n";
  }
  return verdict;
}

// "" when the schema accepts `document`, else its errors.
std::string schema_errors(const nlohmann::json& document) {
  const SchemaVerdict verdict = validate(document);
  return verdict.valid ? "" : (verdict.errors.empty() ? "invalid" : verdict.errors);
}

// The pointer of the SceneError that parsing `text` throws, or "(no error)".
std::string error_pointer(const std::string& text) {
  try {
    parse_scene(text, "s.json");
  } catch (const SceneError& error) {
    return error.pointer();
  }
  return "(no error)";
}

std::string error_message(const std::string& text) {
  try {
    parse_scene(text, "s.json");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "(no error)";
}

// A P6 scene whose only layer is `layer` (JSON text).
std::string with_layer(const std::string& layer) { return p6_with(R"(, "layers": [)" + layer + "]"); }

// Keyframes for panels: three, the middle one `middle`.
std::string three_keyframes(const std::string& middle) {
  return R"([{"t": 0, "p": [0, 0], "m": 1, "w": 0}, )" + middle + R"(, {"t": 1, "p": [2, 0], "m": 1, "w": 0}])";
}

// A valid SAM scene (two poses) with `extra` top-level members.
std::string sam_with(const std::string& extra) {
  return R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
    {"t": 1, "matrix": [[0, -2, 3], [2, 0, 1]]}])" +
         extra + "}";
}

// A P6 scene whose middle keyframe moves, with `extra` top-level members.
std::string moving_with(const std::string& extra) {
  return R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
    {"t": 0.5, "from": {"p": [1, 1], "m": 1, "w": 0}, "to": {"p": [1, -1], "m": 2, "w": 1}},
    {"t": 1, "p": [2, 0], "m": 1, "w": 0}])" +
         extra + "}";
}

// A P6 scene with one shape, `shape` (JSON text).
std::string with_shape(const std::string& shape) { return p6_with(R"(, "shapes": [)" + shape + "]"); }

// A P6 scene with "animation": `animation` (JSON text).
std::string with_animation(const std::string& animation) { return p6_with(R"(, "animation": )" + animation); }

const std::string kFourPoints =
    R"([{"t": 0, "p": [0, 0]}, {"t": 1, "p": [1, 1]}, {"t": 2, "p": [2, 0]}, {"t": 3, "p": [3, 1]}])";

struct BadScene {
  std::string what;     // the class of mistake
  std::string text;     // the scene
  std::string pointer;  // where the parser must say it is wrong
};

std::string many(const std::string& item, int count) {
  std::string text;
  for (int i = 0; i < count; ++i) text += (i > 0 ? ", " : "") + item;
  return text;
}

const std::vector<BadScene>& bad_scenes() {
  static const std::vector<BadScene> corpus = {
      // Keyframe tracks.
      {"unknown chain", p6_with(R"(, "chain": "cubic")"), "/chain"},
      {"blend chain on the SMA",
       R"({"method": "SMA", "chain": "blend", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
        {"t": 1, "p": [1, 0], "m": 1, "w": 0}, {"t": 2, "p": [2, 0], "m": 1, "w": 0}]})",
       "/chain"},
      // Pose scenes (SAM paper).
      {"unknown pose scene field", sam_with(R"(, "keyframe": [])"), "/keyframe"},
      {"pose matrix 3x3", R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]},
        {"t": 1, "matrix": [[1, 0, 0], [0, 1, 0]]}]})",
       "/poses/0/matrix"},
      {"pose without time", R"({"method": "SAM", "poses": [{"matrix": [[1, 0, 0], [0, 1, 0]]},
        {"t": 1, "matrix": [[1, 0, 0], [0, 1, 0]]}]})",
       "/poses/0/t"},
      {"unknown pose field", R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]], "turns": 1},
        {"t": 1, "matrix": [[1, 0, 0], [0, 1, 0]]}]})",
       "/poses/0/turns"},
      {"one pose", R"({"method": "polySAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}]})", "/poses"},
      {"unknown shape outline", sam_with(R"(, "shapes": [{"outline": "G"}])"), "/shapes/0/outline"},
      {"arrow layer in a pose scene", sam_with(R"(, "layers": [{"type": "pattern"}])"), "/layers/0/type"},
      {"unknown shapes layer field", sam_with(R"(, "layers": [{"type": "shapes", "colour": "red"}])"),
       "/layers/0/colour"},
      {"existence rows too many", sam_with(R"(, "layers": [{"type": "existence", "rows": 5000}])"), "/layers/0/rows"},
      {"3D existence steps too many", sam_with(R"(, "layers": [{"type": "sam3d-existence", "steps": 721}])"),
       "/layers/0/steps"},
      {"3D existence step too fine", sam_with(R"(, "layers": [{"type": "sam3d-existence", "step": 0.0001}])"),
       "/layers/0/step"},
      {"3D existence paper not a line", sam_with(R"(, "layers": [{"type": "sam3d-existence", "paper": "yes"}])"),
       "/layers/0/paper"},
      {"unknown pose panel field", sam_with(R"(, "panels": [{"keyframes": []}])"), "/panels/0/keyframes"},
      // Unknown fields, at every level.
      {"unknown top-level field", p6_with(R"(, "titel": "x")"), "/titel"},
      {"unknown canvas field", p6_with(R"(, "canvas": {"widht": 100})"), "/canvas/widht"},
      {"unknown view field", p6_with(R"(, "canvas": {"view": {"min": [0, 0], "max": [1, 1], "mid": [0, 0]}})"),
       "/canvas/view/mid"},
      {"unknown layer field", with_layer(R"({"type": "pattern", "colour": "red"})"), "/layers/0/colour"},
      {"field of another layer type", with_layer(R"({"type": "pattern", "text": "hi"})"), "/layers/0/text"},
      {"field of another layer type (legend)", with_layer(R"({"type": "legend", "color": "red"})"), "/layers/0/color"},
      {"unknown outline field", with_layer(R"({"type": "stroke", "outline": {"colour": "red"}})"),
       "/layers/0/outline/colour"},
      {"unknown panel field", p6_with(R"(, "panels": [{"methd": "P2"}])"), "/panels/0/methd"},
      {"unknown panel option", p6_with(R"(, "panels": [{"options": {"anchr": "start"}}])"), "/panels/0/options/anchr"},
      {"unknown panel keyframe field",
       p6_with(R"(, "panels": [{"keyframes": )" +
               three_keyframes(R"({"t": 0.5, "p": [1, 1], "m": 1, "w": 0, "x": 1})") + "}]"),
       "/panels/0/keyframes/1/x"},
      {"unknown field in a panel's layer",
       p6_with(R"(, "panels": ["P1", {"layers": [{"type": "label", "text": "a", "at": [0, 0], "font": "Sans"}]}])"),
       "/panels/1/layers/0/font"},
      // Wrong types.
      {"title not a string", p6_with(R"(, "title": 3)"), "/title"},
      {"canvas not an object", p6_with(R"(, "canvas": [])"), "/canvas"},
      {"canvas width not an integer", p6_with(R"(, "canvas": {"width": 800.5})"), "/canvas/width"},
      {"layers not an array", p6_with(R"(, "layers": {"type": "pattern"})"), "/layers"},
      {"layer not an object", with_layer(R"("pattern")"), "/layers/0"},
      {"boolean field not a boolean", with_layer(R"({"type": "keyframes", "winding": "yes"})"), "/layers/0/winding"},
      {"outline not an object", with_layer(R"({"type": "stroke", "outline": "black"})"), "/layers/0/outline"},
      {"color not a string", with_layer(R"({"type": "stroke", "fill": 3})"), "/layers/0/fill"},
      {"discrepancy method not a string", with_layer(R"({"type": "discrepancy", "method": 6})"), "/layers/0/method"},
      {"panels not an array", p6_with(R"(, "panels": "P2")"), "/panels"},
      {"panel neither a string nor an object", p6_with(R"(, "panels": [3])"), "/panels/0"},
      {"panel title not a string", p6_with(R"(, "panels": [{"title": 3}])"), "/panels/0/title"},
      {"range not a pair", with_layer(R"({"type": "pattern", "range": [0, 0.5, 1]})"), "/layers/0/range"},
      {"label point not a pair", with_layer(R"({"type": "label", "text": "A", "at": [1]})"), "/layers/0/at"},
      // Bounds.
      {"canvas width too small", p6_with(R"(, "canvas": {"width": 15})"), "/canvas/width"},
      {"canvas height too large", p6_with(R"(, "canvas": {"height": 8193})"), "/canvas/height"},
      {"margin too large", p6_with(R"(, "canvas": {"margin": 0.5})"), "/canvas/margin"},
      {"columns zero", p6_with(R"(, "canvas": {"columns": 0})"), "/canvas/columns"},
      {"columns too many", p6_with(R"(, "canvas": {"columns": 65})"), "/canvas/columns"},
      {"empty font", p6_with(R"(, "canvas": {"font": ""})"), "/canvas/font"},
      {"too many layers", p6_with(R"(, "layers": [)" + many(R"({"type": "legend"})", 65) + "]"), "/layers"},
      {"line width zero", with_layer(R"({"type": "pattern", "width": 0})"), "/layers/0/width"},
      {"line width too large", with_layer(R"({"type": "trajectory", "width": 101})"), "/layers/0/width"},
      {"opacity above 1", with_layer(R"({"type": "stroke", "opacity": 1.5})"), "/layers/0/opacity"},
      {"opacity below 0", with_layer(R"({"type": "pattern", "opacity": -0.1})"), "/layers/0/opacity"},
      {"dash length not positive", with_layer(R"({"type": "pattern", "dash": [4, 0]})"), "/layers/0/dash/1"},
      {"dash too long", with_layer(R"({"type": "pattern", "dash": [)" + many("1", 17) + "]}"), "/layers/0/dash"},
      {"pattern samples too few", with_layer(R"({"type": "pattern", "samples": 1})"), "/layers/0/samples"},
      {"pattern samples too many", with_layer(R"({"type": "stroke", "samples": 10001})"), "/layers/0/samples"},
      {"trajectory samples too many", with_layer(R"({"type": "trajectory", "samples": 100001})"), "/layers/0/samples"},
      {"keyframe colors empty", with_layer(R"({"type": "keyframes", "colors": []})"), "/layers/0/colors"},
      {"keyframe colors too many", with_layer(R"({"type": "keyframes", "colors": [)" + many(R"("red")", 17) + "]}"),
       "/layers/0/colors"},
      {"banner padding too large", with_layer(R"({"type": "banner", "text": "A", "padding": 0.46})"),
       "/layers/0/padding"},
      {"discrepancy scale zero", with_layer(R"({"type": "discrepancy", "scale": 0})"), "/layers/0/scale"},
      {"label size zero", with_layer(R"({"type": "label", "text": "A", "at": [0, 0], "size": 0})"), "/layers/0/size"},
      {"legend size too large", with_layer(R"({"type": "legend", "size": 201})"), "/layers/0/size"},
      {"no panels", p6_with(R"(, "panels": [])"), "/panels"},
      {"too many panels", p6_with(R"(, "panels": [)" + many(R"("P1")", 65) + "]"), "/panels"},
      {"panel samples too many", p6_with(R"(, "panels": [{"samples": 10001}])"), "/panels/0/samples"},
      {"panel keyframe magnitude not positive",
       p6_with(R"(, "panels": [{"keyframes": )" + three_keyframes(R"({"t": 0.5, "p": [1, 1], "m": -1, "w": 0})") +
               "}]"),
       "/panels/0/keyframes/1/m"},
      {"panel SMA given a blend chain",
       p6_with(R"(, "panels": [{"method": "SMA", "chain": "blend", "keyframes": )" +
               three_keyframes(R"({"t": 0.5, "p": [1, 1], "m": 1, "w": 0})") + "}]"),
       "/panels/0/chain"},
      // Colors.
      {"hex color of 5 digits", p6_with(R"(, "canvas": {"background": "#12345"})"), "/canvas/background"},
      {"hex color with a non-hex digit", with_layer(R"({"type": "keyframes", "colors": ["red", "#ggg"]})"),
       "/layers/0/colors/1"},
      {"unknown color name", with_layer(R"({"type": "label", "text": "A", "at": [0, 0], "color": "rde"})"),
       "/layers/0/color"},
      {"color name in capitals", with_layer(R"({"type": "pattern", "color": "Red"})"), "/layers/0/color"},
      // Choices.
      {"y axis", p6_with(R"(, "canvas": {"y_axis": "sideways"})"), "/canvas/y_axis"},
      {"view", p6_with(R"(, "canvas": {"view": "fit"})"), "/canvas/view"},
      {"view box without min", p6_with(R"(, "canvas": {"view": {"max": [1, 1]}})"), "/canvas/view/min"},
      {"layer without type", with_layer(R"({"color": "red"})"), "/layers/0/type"},
      {"unknown layer type", with_layer(R"({"type": "patern"})"), "/layers/0/type"},
      {"trajectory point", with_layer(R"({"type": "trajectory", "point": "start"})"), "/layers/0/point"},
      {"spiral center", with_layer(R"({"type": "keyframes", "spiral_center": "middle"})"), "/layers/0/spiral_center"},
      {"predictor", with_layer(R"({"type": "discrepancy", "predictor": "next"})"), "/layers/0/predictor"},
      {"legend corner", with_layer(R"({"type": "legend", "corner": "top"})"), "/layers/0/corner"},
      // Required text.
      {"banner without text", with_layer(R"({"type": "banner"})"), "/layers/0/text"},
      {"banner with empty text", with_layer(R"({"type": "banner", "text": ""})"), "/layers/0/text"},
      {"banner text too long",
       with_layer(R"({"type": "banner", "text": ")" + std::string(kMaxTextLength + 1, 'x') + "\"}"), "/layers/0/text"},
      {"label without point", with_layer(R"({"type": "label", "text": "A"})"), "/layers/0/at"},
      // Moving keyframes {"t", "from", "to"} (PITA Sec. 7.4).
      {"moving keyframe without \"to\"", p6_with_middle(R"({"t": 0.5, "from": {"p": [1, 1], "m": 1, "w": 0}})"),
       "/keyframes/1/to"},
      {"moving keyframe without \"from\"", p6_with_middle(R"({"t": 0.5, "to": {"p": [1, 1], "m": 1, "w": 0}})"),
       "/keyframes/1/from"},
      {"moving keyframe with \"p\"",
       p6_with_middle(
           R"({"t": 0.5, "p": [1, 1], "from": {"p": [1, 1], "m": 1, "w": 0}, "to": {"p": [1, 1], "m": 1, "w": 0}})"),
       "/keyframes/1/p"},
      {"moving keyframe's \"from\" not an object",
       p6_with_middle(R"({"t": 0.5, "from": [1, 1], "to": {"p": [1, 1], "m": 1, "w": 0}})"), "/keyframes/1/from"},
      {"moving keyframe's \"to\" with a knot",
       p6_with_middle(
           R"({"t": 0.5, "from": {"p": [1, 1], "m": 1, "w": 0}, "to": {"t": 1, "p": [1, 1], "m": 1, "w": 0}})"),
       "/keyframes/1/to/t"},
      {"panel moving keyframe without \"to\"",
       p6_with(R"(, "panels": [{"keyframes": )" +
               three_keyframes(R"({"t": 0.5, "from": {"p": [1, 1], "m": 1, "w": 0}})") + "}]"),
       "/panels/0/keyframes/1/to"},
      // Handles (Sec. 7.1).
      {"handle not an object", p6_with(R"(, "handle": [[0, 0], [1, 0]])"), "/handle"},
      {"handle magnitude zero", p6_with(R"(, "handle": {"p": [0, 0], "m": 0, "w": 0})"), "/handle/m"},
      {"handle with a knot", p6_with(R"(, "handle": {"t": 0, "p": [0, 0], "q": [1, 0]})"), "/handle/t"},
      {"handle without its start", p6_with(R"(, "handle": {"q": [1, 0]})"), "/handle/p"},
      {"handle with points",
       R"({"method": "P6", "points": )" + kFourPoints + R"(, "handle": {"p": [0, 0], "q": [1, 0]}})", "/handle"},
      {"panel handle magnitude negative", p6_with(R"(, "panels": [{"handle": {"p": [0, 0], "m": -1, "w": 0}}])"),
       "/panels/0/handle/m"},
      {"panel handle with points",
       p6_with(R"(, "panels": [{"points": )" + kFourPoints + R"(, "handle": {"p": [0, 0], "q": [1, 0]}}])"),
       "/panels/0/handle"},
      {"unknown handle layer field", with_layer(R"({"type": "handle", "colour": "red"})"), "/layers/0/colour"},
      {"handle layer shapes not a boolean", with_layer(R"({"type": "handle", "shapes": "yes"})"), "/layers/0/shapes"},
      {"field of a shapes layer in a handle layer", with_layer(R"({"type": "handle", "fill": "red"})"),
       "/layers/0/fill"},
      {"handle layer in a pose scene", sam_with(R"(, "layers": [{"type": "handle"}])"), "/layers/0/type"},
      // Shapes and images.
      {"no shapes", p6_with(R"(, "shapes": [])"), "/shapes"},
      {"unknown shape kind", with_shape(R"({"circle": [0, 0]})"), "/shapes/0/circle"},
      {"empty image path", with_shape(R"({"image": "", "box": [[0, 0], [1, 1]]})"), "/shapes/0/image"},
      {"image path not a string", with_shape(R"({"image": 3, "box": [[0, 0], [1, 1]]})"), "/shapes/0/image"},
      {"box without image", with_shape(R"({"box": [[0, 0], [1, 1]]})"), "/shapes/0/box"},
      {"box beside a polygon", with_shape(R"({"polygon": [[0, 0], [1, 0]], "box": [[0, 0], [1, 1]]})"),
       "/shapes/0/box"},
      {"image and polygon", with_shape(R"({"polygon": [[0, 0], [1, 0]], "image": "", "box": [[0, 0], [1, 1]]})"),
       "/shapes/0/image"},
      // Animation.
      {"animation not an object", with_animation("true"), "/animation"},
      {"unknown animation field", with_animation(R"({"duration": 2, "speed": 2})"), "/animation/speed"},
      {"fps zero", with_animation(R"({"fps": 0})"), "/animation/fps"},
      {"fps above 240", with_animation(R"({"fps": 300})"), "/animation/fps"},
      {"duration zero", with_animation(R"({"duration": 0})"), "/animation/duration"},
      {"duration negative", with_animation(R"({"duration": -2})"), "/animation/duration"},
      {"frames one", with_animation(R"({"frames": 1})"), "/animation/frames"},
      {"frames too many", with_animation(R"({"frames": 100001})"), "/animation/frames"},
      {"frames not an integer", with_animation(R"({"frames": 2.5})"), "/animation/frames"},
      {"loop not a boolean", with_animation(R"({"loop": "yes"})"), "/animation/loop"},
      {"unknown what", with_animation(R"({"what": "motions"})"), "/animation/what"},
      {"trail negative", with_animation(R"({"trail": -1})"), "/animation/trail"},
      {"trail too long", with_animation(R"({"trail": 101})"), "/animation/trail"},
      {"overlay value above 1", moving_with(R"(, "animation": {"overlay": [0, 1.5]})"), "/animation/overlay/1"},
      {"overlay empty", moving_with(R"(, "animation": {"overlay": []})"), "/animation/overlay"},
      {"pattern animation of a pose scene", sam_with(R"(, "animation": {"what": "pattern"})"), "/animation/what"},
      {"overlay in a pose scene", sam_with(R"(, "animation": {"overlay": [0.5]})"), "/animation/overlay"},
      {"claim without words", p6_with(R"(, "claims": [{"measure": "turning", "below": 1}])"), "/claims/0"},
      {"lint: unknown check", p6_with(R"(, "lint": {"allow": [{"check": "overlap", "reason": "r"}]})"),
       "/lint/allow/0/check"},
      {"lint: no reason", p6_with(R"(, "lint": {"allow": [{"check": "outside"}]})"), "/lint/allow/0"},
      {"lint: a share above 1", p6_with(R"(, "lint": {"min_content_share": 2})"), "/lint/min_content_share"},
      {"claim without a test", p6_with(R"(, "claims": [{"says": "x", "measure": "turning"}])"), "/claims/0"},
      {"claim with an unknown measure", p6_with(R"(, "claims": [{"says": "x", "measure": "twist", "below": 1}])"),
       "/claims/0/measure"},
      {"claim bound with an unknown field",
       p6_with(R"(, "claims": [{"says": "x", "measure": "turning", "below": {"factor": 2}}])"),
       "/claims/0/below/factor"},
      {"shapes layer times not a list", with_layer(R"({"type": "shapes", "times": 0.5})"), "/layers/0/times"},
  };
  return corpus;
}

// Mistakes that only the parser sees: the schema lets them through. (Poses
// between which no SAM exists are refused by the motion stage, not the parser:
// tests/data/bad/poses-*no-sam*.json.)
const std::vector<BadScene>& parser_only_scenes() {
  static const std::vector<BadScene> corpus = {
      {"singular pose", R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
        {"t": 1, "matrix": [[1, 2, 0], [2, 4, 0]]}]})",
       "/poses/1/matrix"},
      {"pose times not increasing", R"({"method": "SAM", "poses": [{"t": 1, "matrix": [[1, 0, 0], [0, 1, 0]]},
        {"t": 1, "matrix": [[1, 0, 0], [0, 1, 0]]}]})",
       "/poses/1/t"},
      {"range ends out of order", with_layer(R"({"type": "pattern", "range": [1, 0.5]})"), "/layers/0/range/1"},
      {"view min not below max", p6_with(R"(, "canvas": {"view": {"min": [0, 0], "max": [1, 0]}})"),
       "/canvas/view/max/1"},
      {"panel method that the scene's chain cannot extend", p6_with(R"(, "chain": "blend", "panels": ["SMA"])"),
       "/panels/0"},
      {"panel object method that the scene's chain cannot extend",
       p6_with(R"(, "chain": "blend", "panels": [{"method": "SMA", "title": "steady"}])"), "/panels/0/method"},
      {"panel keyframes fewer than the scene's method takes",
       p6_with(R"(, "panels": [{"keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
         {"t": 1, "p": [1, 0], "m": 1, "w": 0}]}])"),
       "/panels/0/keyframes"},
      {"neville chain over more keyframes than it takes",
       R"({"method": "P6", "chain": "neville", "keyframes": [)" +
           [] {
             std::string keys;
             for (int i = 0; i < 65; ++i) {
               keys += (i > 0 ? ", " : "") + std::string(R"({"t": )") + std::to_string(i) +
                       R"(, "p": [0, 0], "m": 1, "w": 0})";
             }
             return keys;
           }() +
           "]}",
       "/chain"},
      {"panel knots not increasing",
       p6_with(R"(, "panels": [{"keyframes": )" + three_keyframes(R"({"t": 1, "p": [1, 1], "m": 1, "w": 0})") + "}]"),
       "/panels/0/keyframes/2/t"},
      {"unknown panel method", p6_with(R"(, "panels": ["P66"])"), "/panels/0"},
      {"unknown discrepancy method", with_layer(R"({"type": "discrepancy", "method": "P66"})"), "/layers/0/method"},
      {"handle of zero length", p6_with(R"(, "handle": {"p": [1, 1], "q": [1, 1]})"), "/handle/q"},
      {"moving keyframe's target of zero length",
       p6_with_middle(R"({"t": 0.5, "from": {"p": [1, 1], "m": 1, "w": 0}, "to": {"p": [1, 1], "q": [1, 1]}})"),
       "/keyframes/1/to/q"},
      {"image file that does not exist", with_shape(R"({"image": "no-such-image.png", "box": [[0, 0], [1, 1]]})"),
       "/shapes/0/image"},
      {"absolute image path", with_shape(R"({"image": "/etc/passwd", "box": [[0, 0], [1, 1]]})"), "/shapes/0/image"},
      {"image path out of the scene's folder",
       with_shape(R"({"image": "../scenes/images/picture.png", "box": [[0, 0], [1, 1]]})"), "/shapes/0/image"},
      {"shapes layer in a scene without shapes", with_layer(R"({"type": "shapes"})"), "/layers/0/type"},
      {"pattern animation without moving keyframes", with_animation(R"({"what": "pattern"})"), "/animation/what"},
      {"overlay without moving keyframes", with_animation(R"({"overlay": [0, 1]})"), "/animation/overlay"},
      {"duration x fps under 2 frames", with_animation(R"({"duration": 0.01, "fps": 30})"), "/animation/duration"},
  };
  return corpus;
}

TEST(SceneSchemaValidation, EveryStarterSceneIsValid) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kSourceDir / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    EXPECT_EQ(schema_errors(read_json(entry.path())), "");
    ++count;
  }
  EXPECT_GT(count, 0);
}

TEST(SceneSchemaValidation, CorpusCoversEnoughMistakes) { EXPECT_GE(bad_scenes().size(), 25U); }

TEST(SceneSchemaValidation, BadScenesAreRefusedByBoth) {
  for (const BadScene& bad : bad_scenes()) {
    SCOPED_TRACE(bad.what + ": " + bad.text.substr(0, 300));
    const SchemaVerdict verdict = validate(nlohmann::json::parse(bad.text));
    EXPECT_FALSE(verdict.valid) << "the schema accepts it";
    // The schema refuses it for the same mistake: each of its errors is at the
    // bad value or at an object or array that holds it.
    for (const std::string& at : verdict.pointers) {
      const bool holds =
          bad.pointer.rfind(at, 0) == 0 && (at.size() == bad.pointer.size() || bad.pointer[at.size()] == '/');
      EXPECT_TRUE(holds) << "schema error at " << at << ":\n" << verdict.errors;
    }
    EXPECT_EQ(error_pointer(bad.text), bad.pointer) << error_message(bad.text);
  }
}

TEST(SceneSchemaValidation, ParserOnlyChecks) {
  for (const BadScene& bad : parser_only_scenes()) {
    SCOPED_TRACE(bad.what);
    EXPECT_EQ(schema_errors(nlohmann::json::parse(bad.text)), "");
    EXPECT_EQ(error_pointer(bad.text), bad.pointer) << error_message(bad.text);
  }
}

// Good scenes that use every field, each accepted by both.
const std::vector<std::string>& good_scenes() {
  static const std::vector<std::string> scenes = {
      R"({
        "$schema": "../schema/scene.schema.json",
        "description": "every field",
        "title": "Every field",
        "method": "P6",
        "options": {"anchor": "midpoint", "path_mean": "arithmetic", "magnitude_mean": "harmonic"},
        "keyframes": [
          {"t": 0, "p": [0, 0], "m": 1, "w": 0.4},
          {"t": 0.5, "p": [3, 1.5], "q": [3.5, 2]},
          {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5, "turns": 1}
        ],
        "samples": 9,
        "canvas": {"width": 1200, "height": 400, "background": "#F8F8F0", "view": {"min": [-1, -2], "max": [7, 3]},
                   "margin": 0.1, "y_axis": "down", "columns": 3, "font": "DejaVu Sans"},
        "layers": [
          {"type": "stroke", "fill": "#4066a680", "opacity": 0.5,
           "outline": {"color": "black", "width": 0.5, "opacity": 0.8, "dash": [2, 1]}, "samples": 40, "range": [0, 1]},
          {"type": "banner", "text": "PITA", "font": "Serif Bold", "fill": "white", "opacity": 0.9,
           "outline": {"color": "grey"}, "padding": 0.2, "samples": 30, "range": [0.1, 0.9]},
          {"type": "pattern", "color": "gray", "width": 0.5, "opacity": 0.7, "dash": [], "extended": true,
           "samples": 25, "range": [-0.5, 1.5]},
          {"type": "trajectory", "point": "mid", "samples": 1000, "range": [0, 1], "color": "orange",
           "width": 1.5, "opacity": 1, "dash": [4, 2]},
          {"type": "discrepancy", "predictor": "pita", "method": "P1", "scale": 10, "color": "purple",
           "width": 1, "opacity": 0.5, "dash": [1, 1], "fill": "#ff000040", "samples": 20},
          {"type": "keyframes", "colors": ["red", "green", "blue", "#abc"], "width": 3, "opacity": 1,
           "winding": false, "spiral_center": "midpoint", "extended": true},
          {"type": "label", "text": "A", "at": [0, -0.5], "size": 14, "color": "brown"},
          {"type": "legend", "corner": "bottom-right", "size": 10},
          {"type": "plot", "box": {"min": [0, -2], "max": [1, -1]}, "point": "q", "samples": 50, "color": "blue",
           "width": 1, "opacity": 0.9, "dash": [], "marks": false}
        ],
        "timing": {"ease": "ease-in-out", "arc_length": "mid", "per": "span"},
        "panels": [
          "P1",
          "la-lp",
          {"method": "P2", "options": {"anchor": "start"}, "title": "", "samples": 33,
           "timing": {"ease": "cubic-bezier(0.1, -0.2, 0.7, 1.3) "}},
          {"method": "P3", "timing": {"ease": {"sine": {"k1": 0.2, "k2": 0.8}}}},
          {"method": "P4", "timing": {"ease": {"parabolic": {"t1": 0.1, "t2": 0.9}}, "per": "motion"}},
          {"keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [1, 0], "m": 1, "w": 1},
                         {"t": 2, "p": [2, 0], "m": 1, "w": 2}],
           "layers": [{"type": "trajectory", "point": "q"}]},
          {"method": "SMA", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [1, 0], "m": 2, "w": 1}]},
          "P2"
        ],
        "claims": [
          {"says": "P1 shrinks more than P6", "panel": 0, "measure": "scale-min", "below": {"panel": 1}},
          {"says": "P2 turns", "panel": 2, "measure": "angle:/panels/0@0.5", "absolute": true,
           "above": {"panel": 3, "measure": "turn-step", "times": 0.5, "plus": -0.1}},
          {"says": "no pop", "panel": 1, "measure": "pop", "is": false},
          {"says": "exact", "panel": 6, "measure": "gain:B.q", "near": 1, "within": 0.01}
        ]
      })",
      R"({
        "$schema": "../schema/scene.schema.json",
        "description": "every pose scene field",
        "title": "Every field",
        "method": "polySAM",
        "reference_triangle": [[0, 0], [2, 0], [0, 2]],
        "shapes": [{"outline": "F", "color": "cyan"}, {"triangle": "reference"}, {"polygon": [[0, 0], [1, 0], [1, 1]]},
                   {"polyline": [[0, 0], [1, 1]]}, {"outline": "house"}, {"outline": "square"}],
        "poses": [
          {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
          {"t": 0.5, "triangle": [[3, 0], [3, 2], [1, 0]]},
          {"t": 1, "matrix": [[0.5, -1, 6], [1, 0.5, 1]]}
        ],
        "samples": 5,
        "subdivisions": 2,
        "timing": {"ease": "sine", "arc_length": "p"},
        "canvas": {"width": 900, "height": 600, "view": "shared"},
        "layers": [
          {"type": "paths", "samples": 64, "range": [0, 1], "color": "gray", "width": 0.5, "opacity": 0.5, "dash": [2, 2]},
          {"type": "shapes", "color": "blue", "width": 1, "opacity": 1, "dash": [], "fill": "#88aaff", "fill_opacity": 0.2,
           "samples": 9, "range": [0, 1]},
          {"type": "velocities", "scale": 0.2, "color": "red", "width": 1, "opacity": 1, "dash": [1, 1], "samples": 5, "range": [0, 1]},
          {"type": "poses", "colors": ["green", "orange", "red"], "width": 2, "fill_opacity": 0.3},
          {"type": "label", "text": "F", "at": [0, -1], "size": 12, "color": "black"},
          {"type": "plot", "box": {"min": [0, -3], "max": [2, -2]}}
        ],
        "panels": [
          "linear",
          {"method": "polySAM", "timing": {"ease": "ease", "per": "span"}},
          {"method": "four-point-sam", "subdivisions": 3},
          {"method": "biarc-SAM", "title": "bi-arc", "samples": 9},
          {"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 2, "matrix": [[2, 0, 1], [0, 2, 1]]}],
           "shapes": [{"outline": "square"}]},
          {"title": "existence", "layers": [{"type": "existence", "columns": 20, "rows": 10, "fill": "red",
            "exists_fill": "none", "boundary": {"color": "black", "dash": [3, 3]}, "trapezoid": {"width": 1}}]}
        ],
        "golden": {"pixel_tolerance": 20},
        "claims": [
          {"says": "steady", "panel": 0, "measure": "ara", "below": 0.1},
          {"says": "no dip", "panel": 1, "measure": "area", "near": 0, "within": 1e-9}
        ]
      })",
      // Moving keyframes, a handle carrying shapes, the shapes and handle
      // layers, panel handles and every animation field. (Image shapes need a
      // file beside the scene: scenes/fig23-image-motion.json.)
      R"({
        "$schema": "../schema/scene.schema.json",
        "method": "P6",
        "keyframes": [
          {"t": 0, "p": [0, 0], "m": 1, "w": 0},
          {"t": 0.5, "from": {"p": [1, 1], "m": 1, "w": 0.5}, "to": {"p": [1, -1], "q": [2, -1], "turns": 1}},
          {"t": 1, "from": {"p": [2, 0], "q": [3, 0]}, "to": {"p": [2, 1], "m": 2, "w": -1}}
        ],
        "handle": {"p": [0, 0], "q": [1, 0]},
        "shapes": [{"outline": "F", "color": "red"}, {"polygon": [[0, 0], [1, 0], [1, 1]]}, {"polyline": [[0, 0], [1, 1]]},
                   {"triangle": "reference"}],
        "layers": [
          {"type": "shapes", "color": "blue", "width": 1, "opacity": 1, "dash": [], "fill": "#88aaff", "fill_opacity": 0.2,
           "samples": 9, "range": [0, 1]},
          {"type": "handle", "color": "red", "width": 2, "shapes": false},
          {"type": "pattern"}
        ],
        "panels": [
          {"title": "own handle", "handle": {"p": [0, 0], "m": 2, "w": 1, "turns": 0}},
          {"keyframes": [{"t": 0, "from": {"p": [0, 0], "m": 1, "w": 0}, "to": {"p": [0, 1], "m": 1, "w": 0}},
                         {"t": 1, "p": [1, 1], "m": 1, "w": 0}, {"t": 2, "p": [2, 0], "m": 1, "w": 0}],
           "handle": {"p": [0, 0], "q": [0, 1]}},
          "P2"
        ],
        "animation": {"duration": 2.5, "fps": 24, "frames": 60, "loop": false, "what": "pattern", "trail": 3,
                      "overlay": [0, 0.5, 1]}
      })",
      p6_with(R"(, "animation": {"duration": 0.05, "fps": 30, "what": "motion", "trail": 100, "loop": true})"),
      sam_with(
          R"(, "animation": {"duration": 3, "fps": 240, "frames": 100000, "loop": true, "what": "motion", "trail": 0})"),
      // A pose scene without poses: only layers that need none.
      R"({"method": "SAM", "layers": [{"type": "existence"}]})",
      R"({"method": "SAM", "layers": [{"type": "sam3d-existence", "steps": 12, "subdivisions": 1, "step": 0.02,
          "color": "blue", "width": 2, "opacity": 1, "dash": [], "fill": "none", "fill_opacity": 0.2,
          "paper": {"color": "orange", "dash": [4, 2]}}]})",
      R"({"method": "SAM", "layers": [{"type": "sam3d-existence", "fill": "#88aaff", "paper": false}]})",
      // Transparent background, shared view, empty layers.
      p6_with(R"(, "canvas": {"background": "none", "view": "shared"}, "layers": [], "panels": ["P4", "La-LP"])"),
  };
  return scenes;
}

TEST(SceneSchemaValidation, GoodScenesAreAcceptedByBoth) {
  for (const std::string& text : good_scenes()) {
    SCOPED_TRACE(text.substr(0, 300));
    EXPECT_EQ(schema_errors(nlohmann::json::parse(text)), "");
    EXPECT_EQ(error_message(text), "(no error)");
  }
}

TEST(SceneSchemaValidation, ColorNamesMatchTheParser) {
  const nlohmann::json schema = read_json(kSourceDir / "schema/scene.schema.json");
  std::vector<std::string> names;
  for (const NamedColor& named : named_colors()) names.emplace_back(named.name);
  EXPECT_EQ(schema.at("definitions").at("color").at("anyOf").at(1).at("enum"), nlohmann::json(names));
  const std::string description = schema.at("definitions").at("color").at("description");
  for (const NamedColor& named : named_colors()) {
    EXPECT_NE(description.find(std::string(named.name) + " (" + std::string(named.hex) + ")"), std::string::npos)
        << named.name;
  }
}

// The one table of the lint's checks (scene/lint_settings.hpp) and the schema's list.
TEST(SceneSchemaValidation, LintChecksMatchTheTable) {
  const nlohmann::json schema = read_json(kSourceDir / "schema/scene.schema.json");
  std::vector<std::string> names;
  for (const LintCheckInfo& check : kLintChecks) names.emplace_back(check.name);
  EXPECT_EQ(schema.at("definitions")
                .at("lint")
                .at("properties")
                .at("allow")
                .at("items")
                .at("properties")
                .at("check")
                .at("enum"),
            nlohmann::json(names));
}

// The one table of measure names (scene/measure_name.cpp) and the schema's
// list, in the same order; the prefixes of the names with an argument are the
// schema's patterns'.
TEST(SceneSchemaValidation, MeasureNamesMatchTheParser) {
  const nlohmann::json schema = read_json(kSourceDir / "schema/scene.schema.json");
  const nlohmann::json& items =
      schema.at("definitions").at("measuresLayer").at("properties").at("show").at("items").at("anyOf");
  std::vector<std::string> plain, parameters;
  std::string angle;
  for (const MeasureEntry& entry : measure_entries()) {
    if (!entry.argument) {
      plain.emplace_back(entry.name);
    } else if (entry.kind == MeasureKind::angle) {
      angle = std::string(entry.name);
    } else if (entry.kind == MeasureKind::frame_distance || entry.kind == MeasureKind::carried_distance ||
               entry.kind == MeasureKind::property || entry.kind == MeasureKind::guess_distance ||
               entry.kind == MeasureKind::guess_discrepancy) {
      continue;  // claims only: the schema's "measureName" (below)
    } else if (entry.kind == MeasureKind::discrepancy_of || entry.kind == MeasureKind::discrepancy_time) {
      continue;  // a pattern of their own (below)
    } else {
      parameters.emplace_back(entry.name.substr(0, entry.name.size() - 1));
    }
  }
  EXPECT_EQ(items.at(0).at("enum"), nlohmann::json(plain));
  std::string alternatives;
  for (const std::string& name : parameters) alternatives += (alternatives.empty() ? "" : "|") + name;
  EXPECT_EQ(items.at(1).at("pattern").get<std::string>().rfind("^(" + alternatives + "):", 0), 0u);
  EXPECT_EQ(items.at(2).at("pattern").get<std::string>().rfind("^" + angle, 0), 0u);
  // "discrepancy:P" and "discrepancy-t:P", P a predictor of Sec. 6.1 (the parser's
  // test refuses any other: tests/scene/test_measure_name.cpp).
  EXPECT_EQ(items.at(3).at("pattern"), "^discrepancy(-t)?:(previous|average|pita)$");
  for (const char* name : {"discrepancy:", "discrepancy-t:"}) {
    const auto entries = measure_entries();
    EXPECT_TRUE(std::any_of(entries.begin(), entries.end(), [&](const MeasureEntry& e) {
      return e.argument && e.name == name;
    })) << name;
  }
  EXPECT_EQ(items.size(), 4u);
  // A claim's measures: the layer's, "frame-distance:", "carried-distance:" and "property:" (whose names
  // tests/analysis/test_claims.cpp checks against the table of properties).
  const nlohmann::json& claim = schema.at("definitions").at("measureName").at("anyOf");
  ASSERT_EQ(claim.size(), 7u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(claim.at(i), items.at(i));
  EXPECT_EQ(claim.at(4).at("pattern"),
            "^(frame-distance:(/panels/[0-9]+(/layers/[0-9]+|@-?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][-+]?[0-9]+)?)?|"
            "[A-Za-z0-9][A-Za-z0-9:-]*)|carried-distance:/panels/[0-9]+)$");
  EXPECT_EQ(claim.at(5).at("pattern").get<std::string>().rfind("^property:(", 0), 0u);
  EXPECT_EQ(claim.at(6).at("pattern"), "^guess-(distance|discrepancy):.+$");
}

// The one table of method options and their values (core/pitas/method_options.hpp)
// and the schema's "options".
TEST(SceneSchemaValidation, OptionNamesMatchTheParser) {
  const nlohmann::json schema = read_json(kSourceDir / "schema/scene.schema.json");
  const nlohmann::json& options = schema.at("definitions").at("options").at("properties");
  std::vector<std::string> keys;
  for (const MethodOptionKey& key : kMethodOptionKeys) keys.emplace_back(key.name);
  std::vector<std::string> in_schema;
  for (const auto& [key, value] : options.items()) in_schema.push_back(key);
  std::vector<std::string> sorted = keys;
  std::sort(sorted.begin(), sorted.end());
  std::sort(in_schema.begin(), in_schema.end());
  EXPECT_EQ(in_schema, sorted);
  const auto names = [](std::span<const std::string_view> values) {
    nlohmann::json out = nlohmann::json::array();
    for (const std::string_view value : values) out.push_back(std::string(value));
    return out;
  };
  EXPECT_EQ(options.at("anchor").at("enum"), names(kAnchorNames));
  EXPECT_EQ(schema.at("definitions").at("mean").at("enum"), names(kMeanNames));
  EXPECT_EQ(options.at("knots").at("enum"), names(kKnotOrderNames));
  EXPECT_EQ(options.at("permutation").at("enum"), names(kPermutationNames));
  // Every option's default, as MethodOptions{} has it (option_choices: not
  // always the first name; the means' is "geometric").
  for (const MethodOptionKey& key : kMethodOptionKeys) {
    const std::string_view expected = option_choices(key.option).default_name;
    const nlohmann::json& given = options.at(std::string(key.name)).at("default");
    if (key.option == kSymmetrizeOption) {
      EXPECT_EQ(given.get<bool>(), expected == "true") << key.name;
    } else {
      EXPECT_EQ(given, std::string(expected)) << key.name;
    }
  }
  EXPECT_EQ(option_choices(kPathMeanOption).default_name, "geometric");  // steady (Sec. 2.7)
}

// 3D pose scenes ("dimension": 3): the schema's spacePoseScene and the
// parser. The method pattern accepts exactly the pose methods the table
// marks in_space.
std::string space_scene(const std::string& method, const std::string& second_pose, const std::string& extra = "") {
  return R"({"dimension": 3, "method": ")" + method + R"(", "poses": [
    {"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]}, )" +
         second_pose + "]" + extra + "}";
}

const std::string kSpacePose = R"({"t": 1, "matrix": [[0, -1, 0, 1], [1, 0, 0, 0], [0, 0, 1, 2]]})";

std::string space_error_pointer(const std::string& text) { return error_pointer(text); }

TEST(SceneSchemaValidation, SpaceScenesAgreeWithTheParser) {
  for (const PoseMethodInfo& entry : all_pose_methods()) {
    if (entry.min_poses > 2) continue;  // two poses below
    const std::string text = space_scene(std::string(entry.id), kSpacePose);
    const nlohmann::json document = nlohmann::json::parse(text);
    EXPECT_EQ(validate(document).valid, entry.in_space) << entry.id;
    EXPECT_EQ(space_error_pointer(text) == "(no error)", entry.in_space) << entry.id;
  }
  const std::string good =
      space_scene("SAM", R"({"t": 1, "tetrahedron": [[1, 0, 0], [1, 1, 0], [0, 0, 0], [1, 0, 1]]})",
                  R"(, "reference_tetrahedron": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], "samples": 5)");
  EXPECT_EQ(schema_errors(nlohmann::json::parse(good)), "");
  EXPECT_EQ(space_error_pointer(good), "(no error)");

  const std::vector<BadScene> bad = {
      {"2D matrix", space_scene("SAM", R"({"t": 1, "matrix": [[1, 0, 2], [0, 1, 0]]})"), "/poses/1/matrix"},
      {"triangle", space_scene("SAM", R"({"t": 1, "triangle": [[0, 0], [1, 0], [0, 1]]})"), "/poses/1/triangle"},
      {"3x3 matrix", space_scene("SAM", R"({"t": 1, "matrix": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]})"), "/poses/1/matrix"},
      {"tetrahedron of three points",
       space_scene("SAM", R"({"t": 1, "tetrahedron": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]})"), "/poses/1/tetrahedron"},
      {"dimension 4", R"({"dimension": 4, "method": "SAM", "poses": []})", "/dimension"},
      {"reference triangle in space",
       space_scene("SAM", kSpacePose, R"(, "reference_triangle": [[0, 0], [1, 0], [0, 1]])"), "/reference_triangle"},
  };
  for (const BadScene& scene : bad) {
    EXPECT_FALSE(validate(nlohmann::json::parse(scene.text)).valid) << scene.what;
    EXPECT_EQ(space_error_pointer(scene.text), scene.pointer) << scene.what;
  }
}

}  // namespace
}  // namespace pita::scene
