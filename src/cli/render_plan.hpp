// What `pita render`'s outputs will be, decided before any scene is read:
// the formats, the PNG scale and the files (-o, --format, --dpi, --scale),
// refusing outputs that two scenes would share, and, once a scene is read,
// an output that is one of its inputs.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "cli/render.hpp"
#include "render/figure.hpp"
#include "scene/scene.hpp"

namespace pita::cli {

// What -o, --format, --dpi and --scale ask for.
struct RenderPlan {
  std::vector<render::Format> formats;
  double scale = 1.0;
  bool single_file = false;  // -o names one file (by its extension), else a directory
};

// Throws UsageError (usage_error.hpp): a bad value, options that contradict
// each other, two scenes that would write the same file.
RenderPlan plan_render(const RenderOptions& options);

// Where each scene's figures go: (format, path) pairs.
struct Target {
  render::Format format;
  std::filesystem::path path;
};

// In a directory, a file is named by the scene file's stem only (its last path
// component less the extension: never a path, and nothing from inside the
// JSON), so that it cannot land outside OUT whatever the scene's path is.
std::vector<Target> targets_for(const RenderOptions& options, const std::string& scene_path,
                                const std::vector<render::Format>& formats, bool single_file);

// An output never replaces an input of the same run: the scene file or an
// image its shapes draw (`-o images/picture.png` beside a scene that draws
// it would replace the picture, and pita watch would render in a loop).
// Throws scene::SceneError naming the output and what it is.
void refuse_an_input(const scene::Scene& scene, const std::filesystem::path& output);

}  // namespace pita::cli
