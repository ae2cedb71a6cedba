// What a layer costs to draw, in units of about one frame of a plain method
// (render/budget.hpp): a visitor over the layers of a panel, one overload per
// layer kind, each defined beside the kind's drawer in
// src/render/layers/<kind>.cpp. Internal to src/render/.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "core/keyframe.hpp"
#include "render/budget.hpp"
#include "scene/scene.hpp"

namespace pita::render::detail {

class LayerCost {
 public:
  LayerCost(const scene::Scene& scene, const scene::Panel& panel, std::string layer, FigureCost& cost)
      : scene_(scene), panel_(panel), layer_(std::move(layer)), cost_(cost) {}

  // One overload per layer struct of Layer and PoseLayer (the compiler refuses
  // a kind without one), each defined in its kind's src/render/layers/<kind>.cpp.
  void operator()(const scene::PatternLayer& layer);
  void operator()(const scene::StrokeLayer& layer);
  void operator()(const scene::DiscrepancyLayer& layer);
  void operator()(const scene::BannerLayer& layer);
  void operator()(const scene::KeyframesLayer& layer);
  void operator()(const scene::TrajectoryLayer& layer);
  void operator()(const scene::PointTrajectoryLayer& layer);
  void operator()(const scene::LabelLayer& layer);
  void operator()(const scene::LegendLayer& layer);
  void operator()(const scene::MeasuresLayer& layer);
  void operator()(const scene::HandleLayer& layer);
  void operator()(const scene::PropertyTableLayer& layer);
  void operator()(const scene::VectorsLayer& layer);
  void operator()(const scene::FixedPointsLayer& layer);
  void operator()(const scene::GuessesLayer& layer);
  void operator()(const scene::CompareLayer& layer);
  void operator()(const scene::PlotLayer& layer);
  void operator()(const scene::ShapesLayer& layer);
  void operator()(const scene::VersusLayer& layer);
  void operator()(const scene::PosesLayer& layer);
  void operator()(const scene::VelocitiesLayer& layer);
  void operator()(const scene::FieldLayer& layer);
  void operator()(const scene::PathsLayer& layer);
  void operator()(const scene::PatchLayer& layer);
  void operator()(const scene::AraLayer& layer);
  void operator()(const scene::SweptLayer& layer);
  void operator()(const scene::ExistenceLayer& layer);
  void operator()(const scene::Sam3dExistenceLayer& layer);

 private:
  // A layer drawn at each of its frames (`samples`, else the panel's):
  // `per_frame` units each, plus what a frame of the panel's motion costs.
  void frames(const std::optional<int>& samples, const char* what, double per_frame);
  // The points of the body drawn (shape points; in 3D every vertex and face corner).
  double shape_points() const;
  // The body drawn once: a shape per outline (per face in 3D) and its points.
  double shapes_units() const;
  // The shadows of a 3D scene's solids (none without "shadow", nor in the plane).
  double shadow_units() const;
  // The panel's keyframes (none for the other kinds, which draw no arrow layers).
  const std::vector<Keyframe>& keyframes() const;
  void add(std::string pointer, std::string what, double units) {
    cost_.units += units;
    cost_.parts.push_back({std::move(pointer), layer_, std::move(what), units});
  }

  const scene::Scene& scene_;
  const scene::Panel& panel_;
  std::string layer_;
  FigureCost& cost_;
};

}  // namespace pita::render::detail
