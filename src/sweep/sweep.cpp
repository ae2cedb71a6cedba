#include "sweep/sweep.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include <fmt/format.h>

#include "analysis/measure.hpp"
#include "animate/progress.hpp"
#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"
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

// The metrics of the scene's own motion (kMetricColumns).
std::array<std::string, kMetricColumns.size()> metrics_of(const scene::Scene& scene) {
  std::array<std::string, kMetricColumns.size()> m{};
  const analysis::MotionMeasures r = analysis::measure_panel(scene, scene::scene_panel(scene));
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
    if (d.name.empty() || d.name.find('/') != std::string::npos || d.variants < 0) throw std::runtime_error("bad name");
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

// Writes the manifest, index and contact sheet of `rows` (an unsharded run, or a merge).
void write_reports(const fs::path& dir, const Definition& d, const std::vector<Row>& rows,
                   std::vector<std::string>& notes) {
  const SheetInput input = sheet_input(dir, d);
  render::write_file_atomically(dir / "manifest.csv", manifest_csv(input.pointers, rows));
  write_index_html(input, rows);
  if (input.figures) {
    const std::string why = write_contact_sheet(input, rows);
    if (!why.empty()) notes.push_back(why);
  }
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
  try {
    const scene::Scene scene = scene::parse_scene(text, job.base.path);
    motion::check_motions(scene);
    std::vector<std::pair<fs::path, std::string>> files;
    const std::string scene_file = variant_file(job.name, index, variants, "scene.json");
    files.emplace_back(job.dir / scene_file, text);
    row.outputs.push_back(scene_file);
    std::optional<render::Figure> figure;
    for (const OutputKind kind : job.options.formats) {
      const std::string file = variant_file(job.name, index, variants, std::string(name_of(kind)));
      if (const auto format = figure_format(kind)) {
        if (!figure) figure = render::build_figure(scene);
        files.emplace_back(job.dir / file, render::render_figure(scene, *figure, *format));
      } else {
        const scene::Panel panel = scene::scene_panel(scene);
        const motion::SceneMotion motion = motion::build_motion(scene, panel);
        const std::vector<double> at =
            motion::uniform_times(motion, scene.samples.value_or(scene::kDefaultSamples));
        files.emplace_back(job.dir / file, motion::frames_text(panel, motion, at,
                                                               kind == OutputKind::csv ? motion::FramesFormat::csv
                                                                                       : motion::FramesFormat::json));
      }
      row.outputs.push_back(file);
    }
    row.metrics = metrics_of(scene);
    render::write_files_atomically(files);
    row.status = "ok";
  } catch (const render::OutputError& error) {
    row.status = fmt::format("cannot write: {}", error.what());
    row.outputs.clear();
    write_failed = true;
  } catch (const std::exception& error) {
    row.status = error.what();
    row.outputs.clear();
    row.metrics = {};
    remove_outputs(job.dir, job.name, index, variants);
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
  int k = -1, n = -1;
  try {
    std::size_t used_k = 0, used_n = 0;
    if (slash == std::string::npos) throw std::invalid_argument("no slash");
    k = std::stoi(text.substr(0, slash), &used_k);
    n = std::stoi(text.substr(slash + 1), &used_n);
    if (used_k != slash || used_n != text.size() - slash - 1) throw std::invalid_argument("trailing");
  } catch (const std::exception&) {
    throw SweepUsageError(fmt::format("--shard: expected K/N with whole numbers 0 <= K < N, for example 0/4 "
                                      "(got \"{}\")",
                                      text));
  }
  if (n < 1 || k < 0 || k >= n) {
    throw SweepUsageError(fmt::format("--shard {}: K must be in 0..N-1 and N >= 1 (got K = {}, N = {})", text, k, n));
  }
  return {k, n};
}

std::string index_ranges(const std::vector<std::int64_t>& indices) {
  std::string out;
  for (std::size_t i = 0; i < indices.size();) {
    std::size_t j = i;
    while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1) ++j;
    out += fmt::format("{}{}", out.empty() ? "" : ", ",
                       j == i ? std::to_string(indices[i]) : fmt::format("{}-{}", indices[i], indices[j]));
    i = j + 1;
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
  render::write_file_atomically(dir / kSweepFile, definition_json(definition));

  std::string salt = "pita " + options.version;
  for (const std::string& f : definition.formats) salt += " " + f;
  const Job job{options, grid, base, dir, definition.name, salt};
  const std::vector<std::string> pointers = pointers_of(definition);
  const std::string manifest = manifest_name(options.shard);
  const auto [shard_k, shard_n] = options.shard.value_or(std::pair<int, int>{0, 1});
  const std::int64_t variants = grid.size();
  const std::int64_t mine = variants > shard_k ? (variants - shard_k + shard_n - 1) / shard_n : 0;

  // Resume: rows of an earlier run whose variant is unchanged and whose
  // outputs are all there are kept; the others are done again.
  std::map<std::int64_t, Row> table;
  SweepSummary summary;
  summary.variants = mine;
  if (!options.force) {
    if (auto old = read_manifest(dir / manifest, pointers)) {
      for (Row& row : *old) {
        if (row.index < 0 || row.index >= variants || row.index % shard_n != shard_k || !row.ok()) continue;
        if (!outputs_exist(dir, row)) continue;
        const std::string text = variant_text(variant_document(base, grid, grid.values(row.index)));
        if (content_hash(text, salt) != row.hash) continue;
        table.emplace(row.index, std::move(row));
      }
    }
  }
  summary.skipped = static_cast<std::int64_t>(table.size());

  std::mutex mutex;
  std::condition_variable finished;
  std::atomic<std::int64_t> next{0};
  std::atomic<bool> stop{false};
  std::int64_t done = summary.skipped;
  int running = 0;
  bool write_failed = false;
  const auto write_manifest = [&] {
    std::vector<Row> rows;
    {
      const std::lock_guard lock(mutex);
      rows.reserve(table.size());
      for (const auto& [index, row] : table) rows.push_back(row);
    }
    render::write_file_atomically(dir / manifest, manifest_csv(pointers, rows));
  };

  animate::Progress progress("pita sweep", static_cast<int>(std::min<std::int64_t>(mine, INT32_MAX)), !options.quiet,
                             true);
  {
    const render::DeferredInterrupts deferred;
    const int threads = static_cast<int>(std::min<std::int64_t>(options.jobs, std::max<std::int64_t>(mine, 1)));
    std::vector<std::thread> pool;
    running = threads;
    for (int t = 0; t < threads; ++t) {
      pool.emplace_back([&] {
        bool failed_write = false;
        while (!stop.load() && render::pending_interrupt() == 0) {
          const std::int64_t j = next.fetch_add(1);
          const std::int64_t index = shard_k + j * shard_n;
          if (j >= mine) break;
          {
            const std::lock_guard lock(mutex);
            if (table.contains(index)) continue;  // resumed
          }
          Row row = run_variant(job, index, failed_write);
          const std::lock_guard lock(mutex);
          table[index] = std::move(row);
          ++done;
        }
        const std::lock_guard lock(mutex);
        write_failed = write_failed || failed_write;
        --running;
        finished.notify_all();
      });
    }
    auto last_write = std::chrono::steady_clock::now();
    std::unique_lock lock(mutex);
    while (running > 0) {
      finished.wait_for(lock, std::chrono::milliseconds(100));
      const std::int64_t now_done = done;
      lock.unlock();
      progress.update(static_cast<int>(std::min<std::int64_t>(now_done, INT32_MAX)));
      if (render::pending_interrupt() != 0) stop = true;
      if (std::chrono::steady_clock::now() - last_write > kManifestInterval) {
        write_manifest();
        last_write = std::chrono::steady_clock::now();
      }
      lock.lock();
    }
    lock.unlock();
    for (std::thread& thread : pool) thread.join();
    if (const int sig = render::pending_interrupt()) {
      // Complete files only (each variant's set is written all or none), and
      // the manifest of every variant that finished: rerunning completes it.
      write_manifest();
      render::exit_interrupted(sig);
    }
  }
  progress.update(static_cast<int>(std::min<std::int64_t>(done, INT32_MAX)));
  summary.write_failed = write_failed;

  std::vector<Row> rows;
  rows.reserve(table.size());
  for (auto& [index, row] : table) {
    if (row.ok()) {
      ++summary.ok;
    } else {
      ++summary.failed;
      summary.failures.push_back(failure_line(pointers, row));
    }
    rows.push_back(std::move(row));
  }
  summary.ok -= summary.skipped;
  if (options.shard) {
    render::write_file_atomically(dir / manifest, manifest_csv(pointers, rows));
    summary.notes.push_back(fmt::format("shard {}/{}: join the shards with pita sweep --merge {}", shard_k, shard_n,
                                        options.output));
  } else {
    write_reports(dir, definition, rows, summary.notes);
  }
  return summary;
}

MergeSummary merge_sweep(const std::string& dir_text, bool quiet) {
  (void)quiet;
  const fs::path dir(dir_text);
  const Definition definition = read_definition(dir);
  const std::vector<std::string> pointers = pointers_of(definition);
  MergeSummary summary;
  summary.variants = definition.variants;
  std::map<std::int64_t, Row> table;
  std::vector<fs::path> parts;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, error)) {
    const std::string file = entry.path().filename().string();
    if (file.starts_with("manifest.") && file.ends_with(".csv") && file.find("-of-") != std::string::npos) {
      parts.push_back(entry.path());
    }
  }
  std::sort(parts.begin(), parts.end());
  if (parts.empty()) {
    throw SweepUsageError(fmt::format("--merge {}: no manifest.K-of-N.csv there (run the shards with --shard K/N "
                                      "-o {} first)",
                                      dir_text, dir_text));
  }
  for (const fs::path& part : parts) {
    std::optional<std::vector<Row>> rows;
    try {
      rows = read_manifest(part, pointers);
    } catch (const std::runtime_error& e) {
      throw SweepUsageError(fmt::format("--merge: {}", e.what()));
    }
    summary.parts.push_back(part.filename().string());
    for (Row& row : *rows) {
      if (row.index < 0 || row.index >= definition.variants) continue;
      auto found = table.find(row.index);
      // A row that succeeded wins over a failed one of another part.
      if (found == table.end() || (!found->second.ok() && row.ok())) table[row.index] = std::move(row);
    }
  }
  std::vector<Row> rows;
  std::int64_t expected = 0;
  for (auto& [index, row] : table) {
    while (expected < index) summary.missing.push_back(expected++);
    expected = index + 1;
    if (!row.ok()) ++summary.failed;
    rows.push_back(std::move(row));
  }
  while (expected < definition.variants) summary.missing.push_back(expected++);
  summary.rows = static_cast<std::int64_t>(rows.size());
  write_reports(dir, definition, rows, summary.notes);
  return summary;
}

}  // namespace pita::sweep
