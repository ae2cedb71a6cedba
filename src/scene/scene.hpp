// The scene model: a JSON scene file read, checked and fully resolved (every
// default applied, every name looked up, every number checked), so that the
// layers above never see JSON (habit copied from usvg handing resvg a resolved
// tree). The format is documented in docs/reference/scene-format.md ("Scene format") and published
// as schema/scene.schema.json.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/keyframe.hpp"
#include "core/methods.hpp"
#include "core/pitas/registry.hpp"
#include "core/sam_family_motion.hpp"
#include "scene/claim.hpp"
#include "scene/figure.hpp"
#include "scene/limits.hpp"
#include "scene/lint_settings.hpp"
#include "scene/located_error.hpp"
#include "scene/motion_keys.hpp"
#include "scene/read_options.hpp"

namespace pita::scene {

struct Scene {
  std::string path;         // where the scene came from (a file name, as given)
  std::string description;  // "" when the scene has none
  // What the scene's own motion is made of: keyframes (the PITA paper),
  // points (PITA Sec. 7.6), poses of the plane (the SAM paper) or of space
  // ("dimension": 3); its alternative is the kind of the scene. Panels start
  // from it (scene_panel) and may override it within the same family.
  MotionKeys keys;
  // "animation": how `pita animate` and `pita render --at` play the scene.
  Animation animation;
  bool has_animation = false;  // the scene gave "animation"
  std::optional<int> samples;  // in [kMinSamples, kMaxSamples] when given
  Timing timing;               // "timing": how scene time runs through the motion

  // The figure (scene/figure.hpp), read by `pita render`; `pita eval` ignores
  // it (but for a pose scene's reference simplex, which poses given as
  // simplices map). `figure` holds the figure data of the family of `keys`:
  // reach it with figure_of below.
  std::string title;  // "" = none; drawn above the panels
  Canvas canvas;
  SceneFigure figure;
  std::vector<Panel> panels;  // at least one: the scene itself when it has no "panels"

  // "golden": this scene's tolerances for `pita check` (docs/reference/check.md "Goldens");
  // unset fields take the command line's values, else the defaults.
  struct GoldenTolerances {
    std::optional<double> numbers;        // "number_tolerance", [0, 1]
    std::optional<double> svg;            // "svg_tolerance", pixels, [0, 1000]
    std::optional<int> pixel;             // "pixel_tolerance", [0, 255]
    std::optional<double> max_differing;  // "max_differing", [0, 1]
  } golden;

  // "claims": the caption's statements, checked by `pita check` (scene/claim.hpp).
  std::vector<Claim> claims;

  // "lint": the legibility lint's thresholds and accepted findings (scene/lint_settings.hpp).
  LintSettings lint;
};

// The figure data of the family of `Keys`, an alternative of MotionKeys
// (ArrowFigure for KeyframeKeys and PointKeys, PoseFigure<Pose> for
// PoseKeys<Pose>): the scene's, or the panel's (PanelFigureOf<Keys>). The
// figure's type follows from the keys' type, so that a site that visits the
// keys cannot take another family's figure; the readers give every scene and
// panel the figure of its keys' family (parse_scene checks it once: see
// figure_agrees), and a panel overrides keys only within its family.
template <class Keys>
const FigureOf<Keys>& figure_of(const Scene& scene) {
  return std::get<FigureOf<Keys>>(scene.figure);
}
template <class Keys>
FigureOf<Keys>& figure_of(Scene& scene) {
  return std::get<FigureOf<Keys>>(scene.figure);
}
template <class Keys>
const PanelFigureOf<Keys>& figure_of(const Panel& panel) {
  return std::get<PanelFigureOf<Keys>>(panel.figure);
}
template <class Keys>
PanelFigureOf<Keys>& figure_of(Panel& panel) {
  return std::get<PanelFigureOf<Keys>>(panel.figure);
}
// The same, the family given by the keys a visit holds: figure_of(scene, keys).
template <class Keys>
const FigureOf<Keys>& figure_of(const Scene& scene, const Keys&) {
  return figure_of<Keys>(scene);
}
template <class Keys>
const PanelFigureOf<Keys>& figure_of(const Panel& panel, const Keys&) {
  return figure_of<Keys>(panel);
}

// The outlines of the plane that a panel draws, images included: an arrow
// panel's shapes (carried by the handle), a plane pose panel's; none in
// space, whose shapes are solids.
const std::vector<ShapeOutline>& outlines_of(const Panel& panel);

// Whether the figure data are of the family of the keys (what the readers
// guarantee of every scene and panel).
bool figure_agrees(const MotionKeys& keys, const SceneFigure& figure);
bool figure_agrees(const MotionKeys& keys, const PanelFigure& figure);

// The layers a panel draws, and where they are in the file: the panel's own
// "layers" (at PANEL/layers), else the scene's (at /layers). LayerType is
// Layer in an arrow scene (keyframes or points), PoseLayer in a pose scene.
template <class LayerType>
struct LayersOf {
  const std::vector<LayerType>& layers;
  bool own = false;    // the panel's own "layers"
  std::string parent;  // the panel's pointer for its own layers, "" for the scene's
  // "/panels/1/layers/0", "/layers/0": the JSON Pointer of layer i.
  std::string pointer(std::size_t i) const { return parent + "/layers/" + std::to_string(i); }
};
template <class LayerType>
LayersOf<LayerType> layers_of(const Scene& scene, const Panel& panel);

// What is wrong with a scene, and where. what() is
//   "FILE: /keyframes/1/m: magnitude must be > 0 (got -2)"   (a value; the
//       JSON Pointer of RFC 6901 is left out when it is the whole document), or
//   "FILE:3:14: malformed JSON: ..."                         (a position of the text).
// (A located error: scene/located_error.hpp.)
class SceneError : public LocatedError {
 public:
  SceneError(std::string file, std::string pointer, std::string reason)
      : LocatedError(LocatedKind::scene, std::move(file), std::move(pointer), std::move(reason)) {}
  SceneError(std::string file, int line, int column, std::string reason)
      : LocatedError(LocatedKind::scene, std::move(file), line, column, std::move(reason)) {}
};

// The panel that is the scene itself: its method, keyframes or poses, shapes,
// options, timing and samples (a scene without "panels" draws this one).
Panel scene_panel(const Scene& scene, std::string pointer = "");

// The pointers of the panels of a scene document ("/panels/0" for a panel
// given as a method name, "/panels/1/method") when every panel sets its own
// method, so that none draws the scene's; empty otherwise (also without
// panels).
std::vector<std::string> panels_with_own_methods(const nlohmann::ordered_json& document);

// Reads and checks the scene file at `path`. Throws SceneError (also when the
// file cannot be read); the error names the file as `path` is spelt.
Scene load_scene(const std::filesystem::path& path, const ReadOptions& options = {});

// Checks the scene given as JSON text; `source_name` names it in errors and
// becomes Scene::path. Throws SceneError.
// Image paths are found relative to the folder of `source_name`.
Scene parse_scene(std::string_view text, std::string source_name, const ReadOptions& options = {});

// The method named `name` (any spelling pita::find_method accepts). Throws
// std::invalid_argument with a message such as
//   unknown method "P66" (did you mean "P6"?)
Method resolve_method(std::string_view name);

// The scene with its method replaced by `method` (command-line override, or
// a method of either kind named by the user). An arrow method needs keyframes
// or points: SceneError at /keyframes when it takes more keyframes than the
// scene has, at /chain when the scene's chain cannot extend it, at /method for
// a pose scene. A pose method needs poses: SceneError at /method for an arrow
// scene, at /dimension for a plane-only method in a 3D scene, at /poses when it
// takes another number of poses.
Scene with_method(Scene scene, const AnyMethod& method);

// The scene with the method named `name` (any spelling find_method_entry
// accepts), looked up first among the methods of the scene's kind: "P6" is
// the arrow P6 in an arrow scene and the pose P6 in a pose scene. A name of
// the other kind only is refused as with_method refuses it; an unknown name
// throws std::invalid_argument with unknown_method_reason's words.
Scene with_method(Scene scene, std::string_view name);

// "no SAM exists between these poses: ... (poses 0 and 1, method SAM)": the
// reason of the error that refuses a pose motion whose SAM does not exist.
std::string no_sam_reason(const NoSamBetweenPoses& error, PoseMethod method);

}  // namespace pita::scene
