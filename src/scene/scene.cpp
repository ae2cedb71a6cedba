#include "scene/scene.hpp"

#include <algorithm>
#include <array>
#include <set>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "core/overloaded.hpp"
#include "core/pose_traits.hpp"
#include "scene/json_reader.hpp"
#include "scene/json_text.hpp"
#include "scene/limits.hpp"
#include "scene/pose_reader.hpp"
#include "scene/scene_readers.hpp"
#include "scene/title_template.hpp"

namespace pita::scene {

namespace {

using detail::element_pointer;
using detail::Interval;
using detail::Json;
using detail::JsonReader;
using detail::keyframe_count_reason;
using detail::value_text;
}  // namespace

Panel scene_panel(const Scene& scene, std::string pointer) {
  Panel panel;
  panel.keys = scene.keys;
  // The scene's shapes, and no layers of its own.
  panel.figure = std::visit(overloaded{[](const ArrowFigure& figure) -> PanelFigure {
                                         return ArrowPanelFigure{std::nullopt, figure.shapes};
                                       },
                                       []<class Pose>(const PoseFigure<Pose>& figure) -> PanelFigure {
                                         return PosePanelFigure<Pose>{std::nullopt, figure.shapes};
                                       }},
                            scene.figure);
  panel.timing = scene.timing;
  panel.samples = scene.samples.value_or(kDefaultFigureSamples);
  panel.samples_pointer = scene.samples ? "/samples" : "";
  panel.pointer = std::move(pointer);
  panel.motion_pointer = keys_field(scene.keys);
  return panel;
}

Scene load_scene(const std::filesystem::path& path, const ReadOptions& options) {
  return parse_scene(read_input_file(path, kMaxSceneFileBytes, "scene file"), path.string(), options);
}

std::vector<std::string> panels_with_own_methods(const Json& document) {
  const auto panels = document.find("panels");
  if (!document.is_object() || panels == document.end() || !panels->is_array() || panels->empty()) return {};
  std::vector<std::string> own;
  for (std::size_t k = 0; k < panels->size(); ++k) {
    const Json& panel = (*panels)[k];
    if (panel.is_string()) {
      own.push_back(fmt::format("/panels/{}", k));
    } else if (panel.is_object() && panel.contains("method")) {
      own.push_back(fmt::format("/panels/{}/method", k));
    } else {
      return {};  // this panel draws the scene's method
    }
  }
  return own;
}

Scene parse_scene(std::string_view text, std::string source_name, const ReadOptions& options) {
  Json document = parse_json(text, source_name);
  const JsonReader reader(std::move(source_name), options);
  if (!document.is_object()) {
    reader.fail("", "a scene must be a JSON object (got " + value_text(document) + ")");
  }
  if (options.method) {
    if (const std::vector<std::string> own = panels_with_own_methods(document); !own.empty()) {
      reader.fail("/method", fmt::format("{}, given in place of the scene's method, would be drawn by no panel: each "
                                         "sets its own ({}); change a panel's \"method\"",
                                         *options.method, fmt::join(own, ", ")));
    }
    document["method"] = *options.method;
  }
  Scene scene = detail::is_pose_scene(document) ? detail::read_pose_scene(reader, document)
                                                : detail::read_arrow_scene(reader, document);
  scene.title = detail::expand_title(reader, document, scene.title, "/title");
  for (Panel& panel : scene.panels) {
    panel.title = detail::expand_title(reader, document, panel.title, panel.pointer + "/title");
  }
  const bool panels_agree = std::all_of(scene.panels.begin(), scene.panels.end(),
                                        [](const Panel& panel) { return figure_agrees(panel.keys, panel.figure); });
  if (!figure_agrees(scene.keys, scene.figure) || !panels_agree) {
    throw std::logic_error("the scene reader gave " + scene.path + " figure data of another kind than its keys");
  }
  return scene;
}

const std::vector<ShapeOutline>& outlines_of(const Panel& panel) {
  static const std::vector<ShapeOutline> kNone;
  return std::visit(
      overloaded{
          [](const ArrowPanelFigure& figure) -> const std::vector<ShapeOutline>& { return figure.shapes; },
          [](const PosePanelFigure<Affine2>& figure) -> const std::vector<ShapeOutline>& { return figure.shapes; },
          [](const PosePanelFigure<Affine3>&) -> const std::vector<ShapeOutline>& { return kNone; }},
      panel.figure);
}

bool figure_agrees(const MotionKeys& keys, const SceneFigure& figure) {
  return std::visit([&]<class Keys>(const Keys&) { return std::holds_alternative<FigureOf<Keys>>(figure); }, keys);
}

bool figure_agrees(const MotionKeys& keys, const PanelFigure& figure) {
  return std::visit([&]<class Keys>(const Keys&) { return std::holds_alternative<PanelFigureOf<Keys>>(figure); }, keys);
}

Method resolve_method(std::string_view name) {
  if (const Method* method = find_method_of<Method>(name)) return *method;
  throw std::invalid_argument(pita::unknown_method_reason(name, is_method_of<Method>));
}

namespace {

// The arrow method of `keys` replaced by `method` (the scene's keyframes or
// points must be enough for it); pose keys are refused.
void replace_method(const Scene& scene, MotionKeys& keys, Method method) {
  const auto arrows = [&](TrackMethod& track, std::size_t count, bool keyframes) {
    if (keyframes && count < static_cast<std::size_t>(info(method).keyframe_count)) {
      throw SceneError(scene.path, "/keyframes", keyframe_count_reason(method, count));
    }
    const JsonReader reader(scene.path);
    reader.check_chain(method, track.chain, count, "/chain");
    track.method = method;
  };
  const auto poses = [&](const auto&) {
    throw SceneError(scene.path, "/method",
                     fmt::format("method {} interpolates arrows; this is a pose scene (methods: {})", info(method).id,
                                 method_ids(is_method_of<PoseMethod>)));
  };
  std::visit(overloaded{[&](KeyframeKeys& given) { arrows(given, given.track_length(), true); },
                        [&](PointKeys& given) { arrows(given, given.track_length(), false); },
                        [&](PlanePoseKeys& given) { poses(given); }, [&](SpacePoseKeys& given) { poses(given); }},
             keys);
}

// The pose method of `keys` replaced by `method`; arrow keys are refused.
template <class Pose>
void replace_pose_method(const Scene& scene, PoseKeys<Pose>& keys, PoseMethod method) {
  const PoseMethodInfo& about = info(method);
  if (in_space_v<Pose> && !about.in_space) {
    throw SceneError(scene.path, "/dimension",
                     fmt::format("method {} moves poses of the plane only; this is a 3D scene", about.id));
  }
  if (keys.poses.empty()) throw SceneError(scene.path, "/poses", "the scene has no poses to interpolate");
  const auto count = static_cast<int>(keys.poses.size());
  if (count < about.min_poses || count > about.max_poses) {
    throw SceneError(scene.path, "/poses", detail::pose_count_reason(method, keys.poses.size()));
  }
  keys.method = method;
}

// The pose method of `keys` replaced by `method`; arrow keys are refused.
void replace_method(const Scene& scene, MotionKeys& keys, PoseMethod method) {
  const auto arrows = [&](const auto&) {
    throw SceneError(scene.path, "/method",
                     fmt::format("method {} interpolates poses; this scene has keyframes (arrows)", info(method).id));
  };
  std::visit(overloaded{[&](KeyframeKeys& given) { arrows(given); }, [&](PointKeys& given) { arrows(given); },
                        [&](PlanePoseKeys& given) { replace_pose_method(scene, given, method); },
                        [&](SpacePoseKeys& given) { replace_pose_method(scene, given, method); }},
             keys);
}

}  // namespace

Scene with_method(Scene scene, std::string_view name) {
  const MethodFilter of_kind =
      std::visit(overloaded{[](const KeyframeKeys&) -> MethodFilter { return is_method_of<Method>; },
                            [](const PointKeys&) -> MethodFilter { return is_method_of<Method>; },
                            [](const PlanePoseKeys&) -> MethodFilter { return is_method_of<PoseMethod>; },
                            [](const SpacePoseKeys&) -> MethodFilter { return is_method_of<PoseMethod>; }},
                 scene.keys);
  const MethodEntry* entry = find_method_entry(name, of_kind);
  if (entry == nullptr) entry = find_method_entry(name);
  if (entry == nullptr) throw std::invalid_argument(pita::unknown_method_reason(name));
  const AnyMethod method = entry->method;
  return with_method(std::move(scene), method);
}

std::string no_sam_reason(const NoSamBetweenPoses& error, PoseMethod method) {
  if (!error.where().empty()) {
    return fmt::format("{} ({}, method {})", error.what(), error.where(), info(method).id);
  }
  return fmt::format("{} (poses {} and {}, method {})", error.what(), error.first(), error.first() + 1,
                     info(method).id);
}

template <class LayerType>
LayersOf<LayerType> layers_of(const Scene& scene, const Panel& panel) {
  return std::visit(
      [&]<class Keys>(const Keys&) -> LayersOf<LayerType> {
        const FigureOf<Keys>& figure = figure_of<Keys>(scene);
        const auto& own = figure_of<Keys>(panel).layers;
        if constexpr (std::is_same_v<typename decltype(figure.layers)::value_type, LayerType>) {
          if (own) return {*own, true, panel.pointer};
          return {figure.layers, false, ""};
        } else {
          throw std::logic_error("layers_of: the panel at \"" + panel.pointer + "\" draws layers of another kind");
        }
      },
      panel.keys);
}
template LayersOf<Layer> layers_of(const Scene&, const Panel&);
template LayersOf<PoseLayer> layers_of(const Scene&, const Panel&);

Scene with_method(Scene scene, const AnyMethod& method) {
  std::visit([&](auto chosen) { replace_method(scene, scene.keys, chosen); }, method);
  // The panel that is the scene itself follows it; panels of their own keep theirs.
  for (Panel& panel : scene.panels) {
    if (panel.pointer.empty()) panel.keys = scene.keys;
  }
  return scene;
}

}  // namespace pita::scene
