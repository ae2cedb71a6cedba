#include "scene/motion_keys.hpp"

#include "core/overloaded.hpp"

namespace pita::scene {

std::string method_id(const MotionKeys& keys) {
  return std::visit([](const auto& given) { return std::string(info(given.method).id); }, keys);
}

const char* keys_field(const MotionKeys& keys) {
  return std::visit(overloaded{[](const KeyframeKeys&) { return "/keyframes"; },
                               [](const PointKeys&) { return "/points"; },
                               [](const PlanePoseKeys&) { return "/poses"; },
                               [](const SpacePoseKeys&) { return "/poses"; }},
                    keys);
}

TrackMethod* track_method(MotionKeys& keys) {
  return std::visit(overloaded{[](TrackMethod& track) -> TrackMethod* { return &track; },
                               [](PlanePoseKeys&) -> TrackMethod* { return nullptr; },
                               [](SpacePoseKeys&) -> TrackMethod* { return nullptr; }},
                    keys);
}

const TrackMethod* track_method(const MotionKeys& keys) { return track_method(const_cast<MotionKeys&>(keys)); }

bool has_motion_keys(const MotionKeys& keys) {
  return std::visit(overloaded{[](const KeyframeKeys&) { return true; },
                               [](const PointKeys&) { return true; },
                               [](const PlanePoseKeys& given) { return !given.poses.empty(); },
                               [](const SpacePoseKeys& given) { return !given.poses.empty(); }},
                    keys);
}

}  // namespace pita::scene
