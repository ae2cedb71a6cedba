#include "sweep/sweep.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <regex>
#include <system_error>
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

// Writes the manifest, index and contact sheet of `rows` (an unsharded run, or a merge).
void write_reports(const fs::path& dir, const Definition& d, const std::map<std::int64_t, Row>& rows,
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
  const std::string scene_file = variant_file(job.name, index, variants, "scene.json");
  try {
    // Read as if it were the base scene's file (relative image paths), named
    // in messages as the variant's own file.
    const scene::Scene scene = scene::parse_scene(text, job.base.path);
    motion::check_motions(scene);
    std::vector<std::pair<fs::path, std::string>> files;
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
  const auto [shard_k, shard_n] = options.shard.value_or(std::pair<int, int>{0, 1});
  const std::int64_t variants = grid.size();
  const std::int64_t mine = variants > shard_k ? (variants - shard_k + shard_n - 1) / shard_n : 0;

  // Resume: rows of an earlier run whose variant is unchanged and whose
  // outputs are all there are kept; the others are done again. A manifest of
  // another sweep (other pointers) is refused before anything is written.
  std::map<std::int64_t, Row> table;
  SweepSummary summary;
  summary.variants = mine;
  std::optional<std::vector<Row>> old;
  try {
    old = read_manifest(dir / manifest, pointers);
  } catch (const std::runtime_error& error) {
    if (!options.force) {
      throw SweepUsageError(fmt::format("-o {}: {} (or --force to start this sweep over there)", options.output,
                                        error.what()));
    }
  }
  if (old && !options.force) {
    for (Row& row : *old) {
      if (row.index < 0 || row.index >= variants || row.index % shard_n != shard_k || !row.ok()) continue;
      if (!outputs_exist(dir, row)) continue;
      const std::string text = variant_text(variant_document(base, grid, grid.values(row.index)));
      if (content_hash(text, salt) != row.hash) continue;
      table.emplace(row.index, std::move(row));
    }
  }
  old.reset();
  summary.skipped = static_cast<std::int64_t>(table.size());
  render::write_file_atomically(dir / kSweepFile, definition_json(definition));

  std::mutex mutex;
  std::condition_variable finished;
  std::atomic<std::int64_t> next{0};
  std::atomic<bool> stop{false};
  std::int64_t done = 0;  // in this run (resumed variants are not counted)
  int running = 0;
  bool write_failed = false;
  const auto manifest_text = [&] {
    const std::lock_guard lock(mutex);
    return manifest_csv(pointers, table);
  };

  const auto work = static_cast<int>(std::min<std::int64_t>(mine - summary.skipped, INT32_MAX));
  animate::Progress progress("pita sweep", work, !options.quiet, true);
  {
    const render::DeferredInterrupts deferred;
    const int threads = static_cast<int>(std::min<std::int64_t>(options.jobs, std::max<std::int64_t>(mine, 1)));
    std::vector<std::thread> pool;
    // Joins whatever was started, also when the main thread throws.
    struct Joiner {
      std::vector<std::thread>& pool;
      std::atomic<bool>& stop;
      ~Joiner() {
        stop = true;
        for (std::thread& t : pool) {
          if (t.joinable()) t.join();
        }
      }
    } joiner{pool, stop};
    const auto worker = [&] {
      bool failed_write = false;
      while (!stop.load() && render::pending_interrupt() == 0) {
        const std::int64_t j = next.fetch_add(1);
        if (j >= mine) break;
        const std::int64_t index = shard_k + j * shard_n;
        {
          const std::lock_guard lock(mutex);
          if (table.contains(index)) continue;  // resumed
        }
        Row row;
        try {
          row = run_variant(job, index, failed_write);
        } catch (const std::exception& error) {
          // Nothing a variant does may end the sweep: it is a failed row.
          row.index = index;
          row.values.assign(pointers.size(), "");
          row.status = fmt::format("internal error: {}", error.what());
        }
        const std::lock_guard lock(mutex);
        table[index] = std::move(row);
        ++done;
      }
      const std::lock_guard lock(mutex);
      write_failed = write_failed || failed_write;
      --running;
      finished.notify_all();
    };
    {
      const std::lock_guard lock(mutex);
      running = threads;  // before any starts: a worker that ends at once counts down from here
    }
    for (int t = 0; t < threads; ++t) {
      try {
        pool.emplace_back(worker);
      } catch (const std::system_error& error) {
        {
          const std::lock_guard lock(mutex);
          running -= threads - t;
        }
        if (pool.empty()) {
          throw SweepUsageError(fmt::format("--jobs {}: cannot start a thread ({})", options.jobs, error.what()));
        }
        break;  // fewer threads than asked
      }
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
        try {
          render::write_file_atomically(dir / manifest, manifest_text());
        } catch (const render::OutputError&) {
          // Said at the end, where the manifest is written once more.
        }
        last_write = std::chrono::steady_clock::now();
      }
      lock.lock();
    }
    lock.unlock();
    for (std::thread& thread : pool) thread.join();
    if (const int sig = render::pending_interrupt()) {
      // Complete files only (each variant's set is written all or none), and
      // the manifest of every variant that finished: rerunning completes it.
      try {
        render::write_file_atomically(dir / manifest, manifest_text());
      } catch (const render::OutputError&) {
      }
      render::exit_interrupted(sig);
    }
  }
  progress.update(static_cast<int>(std::min<std::int64_t>(done, INT32_MAX)));
  summary.write_failed = write_failed;

  for (const auto& [index, row] : table) {
    if (row.ok()) {
      ++summary.ok;
    } else {
      ++summary.failed;
      if (summary.failures.size() < kMaxFailuresKept) summary.failures.push_back(failure_line(pointers, row));
    }
  }
  summary.ok -= summary.skipped;
  if (options.shard) {
    render::write_file_atomically(dir / manifest, manifest_csv(pointers, table));
    summary.notes.push_back(fmt::format("shard {}/{}: join the shards with pita sweep --merge {}", shard_k, shard_n,
                                        options.output));
  } else {
    write_reports(dir, definition, table, summary.notes);
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
  std::map<std::int64_t, Row> table;
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
  for (const fs::path& part : parts) {
    std::optional<std::vector<Row>> rows;
    try {
      rows = read_manifest(part, pointers);
    } catch (const std::runtime_error& e) {
      summary.notes.push_back(fmt::format("{} ignored: {}", part.filename().string(), e.what()));
      continue;
    }
    summary.parts.push_back(part.filename().string());
    for (Row& row : *rows) {
      if (row.index < 0 || row.index >= definition.variants) continue;
      const std::string text = variant_text(variant_document(base, grid, grid.values(row.index)));
      if (row.hash != content_hash(text, definition.salt)) {
        ++summary.foreign;
        continue;
      }
      auto found = table.find(row.index);
      // A row that succeeded wins over a failed one of another part.
      if (found == table.end() || (!found->second.ok() && row.ok())) table[row.index] = std::move(row);
    }
  }
  if (summary.foreign > 0) {
    summary.notes.push_back(fmt::format("{} rows of the parts belong to another sweep (their variants differ from "
                                        "{}'s) and were ignored",
                                        summary.foreign, kSweepFile));
  }
  std::int64_t expected = 0;
  const auto missing = [&](std::int64_t from, std::int64_t to) {  // [from, to)
    if (from >= to) return;
    summary.missing_count += to - from;
    if (summary.missing.size() < kMaxRangesKept) summary.missing.emplace_back(from, to - 1);
  };
  for (const auto& [index, row] : table) {
    missing(expected, index);
    expected = index + 1;
    if (!row.ok()) ++summary.failed;
  }
  missing(expected, definition.variants);
  summary.rows = static_cast<std::int64_t>(table.size());
  write_reports(dir, definition, table, summary.notes);
  return summary;
}

}  // namespace pita::sweep
