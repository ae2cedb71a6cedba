// Video output of `pita animate` (OUT.mp4, OUT.webm): raw frames piped into
// Debian's ffmpeg, drawn on every core and written in order, into a hidden
// temporary that is verified (ffmpeg's stderr, the file's size, ffprobe when
// it sits beside ffmpeg) before it is renamed into place
// (docs/reference/animate.md "Animation").
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "animate/output.hpp"
#include "animate/timeline.hpp"
#include "motion/stage.hpp"
#include "render/figure.hpp"
#include "scene/scene.hpp"

namespace pita::animate {

// The ffmpeg that writes videos, from what a front end read in its environment
// (animate reads none): `given` (PITA_FFMPEG) when set, if it is executable;
// else "ffmpeg" in one of the directories of `search_path` (PATH; when unset,
// /usr/bin:/bin); "" when there is none.
std::string find_ffmpeg(std::optional<std::string_view> given, std::optional<std::string_view> search_path);

// Writes request.out. `stage` and `layers`: the scene's motions for a
// "motion" timeline and the layers drawn once (frame_figure), else nullptr. Throws AnimationError (no ffmpeg, exit 2),
// RenderError, OutputError (exit 3: ffmpeg failed or said an error, the file
// is empty or unreadable); on a signal removes its temporary and exits.
std::filesystem::path write_video(const scene::Scene& scene, const Timeline& timeline, const Request& request,
                                  const motion::Stage* stage, render::StaticLayers* layers,
                                  const std::vector<render::PanelPlacement>& placements);

}  // namespace pita::animate
