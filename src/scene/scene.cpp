#include "scene/scene.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "scene/figure_reader.hpp"
#include "scene/timing_reader.hpp"
#include "scene/json_reader.hpp"
#include "scene/pose_reader.hpp"

namespace pita::scene {

namespace {

using detail::element_pointer;
using detail::Json;
using detail::JsonReader;
using detail::keyframe_count_reason;
using detail::unknown_method_reason;
using detail::value_text;
using detail::Interval;

// The fields each object of a scene may have; anything else is an error.
constexpr std::array<std::string_view, 12> kSceneFields = {
    "$schema", "description", "method", "keyframes", "samples", "options",
    "title",   "canvas",      "layers", "panels",    "golden",  "timing"};
constexpr std::array<std::string_view, 4> kGoldenFields = {"number_tolerance", "svg_tolerance",
                                                           "pixel_tolerance", "max_differing"};
constexpr std::array<std::string_view, 7> kPanelFields = {
    "method", "options", "keyframes", "title", "samples", "layers", "timing"};

// Pose scenes (README "Pose scenes").
constexpr std::array<std::string_view, 14> kPoseSceneFields = {
    "$schema", "description", "method", "poses",  "reference_triangle", "shapes",
    "samples", "title",       "canvas", "layers", "panels",             "golden",
    "subdivisions", "timing"};
constexpr std::array<std::string_view, 8> kPosePanelFields = {
    "method", "poses", "shapes", "title", "samples", "layers", "subdivisions", "timing"};

// Whether a layer needs the motion (every one but "existence" and "label").
bool needs_motion(const std::vector<PoseLayer>& layers) {
  return std::any_of(layers.begin(), layers.end(), [](const PoseLayer& layer) {
    return !std::holds_alternative<ExistenceLayer>(layer) && !std::holds_alternative<LabelLayer>(layer) &&
           !std::holds_alternative<PatchLayer>(layer);
  });
}

// A panel given by its method is titled "P6 La-LP" ("SMA" for SMA).
std::string method_title(Method method) {
  const MethodInfo& about = info(method);
  std::string title(about.id);
  if (!about.mnemonic.empty() && about.mnemonic != about.id) {
    title += ' ';
    title += about.mnemonic;
  }
  return title;
}

// ------------------------------------------------------------ JSON parsing

// 1-based line and column of the byte at `index` (columns count bytes, as
// nlohmann's own messages do).
std::pair<int, int> line_and_column(std::string_view text, std::size_t index) {
  index = std::min(index, text.size());
  const std::string_view before = text.substr(0, index);
  const auto line = 1 + std::count(before.begin(), before.end(), '\n');
  const std::size_t line_start = before.rfind('\n') == std::string_view::npos
                                     ? 0
                                     : before.rfind('\n') + 1;
  return {static_cast<int>(line), static_cast<int>(index - line_start + 1)};
}

// nlohmann's message without its "[json.exception.parse_error.101] parse error
// at line 3, column 14: " prefix (we print our own position).
std::string parse_error_reason(const std::string& message) {
  const std::size_t start = message.find("parse error");
  if (start == std::string::npos) return message;
  const std::size_t colon = message.find(": ", start);
  if (colon == std::string::npos) return message;
  return message.substr(colon + 2);
}

// A number too large for a double (1e999) is refused by nlohmann with an
// out_of_range exception that carries no position. This event-only second
// pass finds where: the parser reports the position just after the number.
class NumberOverflowLocator : public nlohmann::json_sax<Json> {
 public:
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t position, const std::string& last_token,
                   const Json::exception&) override {
    end = position;
    token = last_token;
    return false;
  }

  std::size_t end = 0;  // bytes read, up to and including the number
  std::string token;    // the number as written
};

// A member given twice in one object ("m": 1, "m": -1): JSON leaves its
// meaning open and nlohmann keeps the last one silently, so we refuse it.
struct DuplicateKey {
  std::string pointer;
  std::string key;
};

// Follows the parser's events to know the JSON Pointer of the value being
// read, and throws DuplicateKey at a member's second occurrence.
class DuplicateKeyFinder {
 public:
  bool operator()(int /*depth*/, nlohmann::json::parse_event_t event, Json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        stack_.emplace_back();
        stack_.back().array = event == Event::array_start;
        break;
      case Event::key: {
        Frame& top = stack_.back();
        top.key = parsed.get<std::string>();
        if (!top.keys.insert(top.key).second) throw DuplicateKey{pointer(), top.key};
        break;
      }
      case Event::object_end:
      case Event::array_end:
        stack_.pop_back();
        next_element();
        break;
      case Event::value: next_element(); break;
    }
    return true;
  }

 private:
  struct Frame {
    bool array = false;
    std::size_t index = 0;
    std::set<std::string> keys;
    std::string key;
  };

  void next_element() {
    if (!stack_.empty() && stack_.back().array) ++stack_.back().index;
  }

  std::string pointer() const {
    std::string text;
    for (const Frame& frame : stack_) {
      if (frame.array) {
        text += '/' + std::to_string(frame.index);
      } else {
        text += '/';
        for (char c : frame.key) text += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
      }
    }
    return text;
  }

  std::vector<Frame> stack_;
};

Json parse_json(std::string_view text, const std::string& file) {
  // nlohmann stops at a NUL byte as if the text ended there.
  if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
    const auto [line, column] = line_and_column(text, nul);
    throw SceneError(file, line, column,
                     "the file contains a NUL byte: a scene is UTF-8 text (is this file UTF-16 "
                     "or binary?)");
  }
  try {
    return Json::parse(text, DuplicateKeyFinder());
  } catch (const DuplicateKey& duplicate) {
    throw SceneError(file, duplicate.pointer,
                     fmt::format("field \"{}\" is given twice in the same object", duplicate.key));
  } catch (const Json::parse_error& error) {
    // error.byte counts the bytes read, the offending one included.
    const auto [line, column] = line_and_column(text, error.byte == 0 ? 0 : error.byte - 1);
    throw SceneError(file, line, column, "malformed JSON: " + parse_error_reason(error.what()));
  } catch (const Json::out_of_range&) {
    NumberOverflowLocator locator;
    Json::sax_parse(text, &locator);
    const std::size_t start =
        locator.end >= locator.token.size() ? locator.end - locator.token.size() : 0;
    const auto [line, column] = line_and_column(text, start);
    throw SceneError(file, line, column,
                     fmt::format("number {} is out of range (too large for a double)",
                                 locator.token));
  }
}

// ----------------------------------------------------------- scene reading

class SceneReader {
 public:
  explicit SceneReader(std::string file) : reader_(std::move(file)) {}

  // "golden": {"number_tolerance", "svg_tolerance", "pixel_tolerance", "max_differing"}.
  void read_golden(const Json& value, Scene::GoldenTolerances& out) const {
    reader_.object(value, "/golden", "\"golden\"");
    reader_.check_fields(value, "/golden", kGoldenFields);
    if (const Json* x = member(value, "number_tolerance")) {
      out.numbers = reader_.number(*x, "/golden/number_tolerance", Interval{0.0, 1.0});
    }
    if (const Json* x = member(value, "svg_tolerance")) {
      out.svg = reader_.number(*x, "/golden/svg_tolerance", Interval{0.0, 1000.0});
    }
    if (const Json* x = member(value, "pixel_tolerance")) {
      out.pixel = reader_.integer(*x, "/golden/pixel_tolerance", 0, 255);
    }
    if (const Json* x = member(value, "max_differing")) {
      out.max_differing = reader_.number(*x, "/golden/max_differing", Interval{0.0, 1.0});
    }
  }

  Scene read(const Json& document) const {
    if (!document.is_object()) {
      fail("", "a scene must be a JSON object (got " + value_text(document) + ")");
    }
    if (is_pose_scene(document)) return read_pose_scene(document);
    reader_.check_fields(document, "", kSceneFields);

    Scene scene;
    scene.path = reader_.file();
    if (const Json* schema = member(document, "$schema")) reader_.string(*schema, "/$schema");
    if (const Json* description = member(document, "description")) {
      scene.description = reader_.string(*description, "/description");
    }

    const Json* method = member(document, "method");
    if (method == nullptr) fail("/method", "missing required field (a method such as \"P6\")");
    scene.method = reader_.method(*method, "/method");
    scene.method_name = std::string(info(scene.method).id);

    if (const Json* options = member(document, "options")) {
      scene.options = reader_.options(*options, "/options", MethodOptions{});
    }

    const Json* keyframes = member(document, "keyframes");
    if (keyframes == nullptr) fail("/keyframes", "missing required field (an array of keyframes)");
    scene.keyframes = reader_.keyframes(*keyframes, "/keyframes", scene.method);

    if (const Json* samples = member(document, "samples")) {
      scene.samples = reader_.integer(*samples, "/samples", kMinSamples, kMaxSamples);
    }
    if (const Json* timing = member(document, "timing")) {
      scene.timing = detail::read_timing(reader_, *timing, "/timing");
    }

    // The figure (README "Figures"); `pita eval` ignores it.
    if (const Json* title = member(document, "title")) {
      scene.title = reader_.string(*title, "/title");
    }
    if (const Json* canvas = member(document, "canvas")) {
      scene.canvas = detail::read_canvas(reader_, *canvas, "/canvas");
    }
    if (const Json* layers = member(document, "layers")) {
      scene.layers = detail::read_layers(reader_, *layers, "/layers");
    } else {
      scene.layers = {PatternLayer{}, KeyframesLayer{}};
    }
    if (const Json* panels = member(document, "panels")) {
      scene.panels = read_panels(*panels, "/panels", scene);
    } else {
      scene.panels = {scene_panel(scene, "")};
    }
    if (const Json* golden = member(document, "golden")) read_golden(*golden, scene.golden);
    return scene;
  }

 private:
  // A pose scene has "poses", or a pose method such as "SAM".
  static bool is_pose_scene(const Json& document) {
    if (member(document, "poses") != nullptr) return true;
    const Json* method = member(document, "method");
    return method != nullptr && method->is_string() &&
           find_method_entry(method->get<std::string>(), MotionKind::poses) != nullptr &&
           member(document, "keyframes") == nullptr;
  }

  Scene read_pose_scene(const Json& document) const {
    reader_.check_fields(document, "", kPoseSceneFields);
    Scene scene;
    scene.kind = SceneKind::poses;
    scene.path = reader_.file();
    if (const Json* schema = member(document, "$schema")) reader_.string(*schema, "/$schema");
    if (const Json* description = member(document, "description")) {
      scene.description = reader_.string(*description, "/description");
    }
    const Json* method = member(document, "method");
    if (method == nullptr) {
      fail("/method", "missing required field (a pose method such as \"SAM\")");
    }
    scene.pose_method = detail::read_pose_method(reader_, *method, "/method");
    scene.method_name = std::string(info(scene.pose_method).id);
    if (const Json* reference = member(document, "reference_triangle")) {
      scene.reference_triangle =
          detail::read_reference_triangle(reader_, *reference, "/reference_triangle");
    }
    if (const Json* shapes = member(document, "shapes")) {
      scene.shapes = detail::read_shapes(reader_, *shapes, "/shapes", scene.reference_triangle);
    } else {
      scene.shapes = {ShapeOutline{std::vector<Point>(scene.reference_triangle.begin(),
                                                      scene.reference_triangle.end()),
                                   true, std::nullopt}};
    }
    if (const Json* samples = member(document, "samples")) {
      scene.samples = reader_.integer(*samples, "/samples", kMinSamples, kMaxSamples);
    }
    if (const Json* subdivisions = member(document, "subdivisions")) {
      scene.subdivisions = reader_.integer(*subdivisions, "/subdivisions", 0, kMaxSubdivisions);
    }
    if (const Json* timing = member(document, "timing")) {
      scene.timing = detail::read_timing(reader_, *timing, "/timing");
    }
    if (const Json* title = member(document, "title")) scene.title = reader_.string(*title, "/title");
    if (const Json* canvas = member(document, "canvas")) {
      scene.canvas = detail::read_canvas(reader_, *canvas, "/canvas");
    }
    if (const Json* layers = member(document, "layers")) {
      scene.pose_layers = detail::read_pose_layers(reader_, *layers, "/layers");
    } else {
      scene.pose_layers = {ShapesLayer{}, PosesLayer{}};
    }
    const Json* panels = member(document, "panels");
    const Json* poses = member(document, "poses");
    if (poses != nullptr) {
      scene.poses = detail::read_poses(reader_, *poses, "/poses", scene.reference_triangle,
                                       scene.pose_method);
    } else if (panels == nullptr && needs_motion(scene.pose_layers)) {
      fail("/poses", "missing required field (an array of poses {\"t\": ..., \"matrix\": [[a, b, "
                     "tx], [c, d, ty]]} or {\"t\": ..., \"triangle\": [[x, y], [x, y], [x, y]]})");
    }
    if (panels != nullptr) {
      scene.panels = read_pose_panels(*panels, "/panels", scene);
    } else {
      scene.panels = {scene_panel(scene, "")};
    }
    if (const Json* golden = member(document, "golden")) read_golden(*golden, scene.golden);
    return scene;
  }

  std::vector<Panel> read_pose_panels(const Json& value, const std::string& pointer,
                                      const Scene& scene) const {
    if (!value.is_array() || value.empty() || value.size() > static_cast<std::size_t>(kMaxPanels)) {
      fail(pointer, fmt::format("must be an array of 1 to {} panels (got {})", kMaxPanels,
                                value_text(value)));
    }
    std::vector<Panel> panels;
    for (std::size_t i = 0; i < value.size(); ++i) {
      const std::string at = element_pointer(pointer, i);
      const Json& item = value[i];
      Panel panel = scene_panel(scene, at);
      bool own_method = false, own_poses = false;
      if (item.is_string()) {
        panel.pose_method = detail::read_pose_method(reader_, item, at);
        own_method = true;
      } else {
        reader_.object(item, at, "a panel (a pose method name or an object)");
        reader_.check_fields(item, at, kPosePanelFields);
        if (const Json* method = member(item, "method")) {
          panel.pose_method = detail::read_pose_method(reader_, *method, at + "/method");
          own_method = true;
        }
        if (const Json* title = member(item, "title")) panel.title = reader_.string(*title, at + "/title");
        if (const Json* timing = member(item, "timing")) {
          panel.timing = detail::read_timing(reader_, *timing, at + "/timing");
        }
        if (const Json* samples = member(item, "samples")) {
          panel.samples = reader_.integer(*samples, at + "/samples", kMinSamples, kMaxFigureSamples);
        }
        if (const Json* subdivisions = member(item, "subdivisions")) {
          panel.subdivisions =
              reader_.integer(*subdivisions, at + "/subdivisions", 0, kMaxSubdivisions);
          own_method = true;  // the motion changes: check it again
        }
        if (const Json* shapes = member(item, "shapes")) {
          panel.shapes = detail::read_shapes(reader_, *shapes, at + "/shapes", scene.reference_triangle);
        }
        if (const Json* layers = member(item, "layers")) {
          panel.pose_layers = detail::read_pose_layers(reader_, *layers, at + "/layers");
        }
        if (const Json* poses = member(item, "poses")) {
          panel.poses = detail::read_poses(reader_, *poses, at + "/poses", scene.reference_triangle,
                                           panel.pose_method);
          own_poses = true;
        }
      }
      panel.method_name = std::string(info(panel.pose_method).id);
      const std::vector<PoseLayer>& layers = panel.pose_layers ? *panel.pose_layers : scene.pose_layers;
      if (needs_motion(layers)) {
        const PoseMethodInfo& about = info(panel.pose_method);
        const std::string poses_at = own_poses ? at + "/poses" : std::string("/poses");
        const auto count = static_cast<int>(panel.poses.size());
        if (panel.poses.empty()) {
          fail(at, "the panel draws a motion but has no poses: give it \"poses\" or give the "
                   "scene \"poses\"");
        }
        if (count < about.min_poses || count > about.max_poses) {
          fail(own_method ? at : poses_at,
               detail::pose_count_reason(panel.pose_method, panel.poses.size()) +
                   "; give the panel its own \"poses\"");
        }
        panel.motion_pointer = own_poses ? poses_at : own_method ? at : std::string("/poses");
      }
      if (panel.title.empty() && own_method) panel.title = std::string(info(panel.pose_method).id);
      panels.push_back(std::move(panel));
    }
    return panels;
  }

  [[noreturn]] void fail(const std::string& pointer, std::string reason) const {
    reader_.fail(pointer, std::move(reason));
  }

  static const Json* member(const Json& object, const std::string& key) {
    return JsonReader::member(object, key);
  }

  std::vector<Panel> read_panels(const Json& value, const std::string& pointer,
                                 const Scene& scene) const {
    if (!value.is_array()) {
      fail(pointer, "must be an array of panels, each a method name or an object (got " +
                        value_text(value) + ")");
    }
    if (value.empty() || value.size() > static_cast<std::size_t>(kMaxPanels)) {
      fail(pointer, fmt::format("must have between 1 and {} panels (got {})", kMaxPanels,
                                value.size()));
    }
    std::vector<Panel> panels;
    for (std::size_t i = 0; i < value.size(); ++i) {
      panels.push_back(read_panel(value[i], element_pointer(pointer, i), scene));
    }
    return panels;
  }

  // A panel is a method name ("P2") or an object whose fields override the scene's.
  Panel read_panel(const Json& value, const std::string& pointer, const Scene& scene) const {
    Panel panel = scene_panel(scene, pointer);
    if (value.is_string()) {
      set_method(panel, reader_.method(value, pointer), pointer, scene);
      panel.motion_pointer = pointer;
      return panel;
    }
    if (!value.is_object()) {
      fail(pointer, "a panel must be a method name or an object (got " + value_text(value) + ")");
    }
    reader_.check_fields(value, pointer, kPanelFields);
    const Json* keyframes = member(value, "keyframes");
    if (const Json* method = member(value, "method")) {
      const std::string at = pointer + "/method";
      const Method found = reader_.method(*method, at);
      if (keyframes == nullptr) {
        set_method(panel, found, at, scene);
      } else {
        panel.method = found;
        panel.method_name = std::string(info(found).id);
        panel.title = method_title(found);
      }
    }
    if (const Json* options = member(value, "options")) {
      panel.options = reader_.options(*options, pointer + "/options", scene.options);
    }
    if (keyframes != nullptr) {
      panel.keyframes = reader_.keyframes(*keyframes, pointer + "/keyframes", panel.method);
      panel.motion_pointer = pointer + "/keyframes";
    } else if (member(value, "method") != nullptr || member(value, "options") != nullptr) {
      panel.motion_pointer = pointer;  // the scene's keyframes, the panel's method
    }
    if (const Json* title = member(value, "title")) {
      panel.title = reader_.string(*title, pointer + "/title");
    }
    if (const Json* samples = member(value, "samples")) {
      panel.samples = reader_.integer(*samples, pointer + "/samples", kMinSamples,
                                      kMaxFigureSamples);
    }
    if (const Json* layers = member(value, "layers")) {
      panel.layers = detail::read_layers(reader_, *layers, pointer + "/layers");
    }
    if (const Json* timing = member(value, "timing")) {
      panel.timing = detail::read_timing(reader_, *timing, pointer + "/timing");
    }
    return panel;
  }

  // The panel draws the scene's keyframes with `method`, which must take as many.
  void set_method(Panel& panel, Method method, const std::string& pointer,
                  const Scene& scene) const {
    if (scene.keyframes.size() != static_cast<std::size_t>(info(method).keyframe_count)) {
      fail(pointer, keyframe_count_reason(method, scene.keyframes.size()) +
                        " from the scene; give the panel its own \"keyframes\"");
    }
    panel.method = method;
    panel.method_name = std::string(info(method).id);
    panel.title = method_title(method);
  }

  JsonReader reader_;
};


}  // namespace

std::string located(const std::string& file, const std::string& pointer,
                    const std::string& reason) {
  return pointer.empty() ? file + ": " + reason : file + ": " + pointer + ": " + reason;
}

Panel scene_panel(const Scene& scene, std::string pointer) {
  Panel panel;
  panel.method = scene.method;
  panel.method_name = scene.method_name;
  panel.options = scene.options;
  panel.keyframes = scene.keyframes;
  panel.pose_method = scene.pose_method;
  panel.poses = scene.poses;
  panel.shapes = scene.shapes;
  panel.subdivisions = scene.subdivisions;
  panel.timing = scene.timing;
  panel.samples = scene.samples.value_or(kDefaultFigureSamples);
  panel.pointer = std::move(pointer);
  panel.motion_pointer = scene.kind == SceneKind::poses ? "/poses" : "/keyframes";
  return panel;
}

SceneError::SceneError(std::string file, std::string pointer, std::string reason)
    : std::runtime_error(located(file, pointer, reason)),
      file_(std::move(file)),
      pointer_(std::move(pointer)),
      reason_(std::move(reason)) {}

SceneError::SceneError(std::string file, int line, int column, std::string reason)
    : std::runtime_error(fmt::format("{}:{}:{}: {}", file, line, column, reason)),
      file_(std::move(file)),
      reason_(std::move(reason)),
      line_(line),
      column_(column) {}

Scene load_scene(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) {
    throw SceneError(name, "", "cannot read the scene file: it is a directory");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw SceneError(name, "", fmt::format("cannot open the scene file ({})", std::strerror(errno)));
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw SceneError(name, "", "cannot read the scene file");
  return parse_scene(text.str(), name);
}

Scene parse_scene(std::string_view text, std::string source_name) {
  const Json document = parse_json(text, source_name);
  return SceneReader(std::move(source_name)).read(document);
}

Method resolve_method(std::string_view name) {
  if (const MethodEntry* entry = find_method_entry(name, MotionKind::arrows)) return entry->method;
  throw std::invalid_argument(pita::unknown_method_reason(name, MotionKind::arrows));
}

Scene with_method(Scene scene, Method method) {
  if (scene.kind == SceneKind::poses) {
    std::string pose_methods;
    for (const MethodEntry& entry : every_method()) {
      if (entry.kind != MotionKind::poses) continue;
      pose_methods += (pose_methods.empty() ? "" : ", ") + std::string(entry.id);
    }
    throw SceneError(scene.path, "/method",
                     fmt::format("method {} interpolates arrows; this is a pose scene (methods: {})",
                                 info(method).id, pose_methods));
  }
  const MethodInfo& about = info(method);
  if (scene.keyframes.size() != static_cast<std::size_t>(about.keyframe_count)) {
    throw SceneError(scene.path, "/keyframes", keyframe_count_reason(method, scene.keyframes.size()));
  }
  scene.method = method;
  scene.method_name = std::string(about.id);
  // The panel that is the scene itself follows it; panels of their own keep theirs.
  for (Panel& panel : scene.panels) {
    if (!panel.pointer.empty()) continue;
    panel.method = method;
    panel.method_name = scene.method_name;
  }
  return scene;
}

std::string no_sam_reason(const NoSamBetweenPoses& error, PoseMethod method) {
  if (!error.where().empty()) {
    return fmt::format("{} ({}, method {})", error.what(), error.where(), info(method).id);
  }
  return fmt::format("{} (poses {} and {}, method {})", error.what(), error.first(),
                     error.first() + 1, info(method).id);
}

Scene with_pose_method(Scene scene, PoseMethod method) {
  if (scene.kind != SceneKind::poses) {
    throw SceneError(scene.path, "/method",
                     fmt::format("method {} interpolates poses; this scene has keyframes (arrows)",
                                 info(method).id));
  }
  const PoseMethodInfo& about = info(method);
  if (scene.poses.empty()) {
    throw SceneError(scene.path, "/poses", "the scene has no poses to interpolate");
  }
  const auto count = static_cast<int>(scene.poses.size());
  if (count < about.min_poses || count > about.max_poses) {
    throw SceneError(scene.path, "/poses", detail::pose_count_reason(method, scene.poses.size()));
  }
  scene.pose_method = method;
  scene.method_name = std::string(about.id);
  for (Panel& panel : scene.panels) {
    if (!panel.pointer.empty()) continue;
    panel.pose_method = method;
    panel.method_name = scene.method_name;
  }
  return scene;
}

}  // namespace pita::scene
