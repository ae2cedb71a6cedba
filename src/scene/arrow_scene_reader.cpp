// Arrow scenes: timed keyframes (the PITA paper; docs/reference/scene-format.md "Scene format").
#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "core/limits.hpp"
#include "core/overloaded.hpp"
#include "scene/figure_reader.hpp"
#include "scene/layer_kinds.hpp"
#include "scene/option_use.hpp"
#include "scene/pose_reader.hpp"
#include "scene/scene_readers.hpp"
#include "scene/timing_reader.hpp"

namespace pita::scene::detail {

namespace {

// Layers fit what the panel has: a panel of timed points draws
// point-trajectory (and labels, legends); a panel of keyframes draws the rest.
// The Neville-type curves take at most limits::kMaxNevillePoints points.
void check_point_layers(const JsonReader& reader, const Scene& scene) {
  for (const Panel& panel : scene.panels) {
    const LayersOf<Layer> drawn = layers_of<Layer>(scene, panel);
    const std::vector<Layer>& layers = drawn.layers;
    const std::string in_panel = !drawn.own && !panel.pointer.empty() ? " (in the panel at " + panel.pointer + ")" : "";
    for (std::size_t i = 0; i < layers.size(); ++i) {
      const std::string at = drawn.pointer(i);
      const auto* curve = std::get_if<PointTrajectoryLayer>(&layers[i]);
      const LayerDraws draws = kind_of(arrow_layer_table(), layers[i]).draws;
      const auto* given = std::get_if<PointKeys>(&panel.keys);
      if (given == nullptr && draws == LayerDraws::points) {
        reader.fail(at + "/type",
                    "a point-trajectory draws a curve through timed \"points\"; this panel has "
                    "keyframes" +
                        in_panel);
      }
      if (given != nullptr && draws == LayerDraws::keyframes) {
        reader.fail(at + "/type",
                    "this layer draws a motion of keyframes, and the panel has timed \"points\": "
                    "draw them with \"point-trajectory\" (labels and legends are fine too)" +
                        in_panel);
      }
      if (curve != nullptr && curve->curve != PointCurve::pita && given != nullptr &&
          given->points.size() > static_cast<std::size_t>(limits::kMaxNevillePoints)) {
        reader.fail(at + "/curve",
                    fmt::format("the {} curve takes at most {} points (got {}){}", info(curve->curve).name,
                                limits::kMaxNevillePoints, given->points.size(), in_panel));
      }
    }
  }
}

constexpr std::array<std::string_view, 19> kSceneFields = {
    "$schema", "description", "method", "keyframes", "points", "chain",  "samples", "options", "title",    "canvas",
    "layers",  "panels",      "golden", "claims",    "lint",   "timing", "shapes",  "handle",  "animation"};

// A "shapes" layer draws the scene's shapes, which it must have.
void check_shape_layers(const JsonReader& reader, const Scene& scene) {
  if (!figure_of<KeyframeKeys>(scene).shapes.empty()) return;
  for (const Panel& panel : scene.panels) {
    const LayersOf<Layer> drawn = layers_of<Layer>(scene, panel);
    for (std::size_t i = 0; i < drawn.layers.size(); ++i) {
      if (std::holds_alternative<ShapesLayer>(drawn.layers[i])) {
        reader.fail(drawn.pointer(i) + "/type",
                    "a \"shapes\" layer draws the scene's \"shapes\" carried by the handle, and the scene has none");
      }
    }
  }
}

// An option that no motion it applies to reads would change nothing:
// refused, naming the methods that read it, as a layer's are
// (render/panel_drawing.cpp). The scene's "options" apply to its own motion
// (what pita eval prints) and to every panel that does not set the option
// itself; a panel's to that panel.
void check_options_read(const JsonReader& reader, const Json& document, const Scene& scene) {
  const Json* panels = JsonReader::member(document, "panels");
  for (const MethodOptionKey& key : kMethodOptionKeys) {
    const auto given = [&](const Json& object) {
      const Json* options = JsonReader::member(object, "options");
      return options != nullptr && JsonReader::member(*options, std::string(key.name)) != nullptr;
    };
    if (given(document)) {
      std::vector<const MotionKeys*> applied{&scene.keys};
      for (std::size_t k = 0; panels != nullptr && k < scene.panels.size(); ++k) {
        if (!given((*panels)[k])) applied.push_back(&scene.panels[k].keys);
      }
      if (std::none_of(applied.begin(), applied.end(),
                       [&](const MotionKeys* keys) { return keys_read_option(*keys, key.option); })) {
        std::vector<Method> methods;
        for (const MotionKeys* keys : applied) methods.push_back(track_method(*keys)->method);
        reader.fail("/options/" + std::string(key.name), unread_option_reason(methods, key.name, key.option));
      }
    }
    for (std::size_t k = 0; panels != nullptr && k < scene.panels.size(); ++k) {
      if (!(*panels)[k].is_object() || !given((*panels)[k]) || keys_read_option(scene.panels[k].keys, key.option)) {
        continue;
      }
      const Method method = track_method(scene.panels[k].keys)->method;
      reader.fail(scene.panels[k].pointer + "/options/" + std::string(key.name),
                  unread_option_reason(std::span(&method, 1), key.name, key.option));
    }
  }
}

// The motion of an arrow scene: "method", "options", "keyframes" or
// "points", "handle" and "chain"; the "shapes" the keyframes carry are read
// into the scene's figure (an ArrowFigure, the default).
MotionKeys read_track_keys(const JsonReader& reader, const Json& document, Scene& scene) {
  const Json* method = JsonReader::member(document, "method");
  if (method == nullptr) reader.fail("/method", "missing required field (a method such as \"P6\")");
  TrackMethod track;
  track.method = reader.method(*method, "/method");
  if (const Json* options = JsonReader::member(document, "options")) {
    track.options = reader.options(*options, "/options", MethodOptions{});
  }

  const Json* keyframes = JsonReader::member(document, "keyframes");
  const Json* points = JsonReader::member(document, "points");
  if (keyframes != nullptr && points != nullptr) {
    reader.fail("/points", "give either \"keyframes\" (arrows) or \"points\" (timed points), not both");
  }
  if (keyframes == nullptr && points == nullptr) {
    reader.fail("/keyframes", "missing required field (an array of keyframes, or \"points\")");
  }
  MotionKeys keys;
  KeyframeKeys arrows;
  static_cast<TrackMethod&>(arrows) = track;
  if (keyframes != nullptr) {
    arrows.keyframes =
        reader.keyframes(*keyframes, "/keyframes", track.method, &arrows.keyframes_to, track.options.knots);
  }
  // Shapes carried by the frames (Sec. 7.1): drawn in the handle's frame.
  if (const Json* shapes = JsonReader::member(document, "shapes")) {
    if (points != nullptr) {
      reader.fail("/shapes",
                  "shapes are carried by keyframe arrows (a \"handle\" and \"shapes\" layers); a scene of "
                  "\"points\" has none to carry them");
    }
    figure_of<KeyframeKeys>(scene).shapes =
        detail::read_shapes(reader, *shapes, "/shapes", FigureTraits<Affine2>::unit_simplex());
  }
  if (const Json* handle = JsonReader::member(document, "handle")) {
    if (points != nullptr)
      reader.fail("/handle", "a handle carries shapes with keyframe arrows; a scene of \"points\" has none");
    arrows.given_handle = reader.arrow(*handle, "/handle");
  }
  if (points != nullptr) {
    PointKeys curve;
    static_cast<TrackMethod&>(curve) = track;
    curve.points = reader.points(*points, "/points");
    if (JsonReader::member(document, "timing") != nullptr) {
      reader.fail("/timing", "timing paces keyframes and poses; a scene of \"points\" has none");
    }
    keys = std::move(curve);
  } else {
    keys = std::move(arrows);
  }
  if (const Json* chain = JsonReader::member(document, "chain")) {
    track_method(keys)->chain = reader.chain(*chain, "/chain");
    check_track_chain(reader, keys, "/chain");
  }
  return keys;
}

}  // namespace

Scene read_arrow_scene(const JsonReader& reader, const Json& document) {
  reader.check_fields(document, "", kSceneFields);

  Scene scene;
  scene.path = reader.file();
  if (const Json* schema = JsonReader::member(document, "$schema")) reader.string(*schema, "/$schema");
  if (const Json* description = JsonReader::member(document, "description")) {
    scene.description = reader.string(*description, "/description");
  }

  scene.keys = read_track_keys(reader, document, scene);

  if (const Json* samples = JsonReader::member(document, "samples")) {
    scene.samples = reader.integer(*samples, "/samples", kMinSamples, kMaxSamples);
  }
  if (const Json* timing = JsonReader::member(document, "timing")) {
    scene.timing = detail::read_timing(reader, *timing, "/timing");
  }

  // The figure (docs/reference/render.md "Figures"); `pita eval` ignores it.
  if (const Json* title = JsonReader::member(document, "title")) {
    scene.title = reader.string(*title, "/title");
  }
  if (const Json* canvas = JsonReader::member(document, "canvas")) {
    scene.canvas = detail::read_canvas(reader, *canvas, "/canvas");
  }
  if (const Json* layers = JsonReader::member(document, "layers")) {
    figure_of<KeyframeKeys>(scene).layers = detail::read_layers(reader, *layers, "/layers");
  } else {
    // By default a curve through timed points, else the pattern and the keyframes.
    figure_of<KeyframeKeys>(scene).layers =
        std::visit(overloaded{[](const KeyframeKeys&) {
                                return std::vector<Layer>{PatternLayer{}, KeyframesLayer{}};
                              },
                              [](const PointKeys&) { return std::vector<Layer>{PointTrajectoryLayer{}}; },
                              [](const PlanePoseKeys&) { return std::vector<Layer>{}; },   // not read here:
                              [](const SpacePoseKeys&) { return std::vector<Layer>{}; }},  // pose scenes
                   scene.keys);
  }
  if (const Json* panels = JsonReader::member(document, "panels")) {
    scene.panels = read_panels(reader, *panels, "/panels", scene);
  } else {
    scene.panels = {scene_panel(scene, "")};
  }
  check_point_layers(reader, scene);
  check_shape_layers(reader, scene);
  check_options_read(reader, document, scene);
  const bool moving = std::any_of(scene.panels.begin(), scene.panels.end(), [](const Panel& panel) {
    const auto* given = std::get_if<KeyframeKeys>(&panel.keys);
    return given != nullptr && !given->keyframes_to.empty();
  });
  read_scene_tail<Layer>(reader, document, scene, moving);
  return scene;
}

}  // namespace pita::scene::detail
