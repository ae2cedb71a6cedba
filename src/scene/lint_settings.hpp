// "lint": what `pita lint` (src/lint/) checks on a scene's figure, and the
// findings the scene accepts, each with its reason (docs/reference/lint.md "Lint").
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace pita::scene {

// The checks of the lint, by name: the one table of them (src/lint/checks.cpp
// holds one function per row, in this order; messages and the schema list
// these names).
struct LintCheckInfo {
  std::string_view name;
  std::string_view what;  // for --help, the docs and messages
};
inline constexpr std::array<LintCheckInfo, 10> kLintChecks = {{
    {"text-overlap", "two texts overlap"},
    {"text-over-data", "a text lies over the strokes, fills or images of another layer"},
    {"legend-over-data", "a legend's box lies over data"},
    {"outside", "something is drawn beyond its panel or the canvas, and is cut off"},
    {"small-content", "a panel's content fills less than \"min_content_share\" of its width and of its height"},
    {"small-motion",
     "a panel's motion (its frames) fills less than \"min_motion_share\" of its width and of its height"},
    {"short-frame", "a pattern's frame, or a pose's shape, is drawn shorter than \"min_frame_pixels\""},
    {"small-feature",
     "a claim that two drawn motions differ is about a distance drawn shorter than \"min_feature_pixels\""},
    {"same-color", "two series of a panel (keyframes, poses, two layers of one kind) share a colour"},
    {"hidden-copy", "a copy of a 3D motion is hidden by more than \"max_hidden_share\" of its area"},
}};

// One finding the scene accepts: its check, the pointer of the layer (or
// title, or panel) it names ("" = every pointer), and why.
struct LintAllow {
  std::string check;
  std::string pointer;
  std::string reason;
  std::string at;  // this entry's own pointer, "/lint/allow/0"
};

struct LintSettings {
  double min_content_share = 0.5;   // of a panel's plot area, along its longer side
  double min_motion_share = 0.5;    // the frames alone, likewise
  double min_frame_pixels = 3.0;    // the shortest frame (or pose shape's diagonal) drawn
  double min_feature_pixels = 6.0;  // a distance a claim is about (frame-distance above a bound, ...), drawn
  double max_hidden_share = 0.5;    // of a copy's area that what is painted over it may cover
  std::vector<LintAllow> allow;
};

}  // namespace pita::scene
