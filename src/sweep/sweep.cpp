#include "sweep/sweep.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <system_error>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "animate/progress.hpp"
#include "core/worker_pool.hpp"
#include "io/interrupt.hpp"
#include "io/output_file.hpp"
#include "scene/scene.hpp"
#include "sweep/definition.hpp"
#include "sweep/folder.hpp"
#include "sweep/grid.hpp"
#include "sweep/manifest.hpp"
#include "sweep/run_variant.hpp"
#include "sweep/sheet.hpp"
#include "sweep/unchanged_axes.hpp"
#include "sweep/variant.hpp"

namespace pita::sweep {

namespace {

namespace fs = std::filesystem;

// A running sweep rewrites its manifest this often, so that even a killed
// process (SIGKILL, a lost node) leaves a manifest of most of what finished.
constexpr auto kManifestInterval = std::chrono::seconds(5);
// Variants run ahead of the first one not yet journaled, at most (per run; at
// least 64 per thread).
constexpr std::int64_t kRowsAhead = 1024;
// Failed variants listed in the summary (the manifest has them all).
constexpr std::size_t kMaxFailuresKept = 1000;

// `metrics_only`: a row without outputs is complete (--format metrics).
bool outputs_exist(const fs::path& dir, const Row& row, bool metrics_only) {
  if (row.outputs.empty()) return metrics_only;
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

std::string index_ranges(const std::vector<std::pair<std::int64_t, std::int64_t>>& ranges) {
  std::string out;
  for (const auto& [first, last] : ranges) {
    out += fmt::format("{}{}", out.empty() ? "" : ", ",
                       first == last ? std::to_string(first) : fmt::format("{}-{}", first, last));
  }
  return out;
}

namespace {

// The output folder, created when missing, refused when it holds files a
// sweep did not write (folder.hpp).
fs::path output_folder(const SweepOptions& options) {
  const fs::path dir(options.output);
  // "out.png": a file's name, not a folder to create (an existing folder of
  // that name is used).
  std::error_code error;
  if (dir.has_extension() && dir.extension() != "." && !fs::is_directory(dir, error)) {
    throw SweepUsageError(About{Input::output, options.output},
                          fmt::format("a sweep writes into a folder, and \"{}\" is the extension of a file: give a "
                                      "folder's name without one (an existing folder of that name is used)",
                                      dir.extension().string()));
  }
  claim_folder(dir, options.output, options.scene_path);
  return dir;
}

// "<name>-<index>.<what>" -> index, or -1.
std::int64_t variant_index_of(const std::string& file, const std::string& name) {
  if (file.size() <= name.size() + 1 || file.compare(0, name.size(), name) != 0 || file[name.size()] != '-') return -1;
  std::size_t at = name.size() + 1;
  const std::size_t digits_start = at;
  while (at < file.size() && at - digits_start < 18 && file[at] >= '0' && file[at] <= '9') ++at;
  if (at == digits_start || at >= file.size() || file[at] != '.') return -1;
  return std::stoll(file.substr(digits_start, at - digits_start));
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
  for (const OutputKind k : options.formats) definition.formats.emplace_back(output_kind_name(k));
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
        // (fmt, not "." + std::string: GCC 12 warns falsely of a memcpy
        // overflow, -Wstringop-overflow, when that is inlined here.)
        journal_path_(dir_ / fmt::format(".{}.journal", manifest_name(options.shard))),
        shard_k_(options.shard ? options.shard->first : 0),
        shard_n_(options.shard ? options.shard->second : 1),
        mine_(grid.size() > shard_k_ ? (grid.size() - shard_k_ + shard_n_ - 1) / shard_n_ : 0),
        kept_(static_cast<std::size_t>(mine_), 0),
        unchanged_(grid) {
    summary_.variants = mine_;
  }

  SweepSummary run() {
    // One run per manifest at a time; then what a killed run of this shard
    // left half-written goes.
    const FolderLock lock(dir_, manifest_name(options_.shard), About{Input::output, options_.output}, options_.wait);
    remove_stale_temporaries(dir_, [this](const std::string& target) { return stale_is_mine(target); });
    if (!options_.force) resume();
    std::error_code ignored;
    fs::remove(journal_path_, ignored);
    io::write_file_atomically(dir_ / kSweepFile, definition_json(definition_));
    run_variants();
    note_unchanged_axes();
    write_manifest();
    if (!options_.shard) write_reports(dir_, definition_, summary_.notes);
    return summary_;
  }

 private:
  std::int64_t position(std::int64_t index) const { return (index - shard_k_) / shard_n_; }
  bool in_shard(std::int64_t index) const { return index >= 0 && index < grid_.size() && index % shard_n_ == shard_k_; }
  // A row of an earlier run is kept when its variant is unchanged (same
  // content hash), it is ok and its outputs all exist.
  bool valid(const Row& row) const {
    if (!in_shard(row.index) || !row.ok() || !outputs_exist(dir_, row, metrics_only(options_.formats))) return false;
    return content_hash(variant_text(variant_document(base_, grid_, grid_.values(row.index))), definition_.salt) ==
           row.hash;
  }
  // The temporaries this run would write: its variants' files and manifest,
  // and (unsharded) the folder's own files.
  bool stale_is_mine(const std::string& target) const {
    if (target == manifest_name(options_.shard)) return true;
    if (!options_.shard) {
      for (const std::string_view own : {kSweepFile, kFolderMarker, std::string_view("index.html"),
                                         std::string_view("contact.svg"), std::string_view("contact.png")}) {
        if (target == own) return true;
      }
    }
    return in_shard(variant_index_of(target, definition_.name));
  }
  [[noreturn]] void refuse_folder(const std::runtime_error& error) const {
    throw SweepUsageError(About{Input::output, options_.output, Input::force}, error.what());
  }

  // Resume: the valid rows of an earlier run (its manifest, or the journal of
  // a killed run) are kept; the others are done again. Nothing but one byte
  // per variant is held. A manifest of another sweep (other pointers) is
  // refused before anything is written.
  void resume() {
    std::optional<ManifestReader> old;
    try {
      old = ManifestReader::open(manifest_path_, pointers_);
    } catch (const io::OutputError&) {
      throw;  // there, but cannot be read (exit 3)
    } catch (const std::runtime_error& error) {
      refuse_folder(error);
    }
    std::optional<ManifestReader> journal = ManifestReader::open(journal_path_, pointers_, true);
    have_manifest_ = old.has_value();
    for (auto* reader : {old ? &*old : nullptr, journal ? &*journal : nullptr}) {
      if (reader == nullptr) continue;
      Row row;
      std::int64_t last = -1;
      try {
        while (reader->next(row)) {
          // Rows in increasing order, each once, as every run writes them:
          // a manifest edited out of order is refused here, before any work.
          if (row.index <= last) {
            throw std::runtime_error(
                fmt::format("{}: variant {} is out of order or repeated (a manifest lists each "
                            "variant once, in increasing order)",
                            reader->where(), row.index));
          }
          last = row.index;
          const auto j = static_cast<std::size_t>(position(row.index));
          if (valid(row) && kept_[j] == 0) {
            kept_[j] = 1;
            ++summary_.skipped;
          }
        }
      } catch (const io::OutputError&) {
        throw;
      } catch (const std::runtime_error& error) {
        refuse_folder(error);
      }
    }
    if (journal) {
      // Fold the killed run's journal into the manifest, then start a new one.
      std::vector<ManifestReader> sources;
      if (auto m = ManifestReader::open(manifest_path_, pointers_)) sources.push_back(std::move(*m));
      if (auto j = ManifestReader::open(journal_path_, pointers_, true)) sources.push_back(std::move(*j));
      merge_sources(
          manifest_path_, pointers_, sources, [&](const Row& row, std::size_t) { return valid(row); },
          [](const Row&) {}, SameIndex::later_wins);
      have_manifest_ = true;
    }
  }

  // A variant's row: run, or (resumed) nothing to do.
  struct Finished {
    Row row;
    VariantOutcome outcome;
  };
  std::optional<Finished> produce(std::int64_t j) const {
    if (kept_[static_cast<std::size_t>(j)] != 0) return std::nullopt;  // resumed
    const std::int64_t index = shard_k_ + j * shard_n_;
    Finished finished;
    try {
      finished.row = run_variant(job_, index, finished.outcome);
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
      throw io::OutputError(fmt::format("{}: cannot write ({})", journal_path_.string(), std::strerror(errno)));
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
      summary_.write_failed = summary_.write_failed || finished->outcome.write_failed;
      if (finished->outcome.metrics_skipped) ++metrics_skipped_;
      const Row& row = finished->row;
      unchanged_.add(row.index, finished->outcome.digest);
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
      const io::DeferredInterrupts deferred;
      PoolOptions pool;
      pool.threads = static_cast<int>(std::min<std::int64_t>(options_.jobs, std::max<std::int64_t>(mine_, 1)));
      // Rows finished ahead of an earlier, slower variant wait in memory: at
      // most this many, so that memory does not grow with the sweep (a
      // resumed run produces its skipped variants faster than it journals).
      pool.window = std::max<std::int64_t>(kRowsAhead, 64 * static_cast<std::int64_t>(pool.threads));
      const auto tick = [&] {
        progress.update(static_cast<int>(std::min<std::int64_t>(done, INT32_MAX)));
        return io::pending_interrupt() == 0;  // a signal: stop, keep what is journaled
      };
      try {
        run_ordered(
            mine_, pool, [this](std::int64_t j, const std::atomic<bool>&) { return produce(j); }, journal_row, tick);
      } catch (const std::system_error& error) {
        throw SweepUsageError(About{Input::jobs, std::to_string(options_.jobs)},
                              fmt::format("cannot start a thread ({})", error.what()));
      }
    }
    progress.update(static_cast<int>(std::min<std::int64_t>(done, INT32_MAX)));
    if (metrics_skipped_ > 0) {
      summary_.notes.push_back(
          fmt::format("{} variant{} without metrics: measuring their motion costs more than "
                      "the limit of pita measure (fewer keyframes, or the local \"blend\" "
                      "chain)",
                      metrics_skipped_, metrics_skipped_ == 1 ? "" : "s"));
    }
  }

  // The axes that changed nothing (sweep/unchanged_axes.hpp), said in a
  // note with what was compared.
  void note_unchanged_axes() {
    const std::vector<std::string> unchanged = unchanged_.unchanged();
    if (unchanged.empty()) return;
    std::vector<std::string> shown;
    for (const OutputKind kind : options_.formats) {
      const std::string_view what = kind == OutputKind::metrics                           ? "metrics"
                                    : kind == OutputKind::csv || kind == OutputKind::json ? "frames"
                                                                                          : "figures (titles aside)";
      if (std::find(shown.begin(), shown.end(), what) == shown.end()) shown.emplace_back(what);
    }
    if (std::find(shown.begin(), shown.end(), "metrics") == shown.end()) shown.emplace_back("metrics");
    std::string compared;
    for (std::size_t i = 0; i < shown.size(); ++i) {
      compared += (i == 0 ? "" : i + 1 == shown.size() ? " and " : ", ") + shown[i];
    }
    for (const std::string& pointer : unchanged) {
      summary_.notes.push_back(
          fmt::format("{} changed nothing: every value of it gave the same {} as its first value", pointer, compared));
    }
  }

  // The manifest: the rows kept from before and the journal's, in order (an
  // interrupted run's rows that were still waiting for an earlier one are
  // left out: their variants are done again). Then the journal goes; a
  // pending signal ends the process here.
  void write_manifest() {
    const int sig = io::pending_interrupt();
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
      merge_sources(
          manifest_path_, pointers_, sources, accept, [](const Row&) {}, SameIndex::later_wins);
    } catch (const io::OutputError&) {
      if (sig != 0) io::exit_interrupted(sig);  // the journal stays: the next run folds it
      throw;
    }
    std::error_code ignored;
    fs::remove(journal_path_, ignored);
    if (sig != 0) io::exit_interrupted(sig);
  }

  const SweepOptions& options_;
  const Grid& grid_;
  const BaseScene& base_;
  const fs::path dir_;
  const Definition& definition_;
  const VariantJob job_;
  const std::vector<std::string> pointers_;
  const fs::path manifest_path_;
  const fs::path journal_path_;
  const int shard_k_;
  const int shard_n_;
  const std::int64_t mine_;
  std::vector<char> kept_;  // per variant of the shard: resumed from an earlier run
  UnchangedAxes unchanged_;
  bool have_manifest_ = false;
  std::int64_t metrics_skipped_ = 0;
  SweepSummary summary_;
};

}  // namespace

namespace {

// "/method" varied on a scene whose panels all set their own method changes
// no figure and no metric (they are the panels'), only pita eval's frames of
// the scene's own motion: refused unless those are asked for (csv, json).
void check_method_axis(const BaseScene& base, const Grid& grid, const std::vector<OutputKind>& formats) {
  if (std::any_of(formats.begin(), formats.end(),
                  [](OutputKind k) { return k == OutputKind::csv || k == OutputKind::json; })) {
    return;
  }
  const std::vector<std::string> own = scene::panels_with_own_methods(base.document);
  if (own.empty()) return;
  for (const Axis& axis : grid.axes()) {
    if (axis.pointer != "/method") continue;
    throw SweepUsageError(About(Input::vary, axis.pointer + "=" + axis.spec),
                          fmt::format("every panel sets its own method ({}), so no figure or metric draws the "
                                      "scene's \"method\": vary a panel's (/panels/K/method) instead, or ask for "
                                      "the frames of the scene's own motion (csv, json)",
                                      fmt::join(own, ", ")));
  }
}

}  // namespace

SweepSummary run_sweep(const SweepOptions& options) {
  if (options.jobs < 1) throw SweepUsageError(About{Input::jobs}, fmt::format("must be >= 1 (got {})", options.jobs));
  std::vector<Axis> axes;
  for (const std::string& v : options.vary) axes.push_back(parse_axis(v));
  const Grid grid(std::move(axes), options.zip);
  const BaseScene base = load_base(options.scene_path, grid);
  check_method_axis(base, grid, options.formats);
  fs::path dir = output_folder(options);
  const Definition definition = definition_of(options, grid, base);
  return SweepRun(options, grid, base, std::move(dir), definition).run();
}

}  // namespace pita::sweep
