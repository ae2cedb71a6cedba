// Goldens: the expected outputs of each scene, golden/<name>/<name>.{data.json,
// svg, png} (golden/ mirrors scenes/), and the comparison of a fresh
// rendering, made in memory, with them.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/claims.hpp"
#include "golden/image_compare.hpp"
#include "golden/number_compare.hpp"
#include "golden/svg_compare.hpp"
#include "lint/lint.hpp"
#include "scene/scene.hpp"

namespace pita::golden {

// PNGs are compared tolerantly (a newer cairo, pixman or FreeType may move
// antialiasing by a level or two); the numbers are what catch a moved frame.
inline constexpr int kDefaultChannelTolerance = 16;      // of 255
inline constexpr double kDefaultDifferingShare = 0.002;  // of the pixels

// Golden files are read as hostile input: at most this many bytes each
// (a figure within the render budget writes far less).
inline constexpr std::size_t kMaxGoldenFileBytes = std::size_t{256} << 20;

struct Tolerances {
  double numbers = kDefaultNumberTolerance;  // relative to the panel's extent
  double svg = kDefaultSvgTolerance;         // pixels
  ImageTolerance image{kDefaultChannelTolerance, kDefaultDifferingShare};
};

// The three golden files of a scene, as bytes.
// Scenes with an "animation" also keep a few frames of it (docs/explanation/performance.md
// "Animation"): frames 1, N/2 + 1 and N of the scene's own timeline, as
// drawn by `pita render --at t_k`, in <name>.frame-0001.png, ...
struct Outputs {
  std::string data;  // figure_data_text
  std::string svg;
  std::string png;
  std::vector<std::pair<std::string, std::string>> frames;  // (suffix ".frame-0061.png", PNG bytes)
  std::vector<analysis::ClaimOutcome> claims;               // the scene's "claims", measured (not a golden file)
  lint::Report lint;                                        // the legibility lint of the figure (not a golden file)
};

enum class FileKind { data, svg, png };
inline constexpr FileKind kFileKinds[] = {FileKind::data, FileKind::svg, FileKind::png};
std::string_view suffix(FileKind kind);  // ".data.json", ".svg", ".png"

// Every golden file of the outputs: the three of kFileKinds, then the frames.
struct GoldenFile {
  FileKind kind;
  std::string suffix;        // ".png", ".frame-0061.png"
  const std::string* bytes;  // into the Outputs
};

// golden_dir/<name>/<name><suffix>
std::filesystem::path golden_path(const std::filesystem::path& golden_dir, const std::string& name, FileKind kind);
std::filesystem::path golden_path(const std::filesystem::path& golden_dir, const std::string& name,
                                  const std::string& suffix);
std::vector<GoldenFile> golden_files(const Outputs& outputs);

// The scene's name: its file name without ".json".
std::string scene_name(const std::filesystem::path& scene_path);

// Loads, renders and serialises a scene. Throws scene::SceneError or
// render::RenderError for a bad scene.
Outputs render_outputs(const std::filesystem::path& scene_path);

enum class Verdict { match, differs, missing };

struct FileCheck {
  FileKind kind;
  std::filesystem::path golden;
  Verdict verdict = Verdict::match;
  std::string detail;    // what differs, for people
  std::string expected;  // golden bytes ("" when missing)
  std::string actual;    // fresh bytes
  std::string diff_png;  // PNG highlighting differing pixels (png only)
};

struct SceneCheck {
  std::string scene_path;
  std::string name;
  std::vector<FileCheck> files;
  std::vector<analysis::ClaimOutcome> claims;    // every claim of the scene, in order
  lint::Report lint;                             // the lint's findings (docs/reference/lint.md "Lint")
  bool matches() const;                          // every golden file matches
  bool claims_hold() const;                      // every claim holds
  bool legible() const { return lint.clean(); }  // every finding of the lint accepted by the scene
  bool passes() const { return matches() && claims_hold() && legible(); }
};

// Tolerances asked for (`pita check --number-tolerance ...`, Python's
// Scene.check keywords), each within its range: unset ones take the scene's
// "golden" field, else the defaults.
struct ToleranceOverrides {
  std::optional<double> numbers;        // [0, 1]
  std::optional<double> svg;            // [0, 1000]
  std::optional<int> pixel;             // [0, 255]
  std::optional<double> max_differing;  // [0, 1]
};
Tolerances tolerances_of(const scene::Scene& scene, const ToleranceOverrides& given);

// Throws SceneError/RenderError (bad scene) and GoldenError (a golden file
// that cannot be read or decoded).
SceneCheck check_scene(const std::filesystem::path& scene_path, const std::filesystem::path& golden_dir,
                       const Tolerances& tolerances);

// How a fresh output differs from its golden, in a line ("unchanged", "new",
// "changed: 312 pixels (0.03%)", ...). Throws GoldenError, naming the file,
// for a golden that cannot be read, is too large, or has the wrong shape.
FileCheck compare_file(FileKind kind, const std::filesystem::path& golden, const std::string& actual,
                       const Tolerances& tolerances);

}  // namespace pita::golden
