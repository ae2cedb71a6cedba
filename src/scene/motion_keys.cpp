#include "scene/motion_keys.hpp"

#include <algorithm>

#include "core/overloaded.hpp"

namespace pita::scene {

std::string method_id(const MotionKeys& keys) {
  return std::visit([](const auto& given) { return std::string(info(given.method).id); }, keys);
}

const char* keys_field(const MotionKeys& keys) {
  return std::visit(
      overloaded{[](const KeyframeKeys&) { return "/keyframes"; }, [](const PointKeys&) { return "/points"; },
                 [](const PlanePoseKeys&) { return "/poses"; }, [](const SpacePoseKeys&) { return "/poses"; }},
      keys);
}

std::string_view kind_name(const MotionKeys& keys) {
  return std::visit(overloaded{[](const KeyframeKeys&) { return std::string_view("arrows"); },
                               [](const PointKeys&) { return std::string_view("points"); },
                               [](const PlanePoseKeys&) { return PoseTraits<Affine2>::kind_name; },
                               [](const SpacePoseKeys&) { return PoseTraits<Affine3>::kind_name; }},
                    keys);
}

std::vector<double> knots(const MotionKeys& keys) {
  std::vector<double> knots;
  const auto times = [&](const auto& items) {
    knots.reserve(items.size());
    for (const auto& item : items) knots.push_back(item.t);
  };
  std::visit(overloaded{[&](const KeyframeKeys& given) {
                          times(given.keyframes);
                          std::sort(knots.begin(), knots.end());  // "as-given" keyframes
                        },
                        [&](const PointKeys& given) { times(given.points); },
                        [&](const PlanePoseKeys& given) { times(given.poses); },
                        [&](const SpacePoseKeys& given) { times(given.poses); }},
             keys);
  return knots;
}

TrackMethod* track_method(MotionKeys& keys) {
  return std::visit(overloaded{[](KeyframeKeys& track) -> TrackMethod* { return &track; },
                               [](PointKeys& track) -> TrackMethod* { return &track; },
                               [](PlanePoseKeys&) -> TrackMethod* { return nullptr; },
                               [](SpacePoseKeys&) -> TrackMethod* { return nullptr; }},
                    keys);
}

const TrackMethod* track_method(const MotionKeys& keys) { return track_method(const_cast<MotionKeys&>(keys)); }

bool has_motion_keys(const MotionKeys& keys) {
  return std::visit(overloaded{[](const KeyframeKeys&) { return true; }, [](const PointKeys&) { return true; },
                               [](const PlanePoseKeys& given) { return !given.poses.empty(); },
                               [](const SpacePoseKeys& given) { return !given.poses.empty(); }},
                    keys);
}

}  // namespace pita::scene
