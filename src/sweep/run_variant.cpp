#include "sweep/run_variant.hpp"

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "analysis/measure.hpp"
#include "core/fnv1a.hpp"
#include "io/output_file.hpp"
#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"
#include "motion/stage.hpp"
#include "render/figure.hpp"
#include "render/figure_digest.hpp"
#include "scene/limits.hpp"
#include "scene/scene.hpp"
#include "sweep/variant.hpp"

namespace pita::sweep {

namespace {

namespace fs = std::filesystem;

struct KindInfo {
  OutputKind kind;
  std::string_view name;
};
constexpr std::array<KindInfo, 6> kKinds = {{{OutputKind::svg, "svg"},
                                             {OutputKind::png, "png"},
                                             {OutputKind::pdf, "pdf"},
                                             {OutputKind::csv, "csv"},
                                             {OutputKind::json, "json"},
                                             {OutputKind::metrics, "metrics"}}};

}  // namespace

std::string_view output_kind_name(OutputKind kind) {
  for (const KindInfo& k : kKinds) {
    if (k.kind == kind) return k.name;
  }
  return "?";
}

bool metrics_only(const std::vector<OutputKind>& formats) {
  return std::all_of(formats.begin(), formats.end(), [](OutputKind k) { return k == OutputKind::metrics; });
}

std::optional<OutputKind> output_kind_named(std::string_view name) {
  for (const KindInfo& k : kKinds) {
    if (k.name == name) return k.kind;
  }
  return std::nullopt;
}

namespace {

std::optional<render::Format> figure_format(OutputKind kind) {
  switch (kind) {
    case OutputKind::svg:
      return render::Format::svg;
    case OutputKind::png:
      return render::Format::png;
    case OutputKind::pdf:
      return render::Format::pdf;
    default:
      return std::nullopt;
  }
}

std::string number(double v) { return fmt::format("{:.6g}", v); }

using Metrics = std::array<std::string, kMetricColumns.size()>;

// The columns of kMetricColumns each kind measures.
void add_metrics(const analysis::ArrowMeasures& r, Metrics& m) {
  m[0] = number(r.path_p.length);
  m[1] = number(r.path_q.length);
  m[2] = number(r.path_p.turning);
  m[3] = number(r.path_q.turning);
  m[4] = number(r.winding_min);
  m[5] = number(r.winding_max);
  for (const analysis::DiscrepancyStats& d : r.discrepancy) {
    if (d.frames == 0) continue;
    if (d.predictor == "pita") {
      m[6] = number(d.max);
      m[9] = number(d.t_of_max);
    }
    if (d.predictor == "previous") m[7] = number(d.max);
    if (d.predictor == "average") m[8] = number(d.max);
  }
  if (r.most_sensitive >= 0) {
    const analysis::ParameterReaction& p = r.parameters[static_cast<std::size_t>(r.most_sensitive)];
    m[10] = p.name;
    m[11] = number(p.gain);
  }
  if (r.largest_jump >= 0) m[12] = number(r.parameters[static_cast<std::size_t>(r.largest_jump)].jump);
  if (!r.parameters.empty()) m[13] = r.pops ? "yes" : "no";
  m[16] = std::to_string(r.path_p.inflections);
  m[17] = std::to_string(r.path_q.inflections);
}

void add_metrics(const analysis::PointMeasures& r, Metrics& m) {
  m[0] = number(r.path.length);
  m[2] = number(r.path.turning);
  m[16] = std::to_string(r.path.inflections);
}

template <class Pose>
void add_metrics(const analysis::PoseMeasures<Pose>& r, Metrics& m) {
  m[14] = number(r.ara);
  m[15] = r.area.monotone ? "yes" : "no";
}

// The metrics (kMetricColumns) of the stage's first panel.
Metrics metrics_of(const motion::Stage& stage) {
  Metrics m{};
  const analysis::MotionMeasures r = analysis::measure_panel(stage, 0);
  if (r.no_motion) return m;
  std::visit([&](const auto& measured) { add_metrics(measured, m); }, r.measured);
  return m;
}

// What the variant's outputs show, titles aside: its figure's digest, its
// frames' text and its metrics (not its scene file, which names its values).
std::uint64_t outputs_digest(const std::optional<render::Figure>& figure,
                             const std::vector<std::pair<fs::path, std::string>>& files, const Metrics& metrics) {
  Fnv1a digest;
  if (figure) digest.add(render::figure_digest(*figure));
  for (const auto& [path, bytes] : files) {
    if (path.extension() == ".csv" || path.extension() == ".json") {
      if (path.string().ends_with(".scene.json")) continue;
      digest.add(std::string_view(bytes));
    }
  }
  for (const std::string& m : metrics) {
    digest.add(std::string_view(m));
    digest.add(std::string_view("\0", 1));
  }
  return digest.value() == 0 ? 1 : digest.value();
}

// Removes what an earlier run wrote for a variant that now fails, so that no
// stale figure stands beside a failed row.
void remove_outputs(const fs::path& dir, const std::string& name, std::int64_t index, std::int64_t variants) {
  std::error_code ignored;
  fs::remove(dir / variant_file(name, index, variants, "scene.json"), ignored);
  for (const KindInfo& k : kKinds) {
    if (k.kind == OutputKind::metrics) continue;  // no file
    fs::remove(dir / variant_file(name, index, variants, std::string(k.name)), ignored);
  }
}

}  // namespace

Row run_variant(const VariantJob& job, std::int64_t index, VariantOutcome& outcome) {
  bool& write_failed = outcome.write_failed;
  Row row;
  row.index = index;
  const std::vector<Json> values = job.grid.values(index);
  for (const Json& v : values) row.values.push_back(value_text(v));
  const std::string text = variant_text(variant_document(job.base, job.grid, values));
  row.hash = content_hash(text, job.salt);
  const std::int64_t variants = job.grid.size();
  const std::string scene_file = variant_file(job.name, index, variants, "scene.json");
  try {
    // Read as if it were the base scene's file (relative image paths), named
    // in messages as the variant's own file.
    const scene::Scene scene = scene::parse_scene(text, job.base.path);
    const motion::Stage stage(scene);
    stage.check();
    // The scene's own motion (what pita eval prints), built once for the
    // frames when they are asked for.
    const scene::Panel own = scene::scene_panel(scene);
    std::optional<motion::Stage> own_alone;
    const auto own_stage = [&]() -> const motion::Stage& {
      if (motion::own_is_first_panel(scene)) return stage;
      if (!own_alone) own_alone.emplace(scene, own);
      return *own_alone;
    };
    std::vector<std::pair<fs::path, std::string>> files;
    if (!metrics_only(job.options.formats)) {  // metrics alone: the manifest's row is all
      files.emplace_back(job.dir / scene_file, text);
      row.outputs.push_back(scene_file);
    }
    std::optional<render::Figure> figure;
    for (const OutputKind kind : job.options.formats) {
      if (kind == OutputKind::metrics) continue;
      const std::string file = variant_file(job.name, index, variants, std::string(output_kind_name(kind)));
      if (const auto format = figure_format(kind)) {
        if (!figure) figure = render::build_figure(stage);
        files.emplace_back(job.dir / file, render::render_figure(scene, *figure, *format));
      } else {
        const motion::SceneMotion& motion = own_stage().motion(0);
        const std::vector<double> at = motion::uniform_times(motion, scene.samples.value_or(scene::kDefaultSamples));
        motion::check_eval_work(scene, own_stage().panel(0), motion, at.size(), "ask for fewer frames (/samples)");
        files.emplace_back(job.dir / file, motion::frames_text(own_stage().panel(0), motion, at,
                                                               kind == OutputKind::csv ? motion::FramesFormat::csv
                                                                                       : motion::FramesFormat::json));
      }
      row.outputs.push_back(file);
    }
    // The metrics, of what the figure draws first (the first panel, or the
    // scene's own motion when it has no panels), within `pita measure`'s
    // cost limit, else none (the sweep says how many variants have none).
    if (analysis::measure_cost(stage.panel(0)) <= scene::kMaxEvalWork) {
      row.metrics = metrics_of(stage);
    } else {
      outcome.metrics_skipped = true;
    }
    io::write_files_atomically(files);
    row.status = "ok";
    outcome.digest = outputs_digest(figure, files, row.metrics);
  } catch (const io::OutputError& error) {
    row.status = fmt::format("cannot write: {}", error.what());
    row.outputs.clear();
    write_failed = true;
  } catch (const std::exception& error) {
    std::string message = error.what();
    const std::string prefix = job.base.path + ": ";
    if (message.starts_with(prefix)) message = scene_file + ": " + message.substr(prefix.size());
    row.status = message;
    row.outputs.clear();
    row.metrics = {};
    remove_outputs(job.dir, job.name, index, variants);
    // The failed variant's scene stays, to reproduce the error by hand.
    try {
      io::write_file_atomically(job.dir / scene_file, text);
      row.outputs.push_back(scene_file);
    } catch (const io::OutputError&) {
      write_failed = true;
    }
  }
  return row;
}

}  // namespace pita::sweep
