#include "sweep/sweep.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <system_error>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "analysis/measure.hpp"
#include "animate/progress.hpp"
#include "core/worker_pool.hpp"
#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"
#include "motion/stage.hpp"
#include "render/figure.hpp"
#include "render/interrupt.hpp"
#include "render/output_file.hpp"
#include "scene/limits.hpp"
#include "scene/scene.hpp"
#include "sweep/definition.hpp"
#include "sweep/grid.hpp"
#include "sweep/manifest.hpp"
#include "sweep/sheet.hpp"
#include "sweep/variant.hpp"

namespace pita::sweep {

namespace {

namespace fs = std::filesystem;

// A running sweep rewrites its manifest this often, so that even a killed
// process (SIGKILL, a lost node) leaves a manifest of most of what finished.
constexpr auto kManifestInterval = std::chrono::seconds(5);
// Failed variants listed in the summary (the manifest has them all).
constexpr std::size_t kMaxFailuresKept = 1000;

struct KindInfo {
  OutputKind kind;
  std::string_view name;
};
constexpr std::array<KindInfo, 5> kKinds = {{{OutputKind::svg, "svg"},
                                             {OutputKind::png, "png"},
                                             {OutputKind::pdf, "pdf"},
                                             {OutputKind::csv, "csv"},
                                             {OutputKind::json, "json"}}};

std::string_view name_of(OutputKind kind) {
  for (const KindInfo& k : kKinds) {
    if (k.kind == kind) return k.name;
  }
  return "?";
}

std::optional<render::Format> figure_format(OutputKind kind) {
  switch (kind) {
    case OutputKind::svg: return render::Format::svg;
    case OutputKind::png: return render::Format::png;
    case OutputKind::pdf: return render::Format::pdf;
    default: return std::nullopt;
  }
}

std::string number(double v) { return fmt::format("{:.6g}", v); }

// The metrics of the scene's own motion (kMetricColumns): `own` is its stage.
std::array<std::string, kMetricColumns.size()> metrics_of(const motion::Stage& own) {
  std::array<std::string, kMetricColumns.size()> m{};
  const analysis::MotionMeasures r = analysis::measure_panel(own, 0);
  if (r.no_motion) return m;
  if (r.path_p) {
    m[0] = number(r.path_p->length);
    m[2] = number(r.path_p->turning);
  }
  if (r.path_q) {
    m[1] = number(r.path_q->length);
    m[3] = number(r.path_q->turning);
  }
  if (r.winding_min) m[4] = number(*r.winding_min);
  if (r.winding_max) m[5] = number(*r.winding_max);
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
  if (r.ara) m[14] = number(*r.ara);
  if (r.area) m[15] = r.area->monotone ? "yes" : "no";
  return m;
}

// Removes what an earlier run wrote for a variant that now fails, so that no
// stale figure stands beside a failed row.
void remove_outputs(const fs::path& dir, const std::string& name, std::int64_t index, std::int64_t variants) {
  std::error_code ignored;
  fs::remove(dir / variant_file(name, index, variants, "scene.json"), ignored);
  for (const KindInfo& k : kKinds) fs::remove(dir / variant_file(name, index, variants, std::string(k.name)), ignored);
}

struct Job {
  const SweepOptions& options;
  const Grid& grid;
  const BaseScene& base;
  const fs::path dir;
  const std::string name;
  const std::string salt;
};

Row run_variant(const Job& job, std::int64_t index, bool& write_failed) {
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
    // The scene's own motion, built once for its frames and its metrics.
    const scene::Panel own = scene::scene_panel(scene);
    const std::optional<motion::Stage> own_alone =
        motion::own_is_first_panel(scene) ? std::nullopt : std::make_optional<motion::Stage>(scene, own);
    const motion::Stage& own_stage = own_alone ? *own_alone : stage;
    std::vector<std::pair<fs::path, std::string>> files;
    files.emplace_back(job.dir / scene_file, text);
    row.outputs.push_back(scene_file);
    std::optional<render::Figure> figure;
    for (const OutputKind kind : job.options.formats) {
      const std::string file = variant_file(job.name, index, variants, std::string(name_of(kind)));
      if (const auto format = figure_format(kind)) {
        if (!figure) figure = render::build_figure(stage);
        files.emplace_back(job.dir / file, render::render_figure(scene, *figure, *format));
      } else {
        const motion::SceneMotion& motion = own_stage.motion(0);
        const std::vector<double> at =
            motion::uniform_times(motion, scene.samples.value_or(scene::kDefaultSamples));
        files.emplace_back(job.dir / file, motion::frames_text(own_stage.panel(0), motion, at,
                                                               kind == OutputKind::csv ? motion::FramesFormat::csv
                                                                                       : motion::FramesFormat::json));
      }
      row.outputs.push_back(file);
    }
    row.metrics = metrics_of(own_stage);
    render::write_files_atomically(files);
    row.status = "ok";
  } catch (const render::OutputError& error) {
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
      render::write_file_atomically(job.dir / scene_file, text);
      row.outputs.push_back(scene_file);
    } catch (const render::OutputError&) {
      write_failed = true;
    }
  }
  return row;
}

bool outputs_exist(const fs::path& dir, const Row& row) {
  if (row.outputs.empty()) return false;
  std::error_code ignored;
  return std::all_of(row.outputs.begin(), row.outputs.end(),
                     [&](const std::string& f) { return fs::is_regular_file(dir / f, ignored); });
}

std::string failure_line(const std::vector<std::string>& pointers, const Row& row) {
  std::string values;
  for (std::size_t k = 0; k < pointers.size(); ++k) {
    values += fmt::format("{}{} = {}", k == 0 ? "" : ", ", pointers[k], row.values[k]);
  }
  return fmt::format("variant {} ({}): {}", row.index, values, row.status);
}

}  // namespace

std::vector<OutputKind> parse_output_kinds(const std::string& text) {
  std::vector<OutputKind> kinds;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const auto found = std::find_if(kKinds.begin(), kKinds.end(), [&](const KindInfo& k) { return k.name == item; });
    if (found == kKinds.end()) {
      throw SweepUsageError(fmt::format("--format: \"{}\" is not an output (use svg, png, pdf, csv or json, "
                                        "comma-separated: --format svg,csv)",
                                        item));
    }
    if (std::find(kinds.begin(), kinds.end(), found->kind) == kinds.end()) kinds.push_back(found->kind);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return kinds;
}

std::pair<int, int> parse_shard(const std::string& text) {
  const std::size_t slash = text.find('/');
  const auto digits = [](std::string_view t) {
    return !t.empty() && t.size() <= 9 && t.find_first_not_of("0123456789") == std::string_view::npos;
  };
  if (slash == std::string::npos || !digits(std::string_view(text).substr(0, slash)) ||
      !digits(std::string_view(text).substr(slash + 1))) {
    throw SweepUsageError(fmt::format("--shard: expected K/N with whole numbers 0 <= K < N, for example 0/4 "
                                      "(got \"{}\")",
                                      text));
  }
  const int k = std::stoi(text.substr(0, slash)), n = std::stoi(text.substr(slash + 1));
  if (n < 1 || k >= n) {
    throw SweepUsageError(fmt::format("--shard {}: K must be in 0..N-1 and N >= 1 (got K = {}, N = {})", text, k, n));
  }
  return {k, n};
}

std::string index_ranges(const std::vector<std::pair<std::int64_t, std::int64_t>>& ranges) {
  std::string out;
  for (const auto& [first, last] : ranges) {
    out += fmt::format("{}{}", out.empty() ? "" : ", ", first == last ? std::to_string(first) : fmt::format("{}-{}", first, last));
  }
  return out;
}

namespace {

// The output folder, created when missing.
fs::path output_folder(const SweepOptions& options) {
  const fs::path dir(options.output);
  std::error_code error;
  fs::create_directories(dir, error);
  if (error || !fs::is_directory(dir)) {
    throw SweepUsageError(fmt::format("-o {}: cannot create the output folder ({})", options.output,
                                      error ? error.message() : "a file of that name exists"));
  }
  return dir;
}

Definition definition_of(const SweepOptions& options, const Grid& grid, const BaseScene& base) {
  Definition definition;
  definition.scene = options.scene_path;
  definition.name = fs::path(options.scene_path).stem().string();
  for (const Axis& a : grid.axes()) {
    definition.axes.emplace_back(a.pointer, a.spec);
    definition.axis_sizes.push_back(a.size());
  }
  definition.zip = grid.zip();
  for (const OutputKind k : options.formats) definition.formats.emplace_back(name_of(k));
  definition.variants = grid.size();
  definition.salt = "pita " + options.version;
  for (const std::string& f : definition.formats) definition.salt += " " + f;
  definition.base = base.document;
  return definition;
}

// One run of a sweep (or of its shard K of N) into its folder: what an
// earlier run left is resumed, the other variants are run and journaled in
// order, and the manifest is written from both.
class SweepRun {
 public:
  SweepRun(const SweepOptions& options, const Grid& grid, const BaseScene& base, fs::path dir,
           const Definition& definition)
      : options_(options),
        grid_(grid),
        base_(base),
        dir_(std::move(dir)),
        definition_(definition),
        job_{options, grid, base, dir_, definition.name, definition.salt},
        pointers_(pointers_of(definition)),
        manifest_path_(dir_ / manifest_name(options.shard)),
        // Rows are appended here as they finish, in index order: what a killed
        // process leaves, and what the next run folds into the manifest.
        journal_path_(dir_ / ("." + manifest_name(options.shard) + ".journal")),
        shard_k_(options.shard ? options.shard->first : 0),
        shard_n_(options.shard ? options.shard->second : 1),
        mine_(grid.size() > shard_k_ ? (grid.size() - shard_k_ + shard_n_ - 1) / shard_n_ : 0),
        kept_(static_cast<std::size_t>(mine_), 0) {
    summary_.variants = mine_;
  }

  SweepSummary run() {
    if (!options_.force) resume();
    std::error_code ignored;
    fs::remove(journal_path_, ignored);
    render::write_file_atomically(dir_ / kSweepFile, definition_json(definition_));
    run_variants();
    write_manifest();
    if (options_.shard) {
      summary_.notes.push_back(fmt::format("shard {}/{}: join the shards with pita sweep --merge {}", shard_k_,
                                           shard_n_, options_.output));
    } else {
      write_reports(dir_, definition_, summary_.notes);
    }
    return summary_;
  }

 private:
  std::int64_t position(std::int64_t index) const { return (index - shard_k_) / shard_n_; }
  bool in_shard(std::int64_t index) const {
    return index >= 0 && index < grid_.size() && index % shard_n_ == shard_k_;
  }
  // A row of an earlier run is kept when its variant is unchanged (same
  // content hash), it is ok and its outputs all exist.
  bool valid(const Row& row) const {
    if (!in_shard(row.index) || !row.ok() || !outputs_exist(dir_, row)) return false;
    return content_hash(variant_text(variant_document(base_, grid_, grid_.values(row.index))), definition_.salt) ==
           row.hash;
  }
  [[noreturn]] void refuse_folder(const std::runtime_error& error) const {
    throw SweepUsageError(
        fmt::format("-o {}: {} (or --force to start this sweep over there)", options_.output, error.what()));
  }

  // Resume: the valid rows of an earlier run (its manifest, or the journal of
  // a killed run) are kept; the others are done again. Nothing but one byte
  // per variant is held. A manifest of another sweep (other pointers) is
  // refused before anything is written.
  void resume() {
    std::optional<ManifestReader> old;
    try {
      old = ManifestReader::open(manifest_path_, pointers_);
    } catch (const std::runtime_error& error) {
      refuse_folder(error);
    }
    std::optional<ManifestReader> journal = ManifestReader::open(journal_path_, pointers_, true);
    have_manifest_ = old.has_value();
    for (auto* reader : {old ? &*old : nullptr, journal ? &*journal : nullptr}) {
      if (reader == nullptr) continue;
      Row row;
      try {
        while (reader->next(row)) {
          const auto j = static_cast<std::size_t>(position(row.index));
          if (valid(row) && kept_[j] == 0) {
            kept_[j] = 1;
            ++summary_.skipped;
          }
        }
      } catch (const std::runtime_error& error) {
        refuse_folder(error);
      }
    }
    if (journal) {
      // Fold the killed run's journal into the manifest, then start a new one.
      std::vector<ManifestReader> sources;
      if (auto m = ManifestReader::open(manifest_path_, pointers_)) sources.push_back(std::move(*m));
      if (auto j = ManifestReader::open(journal_path_, pointers_, true)) sources.push_back(std::move(*j));
      merge_sources(manifest_path_, pointers_, sources, [&](const Row& row, std::size_t) { return valid(row); },
                    [](const Row&) {}, false);
      have_manifest_ = true;
    }
  }

  // A variant's row: run, or (resumed) nothing to do.
  struct Finished {
    Row row;
    bool write_failed = false;
  };
  std::optional<Finished> produce(std::int64_t j) const {
    if (kept_[static_cast<std::size_t>(j)] != 0) return std::nullopt;  // resumed
    const std::int64_t index = shard_k_ + j * shard_n_;
    Finished finished;
    try {
      finished.row = run_variant(job_, index, finished.write_failed);
    } catch (const std::exception& error) {
      // Nothing a variant does may end the sweep: it is a failed row.
      finished.row = Row{};
      finished.row.index = index;
      finished.row.values.assign(pointers_.size(), "");
      finished.row.status = fmt::format("internal error: {}", error.what());
    }
    return finished;
  }

  // The variants not resumed, on the pool; their rows journaled in order, on
  // this thread, as soon as every earlier one is (core/worker_pool.hpp).
  void run_variants() {
    std::FILE* journal = std::fopen(journal_path_.c_str(), "w");
    if (journal == nullptr) {
      throw render::OutputError(fmt::format("{}: cannot write ({})", journal_path_.string(), std::strerror(errno)));
    }
    struct Closer {
      std::FILE* file;
      ~Closer() { std::fclose(file); }
    } closer{journal};
    std::int64_t done = 0;  // in this run (resumed variants are not counted)
    std::string line;
    const auto journal_row = [&](std::int64_t, std::optional<Finished>&& finished) {
      if (!finished) return true;
      ++done;
      summary_.write_failed = summary_.write_failed || finished->write_failed;
      const Row& row = finished->row;
      if (row.ok()) {
        ++summary_.ok;
      } else {
        ++summary_.failed;
        if (summary_.failures.size() < kMaxFailuresKept) summary_.failures.push_back(failure_line(pointers_, row));
      }
      line.clear();
      append_row(line, row);
      if (std::fwrite(line.data(), 1, line.size(), journal) != line.size() || std::fflush(journal) != 0) {
        summary_.write_failed = true;
      }
      return true;
    };
    const auto work = static_cast<int>(std::min<std::int64_t>(mine_ - summary_.skipped, INT32_MAX));
    animate::Progress progress("pita sweep", work, options_.progress, true);
    {
      const render::DeferredInterrupts deferred;
      PoolOptions pool;
      pool.threads = static_cast<int>(std::min<std::int64_t>(options_.jobs, std::max<std::int64_t>(mine_, 1)));
      const auto tick = [&] {
        progress.update(static_cast<int>(std::min<std::int64_t>(done, INT32_MAX)));
        return render::pending_interrupt() == 0;  // a signal: stop, keep what is journaled
      };
      try {
        run_ordered(
            mine_, pool, [this](std::int64_t j, const std::atomic<bool>&) { return produce(j); }, journal_row,
            tick);
      } catch (const std::system_error& error) {
        throw SweepUsageError(fmt::format("--jobs {}: cannot start a thread ({})", options_.jobs, error.what()));
      }
    }
    progress.update(static_cast<int>(std::min<std::int64_t>(done, INT32_MAX)));
  }

  // The manifest: the rows kept from before and the journal's, in order (an
  // interrupted run's rows that were still waiting for an earlier one are
  // left out: their variants are done again). Then the journal goes; a
  // pending signal ends the process here.
  void write_manifest() {
    const int sig = render::pending_interrupt();
    std::vector<ManifestReader> sources;
    if (have_manifest_) {
      if (auto m = ManifestReader::open(manifest_path_, pointers_)) sources.push_back(std::move(*m));
    }
    const std::size_t journal_source = sources.size();
    if (auto j = ManifestReader::open(journal_path_, pointers_, true)) sources.push_back(std::move(*j));
    const auto accept = [&](const Row& row, std::size_t source) {
      if (!in_shard(row.index)) return false;
      // Rows from before: only those kept, the others were done again.
      return source == journal_source || kept_[static_cast<std::size_t>(position(row.index))] != 0;
    };
    try {
      merge_sources(manifest_path_, pointers_, sources, accept, [](const Row&) {}, false);
    } catch (const render::OutputError&) {
      if (sig != 0) render::exit_interrupted(sig);  // the journal stays: the next run folds it
      throw;
    }
    std::error_code ignored;
    fs::remove(journal_path_, ignored);
    if (sig != 0) render::exit_interrupted(sig);
  }

  const SweepOptions& options_;
  const Grid& grid_;
  const BaseScene& base_;
  const fs::path dir_;
  const Definition& definition_;
  const Job job_;
  const std::vector<std::string> pointers_;
  const fs::path manifest_path_;
  const fs::path journal_path_;
  const int shard_k_;
  const int shard_n_;
  const std::int64_t mine_;
  std::vector<char> kept_;  // per variant of the shard: resumed from an earlier run
  bool have_manifest_ = false;
  SweepSummary summary_;
};

}  // namespace

SweepSummary run_sweep(const SweepOptions& options) {
  if (options.jobs < 1) throw SweepUsageError(fmt::format("--jobs: must be >= 1 (got {})", options.jobs));
  std::vector<Axis> axes;
  for (const std::string& v : options.vary) axes.push_back(parse_axis(v));
  const Grid grid(std::move(axes), options.zip);
  const BaseScene base = load_base(options.scene_path, grid);
  fs::path dir = output_folder(options);
  const Definition definition = definition_of(options, grid, base);
  return SweepRun(options, grid, base, std::move(dir), definition).run();
}

}  // namespace pita::sweep
