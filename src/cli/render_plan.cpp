#include "cli/render_plan.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include <fmt/format.h>

#include "cli/usage_error.hpp"
#include "core/methods.hpp"
#include "io/input_file.hpp"
#include "scene/image_file.hpp"
#include "scene/limits.hpp"
#include "scene/located_error.hpp"
#include "text/list.hpp"

namespace pita::cli {

namespace fs = std::filesystem;

namespace {

// The CSS pixel: PNGs are drawn at --dpi / 96 times the canvas size.
constexpr double kCssDpi = 96.0;

std::vector<render::Format> parse_formats(const std::string& text) {
  std::vector<render::Format> formats;
  text::for_each_item(text, [&](std::string_view item) {
    const auto format = render::format_from_name(item);
    if (!format) {
      throw UsageError(
          fmt::format("--format: \"{}\" is not a format (use svg, png or pdf, "
                      "comma-separated: --format svg,png)",
                      item));
    }
    if (std::find(formats.begin(), formats.end(), *format) == formats.end()) formats.push_back(*format);
  });
  return formats;
}

// Two scenes that would write the same file (a/x.json and b/x.json, or one
// scene given twice) are refused before anything is written: the second would
// silently replace the first, and numbering one of them would make the names
// unpredictable for scripts.
void refuse_shared_outputs(const RenderOptions& options, const std::vector<render::Format>& formats) {
  // The first format is enough: every scene writes the same formats.
  std::map<fs::path, const std::string*> writer;
  for (const std::string& path : options.scene_paths) {
    const fs::path target = targets_for(options, path, formats, false).front().path;
    const auto [it, inserted] = writer.emplace(target, &path);
    if (inserted) continue;
    const std::string& first = *it->second;
    std::error_code ignored;
    if (first == path || fs::equivalent(first, path, ignored)) {
      throw UsageError(fmt::format("{} is given twice: it would write {} twice{}", path, target.string(),
                                   first == path ? "" : fmt::format(" (also as {})", first)));
    }
    throw UsageError(
        fmt::format("{} and {} would both write {} (outputs are named by the scene "
                    "file's name); rename one, or render them into different directories",
                    first, path, target.string()));
  }
}

}  // namespace

std::vector<Target> targets_for(const RenderOptions& options, const std::string& scene_path,
                                const std::vector<render::Format>& formats, bool single_file) {
  if (single_file) return {{formats.front(), options.output}};
  std::vector<Target> targets;
  const std::string stem = fs::path(scene_path).stem().string();
  for (const render::Format format : formats) {
    targets.push_back({format, fs::path(options.output) / (stem + "." + std::string(render::extension(format)))});
  }
  return targets;
}

RenderPlan plan_render(const RenderOptions& options) {
  RenderPlan plan;
  if (options.method && find_method_entry(*options.method) == nullptr) {
    throw UsageError(fmt::format("--method: {}", unknown_method_reason(*options.method)));
  }
  const std::optional<render::Format> by_extension = render::format_from_name(
      fs::path(options.output).extension().string().substr(fs::path(options.output).has_extension() ? 1 : 0));
  plan.single_file = by_extension.has_value();
  // "-o four.jpg": an extension pita does not write is a mistake, not a
  // directory to create (an existing directory of that name is used).
  const fs::path out(options.output);
  std::error_code error;
  if (!plan.single_file && out.has_extension() && out.extension() != "." && !fs::is_directory(out, error)) {
    throw UsageError(fmt::format(
        "-o {}: pita render writes .svg, .png or .pdf files (\"{}\" is none of them), or a directory without an "
        "extension that receives one file per scene",
        options.output, out.extension().string()));
  }
  if (options.formats) plan.formats = parse_formats(*options.formats);
  if (plan.single_file) {
    if (options.scene_paths.size() != 1) {
      throw UsageError(
          fmt::format("-o {}: a single output file takes one scene (got {}); give a "
                      "directory to render several",
                      options.output, options.scene_paths.size()));
    }
    if (!plan.formats.empty() && (plan.formats.size() != 1 || plan.formats.front() != *by_extension)) {
      throw UsageError(fmt::format("--format {} contradicts the extension of -o {}", *options.formats, options.output));
    }
    plan.formats = {*by_extension};
  } else if (plan.formats.empty()) {
    plan.formats = {render::Format::svg};
  }
  if (!std::isfinite(options.budget))
    throw UsageError(fmt::format("--budget: must be a number (got {})", options.budget));
  if (options.at && !(std::abs(*options.at) <= scene::kMaxKeyframeValue)) {
    throw UsageError(fmt::format("--at: the time must be a finite number within +-{:g} (got {})",
                                 scene::kMaxKeyframeValue, *options.at));
  }
  if (options.dpi) plan.scale = *options.dpi / kCssDpi;
  if (options.scale) plan.scale = *options.scale;
  if (!(plan.scale >= render::kMinScale && plan.scale <= render::kMaxScale)) {
    throw UsageError(fmt::format("{}: the PNG scale must be between {} and {} (got {})",
                                 options.dpi ? "--dpi" : "--scale", render::kMinScale, render::kMaxScale, plan.scale));
  }
  if (!plan.single_file) refuse_shared_outputs(options, plan.formats);
  return plan;
}

void refuse_an_input(const scene::Scene& scene, const fs::path& output) {
  std::vector<std::pair<fs::path, std::string>> inputs{{scene.path, "the scene file"}};
  for (const fs::path& image : scene::image_files(scene)) inputs.emplace_back(image, "an image its shapes draw");
  for (const auto& [input, what] : inputs) {
    if (!io::same_file(input, output)) continue;
    throw scene::SceneError(
        scene.path, "",
        fmt::format("the output {} is {}, which it would replace: write the figure elsewhere", output.string(), what));
  }
}

}  // namespace pita::cli
