// The keys of one kind of a scene or panel (scene/motion_keys.hpp), for tests
// that know which kind they read: std::get throws std::bad_variant_access,
// which fails the test, when the scene holds another kind.
#pragma once

#include <type_traits>
#include <utility>
#include <variant>

#include "scene/motion_keys.hpp"

namespace pita::scene {

// Of a scene or panel that lives on, a reference; of a temporary (a scene
// just loaded), a copy.
template <class Kind, class Owner>
decltype(auto) keys_of(Owner&& owner) {
  if constexpr (std::is_lvalue_reference_v<Owner>) {
    return (std::get<Kind>(owner.keys));
  } else {
    return Kind(std::get<Kind>(owner.keys));
  }
}
template <class Owner>
decltype(auto) arrow_keys(Owner&& owner) {
  return keys_of<KeyframeKeys>(std::forward<Owner>(owner));
}
template <class Owner>
decltype(auto) point_keys(Owner&& owner) {
  return keys_of<PointKeys>(std::forward<Owner>(owner));
}
template <class Owner>
decltype(auto) plane_keys(Owner&& owner) {
  return keys_of<PlanePoseKeys>(std::forward<Owner>(owner));
}
template <class Owner>
decltype(auto) space_keys(Owner&& owner) {
  return keys_of<SpacePoseKeys>(std::forward<Owner>(owner));
}
// The PITA of keyframes or points.
template <class Owner>
decltype(auto) track_keys(Owner&& owner) {
  auto* track = track_method(owner.keys);
  if (track == nullptr) throw std::bad_variant_access();
  if constexpr (std::is_lvalue_reference_v<Owner>) {
    return (*track);
  } else {
    return TrackMethod(*track);
  }
}
// The pose method of poses of either dimension.
template <class Owner>
PoseMethod pose_method_of(const Owner& owner) {
  if (const auto* space = std::get_if<SpacePoseKeys>(&owner.keys)) return space->method;
  return std::get<PlanePoseKeys>(owner.keys).method;
}
// Whether the scene is of poses (of the plane or of space).
template <class Owner>
bool is_pose_scene(const Owner& owner) {
  return track_method(owner.keys) == nullptr;
}
template <class Owner>
int dimension_of(const Owner& owner) {
  return std::holds_alternative<SpacePoseKeys>(owner.keys) ? 3 : 2;
}

}  // namespace pita::scene
