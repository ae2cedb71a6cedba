// "timing": how a scene's (or panel's) time runs through its motion (docs/reference/scene-format.md
// "Timing"; the chapter's speed control, docs/paper-notes.md N20). Resolved:
// the ease is looked up and its parameters checked.
#pragma once

#include <optional>
#include <string>

#include "core/ease.hpp"
#include "core/time_warp.hpp"

namespace pita::scene {

// Which point of a frame a trajectory follows, or arc length measures.
enum class TrackedPoint { start, end, middle };  // "p", "q", "mid"

struct Timing {
  Ease ease;                               // "ease": default linear
  std::optional<TrackedPoint> arc_length;  // "arc_length": reparameterise by this point's path
  WarpSpan per = WarpSpan::motion;         // "per": "motion" | "span"
  std::string pointer;                     // JSON Pointer of "timing" ("" when not given)

  // The motion's time is the scene's (no "timing", or linear without arc length).
  bool is_identity() const { return ease.kind == EaseKind::linear && !arc_length; }
};

}  // namespace pita::scene
