#include "scene/option_use.hpp"

#include <algorithm>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/overloaded.hpp"
#include "core/pitas/registry.hpp"

namespace pita::scene {

bool keys_read_option(const MotionKeys& keys, MethodOption option) {
  const TrackMethod* track = track_method(keys);
  if (track == nullptr) return false;
  const std::size_t length = std::visit(overloaded{[](const KeyframeKeys& k) { return k.track_length(); },
                                                   [](const PointKeys& k) { return k.track_length(); },
                                                   []<class Pose>(const PoseKeys<Pose>&) { return std::size_t{0}; }},
                                        keys);
  const bool chained =
      track->chain.has_value() || length > static_cast<std::size_t>(info(track->method).keyframe_count);
  return reads_option(track->method, option, chained);
}

std::string unread_option_reason(std::span<const Method> methods, std::string_view key, MethodOption option) {
  std::vector<std::string> readers;
  for (const MethodInfo& reader : all_methods()) {
    if (reads_option(reader.method, option, false)) readers.emplace_back(reader.id);
  }
  std::vector<std::string> names;
  for (const Method m : methods) {
    const std::string name = method_name(m);
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  const std::string who = names.size() == 1
                              ? fmt::format("{} does not read", names.front())
                              : fmt::format("none of the methods it applies to ({}) reads", fmt::join(names, ", "));
  return fmt::format("{} \"{}\", so it would change nothing here; {} read{} it", who, key, fmt::join(readers, ", "),
                     readers.size() == 1 ? "s" : "");
}

}  // namespace pita::scene
