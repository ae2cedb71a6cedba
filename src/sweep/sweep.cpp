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
#include "sweep/grid.hpp"
#include "sweep/manifest.hpp"
#include "sweep/sheet.hpp"
#include "sweep/variant.hpp"

namespace pita::sweep {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kSweepFile = "sweep.json";
// A running sweep rewrites its manifest this often, so that even a killed
// process (SIGKILL, a lost node) leaves a manifest of most of what finished.
constexpr auto kManifestInterval = std::chrono::seconds(5);
// Failed variants listed in the summary (the manifest has them all), and
// ranges of missing variants --merge reports.
constexpr std::size_t kMaxFailuresKept = 1000;
constexpr std::size_t kMaxRangesKept = 1000;

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

// What defines a sweep in DIR (read back by --merge).
struct Definition {
  std::string scene;  // the base scene's path, as given
  std::string name;   // its stem: the variants' file names
  std::vector<std::pair<std::string, std::string>> axes;  // pointer, spec
  std::vector<std::size_t> axis_sizes;
  bool zip = false;
  std::vector<std::string> formats;
  std::int64_t variants = 0;
  std::string salt;   // what else the content hashes cover (formats, pita's version)
  Json base;          // the base scene's document: --merge rebuilds each variant's hash from it
};

std::string definition_json(const Definition& d) {
  Json j;
  j["scene"] = d.scene;
  j["name"] = d.name;
  j["axes"] = Json::array();
  for (std::size_t k = 0; k < d.axes.size(); ++k) {
    j["axes"].push_back(Json{{"pointer", d.axes[k].first}, {"spec", d.axes[k].second}, {"size", d.axis_sizes[k]}});
  }
  j["zip"] = d.zip;
  j["formats"] = d.formats;
  j["variants"] = d.variants;
  j["salt"] = d.salt;
  j["base"] = d.base;
  return j.dump(2) + "\n";
}

Definition read_definition(const fs::path& dir) {
  std::ifstream in(dir / kSweepFile, std::ios::binary);
  if (!in) {
    throw SweepUsageError(fmt::format("--merge {}: no {} there: it is not the output folder of a pita sweep",
                                      dir.string(), kSweepFile));
  }
  std::stringstream text;
  text << in.rdbuf();
  try {
    const Json j = Json::parse(text.str());
    Definition d;
    d.scene = j.at("scene").get<std::string>();
    d.name = j.at("name").get<std::string>();
    for (const Json& a : j.at("axes")) {
      d.axes.emplace_back(a.at("pointer").get<std::string>(), a.at("spec").get<std::string>());
      d.axis_sizes.push_back(a.at("size").get<std::size_t>());
    }
    d.zip = j.at("zip").get<bool>();
    d.formats = j.at("formats").get<std::vector<std::string>>();
    d.variants = j.at("variants").get<std::int64_t>();
    d.salt = j.at("salt").get<std::string>();
    d.base = j.at("base");
    if (d.name.empty() || d.name.find('/') != std::string::npos) throw std::runtime_error("bad name");
    if (d.variants < 0 || d.variants > kMaxVariants) throw std::runtime_error("bad variant count");
    return d;
  } catch (const std::exception& error) {
    throw SweepUsageError(fmt::format("--merge {}: {} is not a sweep definition ({})", dir.string(),
                                      (dir / kSweepFile).string(), error.what()));
  }
}

std::vector<std::string> pointers_of(const Definition& d) {
  std::vector<std::string> p;
  for (const auto& [pointer, spec] : d.axes) p.push_back(pointer);
  return p;
}

SheetInput sheet_input(const fs::path& dir, const Definition& d) {
  SheetInput s;
  s.dir = dir;
  s.name = d.name;
  s.base_path = d.scene;
  s.pointers = pointers_of(d);
  s.axis_sizes = d.axis_sizes;
  s.zip = d.zip;
  s.variants = d.variants;
  for (const std::string& f : d.formats) s.figures = s.figures || f == "svg" || f == "png" || f == "pdf";
  return s;
}

// index.html and contact.* from DIR/manifest.csv (an unsharded run, or a merge).
void write_reports(const fs::path& dir, const Definition& d, std::vector<std::string>& notes) {
  const SheetInput input = sheet_input(dir, d);
  if (std::string why = write_index_html(input); !why.empty()) notes.push_back(std::move(why));
  if (input.figures) {
    if (std::string why = write_contact_sheet(input); !why.empty()) notes.push_back(std::move(why));
  }
}

// A manifest written from sources of rows, each sorted by index, without
// holding them: of the rows of one index, an accepted one of a later source
// wins (ok rows before failed ones when `prefer_ok`). `accept(row, source)`
// filters; `on_row` sees each row written.
template <typename Accept, typename OnRow>
void merge_sources(const fs::path& path, const std::vector<std::string>& pointers,
                   std::vector<ManifestReader>& sources, Accept accept, OnRow on_row, bool prefer_ok) {
  render::StreamingOutput out(path);
  out.write(manifest_header(pointers));
  std::vector<std::optional<Row>> heads(sources.size());
  const auto advance = [&](std::size_t s) {
    heads[s].reset();
    Row row;
    while (sources[s].next(row)) {
      if (accept(row, s)) {
        heads[s] = std::move(row);
        return;
      }
    }
  };
  for (std::size_t s = 0; s < sources.size(); ++s) advance(s);
  std::string line;
  while (true) {
    std::optional<std::int64_t> least;
    for (const auto& head : heads) {
      if (head && (!least || head->index < *least)) least = head->index;
    }
    if (!least) break;
    std::optional<std::size_t> best;
    for (std::size_t s = 0; s < heads.size(); ++s) {
      if (!heads[s] || heads[s]->index != *least) continue;
      if (!best || !prefer_ok || heads[s]->ok() || !heads[*best]->ok()) best = s;
    }
    on_row(*heads[*best]);
    line.clear();
    append_row(line, *heads[*best]);
    out.write(line);
    for (std::size_t s = 0; s < heads.size(); ++s) {
      if (heads[s] && heads[s]->index == *least) advance(s);
    }
  }
  out.commit();
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

SweepSummary run_sweep(const SweepOptions& options) {
  if (options.jobs < 1) throw SweepUsageError(fmt::format("--jobs: must be >= 1 (got {})", options.jobs));
  std::vector<Axis> axes;
  for (const std::string& v : options.vary) axes.push_back(parse_axis(v));
  const Grid grid(std::move(axes), options.zip);
  const BaseScene base = load_base(options.scene_path, grid);

  const fs::path dir(options.output);
  {
    std::error_code error;
    fs::create_directories(dir, error);
    if (error || !fs::is_directory(dir)) {
      throw SweepUsageError(fmt::format("-o {}: cannot create the output folder ({})", options.output,
                                        error ? error.message() : "a file of that name exists"));
    }
  }
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

  const std::string& salt = definition.salt;
  const Job job{options, grid, base, dir, definition.name, salt};
  const std::vector<std::string> pointers = pointers_of(definition);
  const std::string manifest = manifest_name(options.shard);
  const fs::path manifest_path = dir / manifest;
  // Rows are appended here as they finish, in index order: what a killed
  // process leaves, and what the next run folds into the manifest.
  const fs::path journal_path = dir / ("." + manifest + ".journal");
  // Plain variables, not a structured binding: lambdas capture them (clang 14).
  const int shard_k = options.shard ? options.shard->first : 0;
  const int shard_n = options.shard ? options.shard->second : 1;
  const std::int64_t variants = grid.size();
  const std::int64_t mine = variants > shard_k ? (variants - shard_k + shard_n - 1) / shard_n : 0;
  const auto position = [&](std::int64_t index) { return (index - shard_k) / shard_n; };
  const auto in_shard = [&](std::int64_t index) {
    return index >= 0 && index < variants && index % shard_n == shard_k;
  };

  // Resume: a row of an earlier run (its manifest, or the journal of a killed
  // run) is kept when its variant is unchanged (same content hash), it is ok
  // and its outputs all exist; the others are done again. Nothing but one
  // byte per variant is held. A manifest of another sweep (other pointers) is
  // refused before anything is written.
  const auto valid = [&](const Row& row) {
    if (!in_shard(row.index) || !row.ok() || !outputs_exist(dir, row)) return false;
    return content_hash(variant_text(variant_document(base, grid, grid.values(row.index))), salt) == row.hash;
  };
  std::vector<char> kept(static_cast<std::size_t>(mine), 0);
  SweepSummary summary;
  summary.variants = mine;
  bool have_manifest = false;
  if (!options.force) {
    std::optional<ManifestReader> old;
    try {
      old = ManifestReader::open(manifest_path, pointers);
    } catch (const std::runtime_error& error) {
      throw SweepUsageError(fmt::format("-o {}: {} (or --force to start this sweep over there)", options.output,
                                        error.what()));
    }
    std::optional<ManifestReader> journal = ManifestReader::open(journal_path, pointers, true);
    have_manifest = old.has_value();
    for (auto* reader : {old ? &*old : nullptr, journal ? &*journal : nullptr}) {
      if (reader == nullptr) continue;
      Row row;
      try {
        while (reader->next(row)) {
          if (valid(row) && !kept[static_cast<std::size_t>(position(row.index))]) {
            kept[static_cast<std::size_t>(position(row.index))] = 1;
            ++summary.skipped;
          }
        }
      } catch (const std::runtime_error& error) {
        throw SweepUsageError(fmt::format("-o {}: {} (or --force to start this sweep over there)", options.output,
                                          error.what()));
      }
    }
    if (journal) {
      // Fold the killed run's journal into the manifest, then start a new one.
      std::vector<ManifestReader> sources;
      if (auto m = ManifestReader::open(manifest_path, pointers)) sources.push_back(std::move(*m));
      if (auto j = ManifestReader::open(journal_path, pointers, true)) sources.push_back(std::move(*j));
      merge_sources(manifest_path, pointers, sources, [&](const Row& row, std::size_t) { return valid(row); },
                    [](const Row&) {}, false);
      have_manifest = true;
    }
  }
  std::error_code ignored;
  fs::remove(journal_path, ignored);
  render::write_file_atomically(dir / kSweepFile, definition_json(definition));

  std::FILE* journal = std::fopen(journal_path.c_str(), "w");
  if (journal == nullptr) {
    throw render::OutputError(fmt::format("{}: cannot write ({})", journal_path.string(), std::strerror(errno)));
  }
  struct Closer {
    std::FILE*& file;
    ~Closer() {
      if (file != nullptr) std::fclose(file);
    }
  } closer{journal};

  // Variants finish out of order; their rows are journaled in order, on this
  // thread, as soon as every earlier one is (core/worker_pool.hpp).
  std::int64_t done = 0;  // in this run (resumed variants are not counted)
  bool write_failed = false;
  std::string line;
  struct Finished {
    Row row;
    bool write_failed = false;
  };
  const auto produce = [&](std::int64_t j, const std::atomic<bool>&) -> std::optional<Finished> {
    if (kept[static_cast<std::size_t>(j)] != 0) return std::nullopt;  // resumed
    const std::int64_t index = shard_k + j * shard_n;
    Finished finished;
    try {
      finished.row = run_variant(job, index, finished.write_failed);
    } catch (const std::exception& error) {
      // Nothing a variant does may end the sweep: it is a failed row.
      finished.row = Row{};
      finished.row.index = index;
      finished.row.values.assign(pointers.size(), "");
      finished.row.status = fmt::format("internal error: {}", error.what());
    }
    return finished;
  };
  const auto journal_row = [&](std::int64_t, std::optional<Finished>&& finished) {
    if (!finished) return true;
    ++done;
    write_failed = write_failed || finished->write_failed;
    const Row& row = finished->row;
    if (row.ok()) {
      ++summary.ok;
    } else {
      ++summary.failed;
      if (summary.failures.size() < kMaxFailuresKept) summary.failures.push_back(failure_line(pointers, row));
    }
    line.clear();
    append_row(line, row);
    if (std::fwrite(line.data(), 1, line.size(), journal) != line.size() || std::fflush(journal) != 0) {
      write_failed = true;
    }
    return true;
  };

  const auto work = static_cast<int>(std::min<std::int64_t>(mine - summary.skipped, INT32_MAX));
  animate::Progress progress("pita sweep", work, options.progress, true);
  {
    const render::DeferredInterrupts deferred;
    PoolOptions pool;
    pool.threads = static_cast<int>(std::min<std::int64_t>(options.jobs, std::max<std::int64_t>(mine, 1)));
    const auto tick = [&] {
      progress.update(static_cast<int>(std::min<std::int64_t>(done, INT32_MAX)));
      return render::pending_interrupt() == 0;  // a signal: stop, keep what is journaled
    };
    try {
      run_ordered(mine, pool, produce, journal_row, tick);
    } catch (const std::system_error& error) {
      throw SweepUsageError(fmt::format("--jobs {}: cannot start a thread ({})", options.jobs, error.what()));
    }
  }
  progress.update(static_cast<int>(std::min<std::int64_t>(done, INT32_MAX)));
  std::fclose(journal);
  journal = nullptr;

  // The manifest: the rows kept from before and the journal's, in order (an
  // interrupted run's rows that were still waiting for an earlier one are
  // left out: their variants are done again). Then the journal goes.
  const int sig = render::pending_interrupt();
  {
    std::vector<ManifestReader> sources;
    if (have_manifest) {
      if (auto m = ManifestReader::open(manifest_path, pointers)) sources.push_back(std::move(*m));
    }
    const std::size_t journal_source = sources.size();
    if (auto j = ManifestReader::open(journal_path, pointers, true)) sources.push_back(std::move(*j));
    const auto accept = [&](const Row& row, std::size_t source) {
      if (!in_shard(row.index)) return false;
      // Rows from before: only those kept, the others were done again.
      return source == journal_source || kept[static_cast<std::size_t>(position(row.index))] != 0;
    };
    try {
      merge_sources(manifest_path, pointers, sources, accept, [](const Row&) {}, false);
    } catch (const render::OutputError&) {
      if (sig != 0) render::exit_interrupted(sig);  // the journal stays: the next run folds it
      throw;
    }
    fs::remove(journal_path, ignored);
  }
  if (sig != 0) render::exit_interrupted(sig);
  summary.write_failed = write_failed;
  if (options.shard) {
    summary.notes.push_back(fmt::format("shard {}/{}: join the shards with pita sweep --merge {}", shard_k, shard_n,
                                        options.output));
  } else {
    write_reports(dir, definition, summary.notes);
  }
  return summary;
}

MergeSummary merge_sweep(const std::string& dir_text, bool quiet) {
  (void)quiet;
  const fs::path dir(dir_text);
  const Definition definition = read_definition(dir);
  const std::vector<std::string> pointers = pointers_of(definition);
  // The sweep again, from its definition: each row of the parts must be its
  // variant (same values, same content hash), else it is another sweep's.
  std::vector<Axis> axes;
  for (const auto& [pointer, spec] : definition.axes) axes.push_back(parse_axis(pointer + "=" + spec));
  const Grid grid(std::move(axes), definition.zip);
  if (grid.size() != definition.variants) {
    throw SweepUsageError(fmt::format("--merge {}: {} does not add up ({} variants, its axes make {})", dir_text,
                                      kSweepFile, definition.variants, grid.size()));
  }
  const BaseScene base{definition.scene, definition.base};
  MergeSummary summary;
  summary.variants = definition.variants;
  std::vector<fs::path> parts;
  std::error_code error;
  static const std::regex kPart(R"(manifest\.[0-9]+-of-[0-9]+\.csv)");
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, error)) {
    if (std::regex_match(entry.path().filename().string(), kPart)) parts.push_back(entry.path());
  }
  std::sort(parts.begin(), parts.end());
  if (parts.empty()) {
    throw SweepUsageError(fmt::format("--merge {}: no manifest.K-of-N.csv there (run the shards with --shard K/N "
                                      "-o {} first)",
                                      dir_text, dir_text));
  }
  std::vector<ManifestReader> sources;
  for (const fs::path& part : parts) {
    try {
      if (auto reader = ManifestReader::open(part, pointers)) {
        sources.push_back(std::move(*reader));
        summary.parts.push_back(part.filename().string());
      }
    } catch (const std::runtime_error& e) {
      summary.notes.push_back(fmt::format("{} ignored: {}", part.filename().string(), e.what()));
    }
  }
  const auto accept = [&](const Row& row, std::size_t) {
    if (row.index < 0 || row.index >= definition.variants) return false;
    const std::string text = variant_text(variant_document(base, grid, grid.values(row.index)));
    if (row.hash == content_hash(text, definition.salt)) return true;
    ++summary.foreign;
    return false;
  };
  std::int64_t expected = 0;
  const auto missing = [&](std::int64_t from, std::int64_t to) {  // [from, to)
    if (from >= to) return;
    summary.missing_count += to - from;
    if (summary.missing.size() < kMaxRangesKept) summary.missing.emplace_back(from, to - 1);
  };
  const auto on_row = [&](const Row& row) {
    missing(expected, row.index);
    expected = row.index + 1;
    ++summary.rows;
    if (!row.ok()) ++summary.failed;
  };
  try {
    merge_sources(dir / "manifest.csv", pointers, sources, accept, on_row, true);
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const render::OutputError*>(&e) != nullptr) throw;
    throw SweepUsageError(fmt::format("--merge: {}", e.what()));
  }
  missing(expected, definition.variants);
  if (summary.foreign > 0) {
    summary.notes.push_back(fmt::format("{} rows of the parts belong to another sweep (their variants differ from "
                                        "{}'s) and were ignored",
                                        summary.foreign, kSweepFile));
  }
  write_reports(dir, definition, summary.notes);
  return summary;
}

}  // namespace pita::sweep
