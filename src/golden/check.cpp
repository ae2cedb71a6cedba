#include "golden/check.hpp"

#include <optional>

#include <fmt/format.h>

#include "analysis/claims.hpp"
#include "animate/frame.hpp"
#include "animate/output.hpp"
#include "animate/timeline.hpp"
#include "golden/figure_data.hpp"
#include "golden/golden_file.hpp"
#include "motion/stage.hpp"
#include "render/figure.hpp"
#include "scene/json_text.hpp"
#include "scene/scene.hpp"

namespace pita::golden {

namespace fs = std::filesystem;

namespace {

const std::string& output(const Outputs& outputs, FileKind kind) {
  switch (kind) {
    case FileKind::data:
      return outputs.data;
    case FileKind::svg:
      return outputs.svg;
    case FileKind::png:
      return outputs.png;
  }
  return outputs.data;
}

Json parse_data(const std::string& text, const fs::path& path) { return read_figure_data(text, path.string()); }

}  // namespace

std::string_view suffix(FileKind kind) {
  switch (kind) {
    case FileKind::data:
      return ".data.json";
    case FileKind::svg:
      return ".svg";
    case FileKind::png:
      return ".png";
  }
  return "";
}

fs::path golden_path(const fs::path& golden_dir, const std::string& name, FileKind kind) {
  return golden_dir / name / (name + std::string(suffix(kind)));
}

fs::path golden_path(const fs::path& golden_dir, const std::string& name, const std::string& suffix) {
  return golden_dir / name / (name + suffix);
}

std::vector<GoldenFile> golden_files(const Outputs& outputs) {
  std::vector<GoldenFile> files;
  for (const FileKind kind : kFileKinds) files.push_back({kind, std::string(suffix(kind)), &output(outputs, kind)});
  for (const auto& [frame_suffix, bytes] : outputs.frames) files.push_back({FileKind::png, frame_suffix, &bytes});
  return files;
}

std::string scene_name(const fs::path& scene_path) { return scene_path.stem().string(); }

Outputs render_outputs(const fs::path& scene_path) {
  const scene::Scene scene = scene::load_scene(scene_path);
  const motion::Stage stage(scene);
  const render::Figure figure = render::build_figure(stage);
  Outputs out;
  out.claims = analysis::check_claims(stage);               // measured on the motions drawn
  out.lint = lint::lint_figure(stage, figure, out.claims);  // on the figure drawn
  out.data = figure_data_text(figure_data(scene_name(scene_path), scene, figure));
  out.svg = render::render_figure(scene, figure, render::Format::svg);
  out.png = render::render_figure(scene, figure, render::Format::png);
  if (scene.has_animation) {
    const animate::Timeline timeline = animate::make_timeline(scene);
    const auto placements = animate::animation_layout(scene, timeline);
    for (const int k : {0, timeline.frames / 2, timeline.frames - 1}) {
      const render::Figure frame = animate::frame_figure(scene, timeline, timeline.time(k), placements);
      out.frames.emplace_back(fmt::format(".{}", animate::frame_file_name(k, timeline.frames, render::Format::png)),
                              render::render_figure(scene, frame, render::Format::png));
    }
  }
  return out;
}

bool SceneCheck::claims_hold() const {
  return std::all_of(claims.begin(), claims.end(), [](const analysis::ClaimOutcome& c) { return c.held; });
}

bool SceneCheck::matches() const {
  for (const FileCheck& f : files) {
    if (f.verdict != Verdict::match) return false;
  }
  return true;
}

namespace {

FileCheck compare_file_unchecked(FileKind kind, const fs::path& golden, const std::string& actual,
                                 const Tolerances& tolerances) {
  FileCheck check{kind, golden, Verdict::match, "", "", actual, ""};
  // Never through a link, a FIFO or a device (golden_file.hpp).
  std::optional<std::string> golden_bytes = read_golden_file(golden, kMaxGoldenFileBytes);
  if (!golden_bytes) {
    check.verdict = Verdict::missing;
    check.detail = "no golden file (create it with `pita update-goldens`)";
    return check;
  }
  check.expected = std::move(*golden_bytes);
  if (check.expected == actual) {
    check.detail = "identical";
    return check;
  }
  switch (kind) {
    case FileKind::data: {
      const Json expected = parse_data(check.expected, golden);  // the golden's errors first
      const NumberComparison c = compare_numbers(expected, parse_data(actual, "(fresh rendering)"), tolerances.numbers);
      check.verdict = c.matches ? Verdict::match : Verdict::differs;
      check.detail = c.matches ? fmt::format("within tolerance (worst {:.2g} of the extent)", c.relative)
                               : describe(c, tolerances.numbers);
      break;
    }
    case FileKind::svg: {
      const SvgComparison c = compare_svg(check.expected, actual, tolerances.svg);
      check.verdict = c.matches ? Verdict::match : Verdict::differs;
      check.detail = c.matches ? fmt::format("geometry within {:g} px", tolerances.svg) : describe(c, tolerances.svg);
      break;
    }
    case FileKind::png: {
      ImageComparison c;
      try {
        c = compare_png(check.expected, actual, tolerances.image);
      } catch (const GoldenError& e) {
        throw GoldenError(golden.string() + ": " + e.what());
      }
      check.verdict = c.matches ? Verdict::match : Verdict::differs;
      check.diff_png = c.diff_png;
      if (!c.same_size) {
        check.detail = fmt::format("the image is {}x{} instead of {}x{}", c.actual_width, c.actual_height,
                                   c.expected_width, c.expected_height);
      } else {
        check.detail = fmt::format(
            "{} pixels ({:.3f}%) differ by more than {} levels (largest "
            "difference {}); allowed: {:.3f}%",
            c.differing, 100.0 * c.share, tolerances.image.channel, c.max_channel_difference,
            100.0 * tolerances.image.max_share);
      }
      break;
    }
  }
  return check;
}

}  // namespace

FileCheck compare_file(FileKind kind, const fs::path& golden, const std::string& actual, const Tolerances& tolerances) {
  try {
    return compare_file_unchecked(kind, golden, actual, tolerances);
  } catch (const scene::SceneError& e) {  // the golden file's size, JSON text or nesting
    throw GoldenError(e.what());
  }
}

Tolerances tolerances_of(const scene::Scene& scene, const ToleranceOverrides& given) {
  Tolerances t;
  t.numbers = given.numbers.value_or(scene.golden.numbers.value_or(t.numbers));
  t.svg = given.svg.value_or(scene.golden.svg.value_or(t.svg));
  t.image.channel = given.pixel.value_or(scene.golden.pixel.value_or(t.image.channel));
  t.image.max_share = given.max_differing.value_or(scene.golden.max_differing.value_or(t.image.max_share));
  return t;
}

SceneCheck check_scene(const fs::path& scene_path, const fs::path& golden_dir, const Tolerances& tolerances) {
  const Outputs outputs = render_outputs(scene_path);
  SceneCheck result{scene_path.string(), scene_name(scene_path), {}, outputs.claims, outputs.lint};
  for (const GoldenFile& file : golden_files(outputs)) {
    result.files.push_back(
        compare_file(file.kind, golden_path(golden_dir, result.name, file.suffix), *file.bytes, tolerances));
  }
  return result;
}

}  // namespace pita::golden
