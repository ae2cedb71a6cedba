// The image files that scenes name ("shapes": [{"image": "x.png", "box": ...}],
// PITA Sec. 7.1): where the file is, and whether it may be read at all,
// checked when the scene is read so that a bad path is refused (exit 2)
// before anything is drawn or written. Decoding is left to cairo (render/).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/figure.hpp"
#include "scene/read_options.hpp"
#include "scene/scene.hpp"

namespace pita::scene {

// Resolves `given` (as the scene spells it) against the folder of
// `scene_file` and checks it: not empty; relative, unless
// options.allow_absolute_paths; inside the scene's folder tree once "." and
// ".." and symbolic links are resolved; an existing regular file that can be
// read; a PNG (its signature and IHDR header) of 1 to kMaxImageSide pixels a
// side. Throws std::invalid_argument with the reason.
ImageRef check_image_file(const std::string& scene_file, const std::string& given, const ReadOptions& options);

// The image files the scene's shapes name (every panel's), resolved, each
// once, in the order they first appear: what `pita watch` and `pita serve`
// watch besides the scene.
std::vector<std::filesystem::path> image_files(const Scene& scene);

}  // namespace pita::scene
