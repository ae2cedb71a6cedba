// Reading "timing" (docs/reference/scene-format.md "Timing"). Internal to src/scene/.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "scene/json_reader.hpp"
#include "scene/timing.hpp"

namespace pita::scene::detail {

// The names of a tracked point ("point" of a trajectory, "arc_length").
inline constexpr std::array<std::string_view, 3> kPointNames = {"p", "q", "mid"};
inline constexpr std::array<TrackedPoint, 3> kPoints = {TrackedPoint::start, TrackedPoint::end, TrackedPoint::middle};

// {"ease": ..., "arc_length": "p" | "q" | "mid", "per": "motion" | "span"},
// every field optional. The ease is a name ("ease-in-out"), a CSS
// "cubic-bezier(x1, y1, x2, y2)", {"sine": {"k1": .., "k2": ..}} or
// {"parabolic": {"t1": .., "t2": ..}}.
Timing read_timing(const JsonReader& reader, const Json& value, const std::string& pointer);

// The ease alone (also the value of "ease").
Ease read_ease(const JsonReader& reader, const Json& value, const std::string& pointer);

}  // namespace pita::scene::detail
