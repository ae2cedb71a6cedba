// `pita sweep --merge DIR`: the shards' manifest.K-of-N.csv joined into one
// manifest.csv, each row checked against its variant, and the gaps named.
#include <algorithm>
#include <filesystem>
#include <regex>
#include <system_error>

#include <fmt/format.h>
#include <sys/resource.h>

#include "io/output_file.hpp"
#include "sweep/definition.hpp"
#include "sweep/folder.hpp"
#include "sweep/manifest.hpp"
#include "sweep/sweep.hpp"
#include "sweep/variant.hpp"

namespace pita::sweep {

namespace {

namespace fs = std::filesystem;

// Ranges of missing variants --merge reports (the count covers them all).
constexpr std::size_t kMaxRangesKept = 1000;
// Files open besides the parts: standard streams, the lock, the manifest
// being written, the variants' files read back, the reports.
constexpr rlim_t kOtherOpenFiles = 64;

// The parts are read side by side, one open file each: raises the soft limit
// of open files (ulimit -n, often 1024) up to the hard one when they need it,
// and refuses, saying so, when even that is too few.
void ensure_open_files(std::size_t parts, const std::string& dir_text) {
  rlimit limit{};
  if (::getrlimit(RLIMIT_NOFILE, &limit) != 0) return;
  const rlim_t needed = static_cast<rlim_t>(parts) + kOtherOpenFiles;
  if (limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur < needed) {
    rlimit raised = limit;
    raised.rlim_cur = limit.rlim_max == RLIM_INFINITY ? needed : std::min(needed, limit.rlim_max);
    if (::setrlimit(RLIMIT_NOFILE, &raised) == 0) limit = raised;
  }
  if (limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur < needed) {
    throw SweepUsageError(About{Input::merge, dir_text},
                          fmt::format("its {} parts need {} open files, more than this process may open ({}, the hard "
                                      "limit of ulimit -n); merge fewer, larger shards (a smaller N)",
                                      parts, needed, limit.rlim_cur));
  }
}

// The sweep again, from its definition: each row of the parts must be its
// variant (same values, same content hash), else it is another sweep's.
Grid grid_of(const Definition& definition, const std::string& dir_text) {
  std::vector<Axis> axes;
  for (const auto& [pointer, spec] : definition.axes) axes.push_back(parse_axis(pointer + "=" + spec));
  Grid grid(std::move(axes), definition.zip);
  if (grid.size() != definition.variants) {
    throw SweepUsageError(About{Input::merge, dir_text},
                          fmt::format("{} does not add up ({} variants, its axes make {})", kSweepFile,
                                      definition.variants, grid.size()));
  }
  return grid;
}

// The shards' parts in DIR (manifest.K-of-N.csv), in order of name.
std::vector<fs::path> find_parts(const fs::path& dir) {
  std::vector<fs::path> parts;
  std::error_code error;
  static const std::regex kPart(R"(manifest\.[0-9]+-of-[0-9]+\.csv)");
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, error)) {
    if (std::regex_match(entry.path().filename().string(), kPart)) parts.push_back(entry.path());
  }
  std::sort(parts.begin(), parts.end());
  return parts;
}

// N when all parts are of one split into N shards (the missing variants are
// then counted per shard), else 0.
int shard_count(const std::vector<fs::path>& parts) {
  static const std::regex kOfN(R"(manifest\.[0-9]+-of-([0-9]+)\.csv)");
  int shards = 0;
  for (const fs::path& part : parts) {
    std::smatch m;
    const std::string name = part.filename().string();
    std::regex_match(name, m, kOfN);
    const int n = m[1].length() <= 9 ? std::stoi(m[1].str()) : 0;
    shards = part == parts.front() || shards == n ? n : 0;
    if (shards == 0) break;
  }
  return shards;
}

// The parts as readers of rows in order of index: a part of another sweep
// (its header) is left out with a note in `summary`, one that cannot be read
// is an error. Its names go into summary.parts.
std::vector<ManifestReader> open_parts(const std::vector<fs::path>& parts, const std::vector<std::string>& pointers,
                                       MergeSummary& summary) {
  std::vector<ManifestReader> sources;
  for (const fs::path& part : parts) {
    try {
      if (!ManifestReader::open(part, pointers)) continue;
    } catch (const io::OutputError&) {  // there, but cannot be read: never left out
      throw;
    } catch (const std::runtime_error& e) {  // the header of another sweep
      summary.notes.push_back(fmt::format("{} ignored: {}", part.filename().string(), e.what()));
      continue;
    }
    try {
      // A part out of order (edited, concatenated) is sorted in memory; one
      // in order, as every run writes it, is streamed. A variant twice in a
      // part is refused.
      std::optional<ManifestReader> reader = ManifestReader::is_sorted(part, pointers)
                                                 ? ManifestReader::open(part, pointers)
                                                 : ManifestReader::open_sorted(part, pointers);
      if (reader) {
        sources.push_back(std::move(*reader));
        summary.parts.push_back(part.filename().string());
      }
    } catch (const io::OutputError&) {
      throw;
    } catch (const std::runtime_error& e) {
      throw SweepUsageError(About{Input::merge}, e.what());
    }
  }
  return sources;
}

// The variants in no part, told range by range in order of index: counted,
// their first kMaxRangesKept ranges kept, and counted per shard when the
// parts are of one split into N (N at most kMaxShardsCounted).
class MissingVariants {
 public:
  explicit MissingVariants(MergeSummary& summary)
      : summary_(summary),
        in_shard_(
            summary.shards > 0 && summary.shards <= kMaxShardsCounted ? static_cast<std::size_t>(summary.shards) : 0,
            0) {}

  // The variants [from, to).
  void add(std::int64_t from, std::int64_t to) {
    if (from >= to) return;
    summary_.missing_count += to - from;
    if (summary_.missing.size() < kMaxRangesKept) summary_.missing.emplace_back(from, to - 1);
    if (in_shard_.empty()) return;
    const auto n = static_cast<std::int64_t>(in_shard_.size());
    if (to - from >= n) {  // every shard loses (to - from) / n, and some one more
      for (std::int64_t k = 0; k < n; ++k) {
        in_shard_[static_cast<std::size_t>(k)] += (to - from) / n + (((k - from) % n + n) % n < (to - from) % n);
      }
    } else {
      for (std::int64_t i = from; i < to; ++i) ++in_shard_[static_cast<std::size_t>(i % n)];
    }
  }

  // The shards with variants missing, into summary.missing_shards.
  void name_shards() const {
    for (std::size_t k = 0; k < in_shard_.size() && summary_.missing_shards.size() < kMaxRangesKept; ++k) {
      if (in_shard_[k] > 0) summary_.missing_shards.emplace_back(static_cast<int>(k), in_shard_[k]);
    }
  }

 private:
  static constexpr int kMaxShardsCounted = 1'000'000;
  MergeSummary& summary_;
  std::vector<std::int64_t> in_shard_;
};

}  // namespace

MergeSummary merge_sweep(const std::string& dir_text, bool wait) {
  const fs::path dir(dir_text);
  const Definition definition = read_definition(dir);
  const FolderLock lock(dir, manifest_name(std::nullopt), About{Input::merge, dir_text}, wait);
  const std::vector<std::string> pointers = pointers_of(definition);
  const Grid grid = grid_of(definition, dir_text);
  const BaseScene base{definition.scene, definition.base};
  MergeSummary summary;
  summary.variants = definition.variants;
  const std::vector<fs::path> parts = find_parts(dir);
  summary.shards = shard_count(parts);
  MissingVariants missing(summary);
  if (parts.empty()) {
    throw SweepUsageError(About{Input::merge, dir_text, Input::shard}, "no manifest.K-of-N.csv there");
  }
  ensure_open_files(parts.size(), dir_text);
  std::vector<ManifestReader> sources = open_parts(parts, pointers, summary);
  const auto accept = [&](const Row& row, std::size_t) {
    if (row.index < 0 || row.index >= definition.variants) return false;
    const std::string text = variant_text(variant_document(base, grid, grid.values(row.index)));
    if (row.hash == content_hash(text, definition.salt)) return true;
    ++summary.foreign;
    return false;
  };
  std::int64_t expected = 0;
  const auto on_row = [&](const Row& row) {
    missing.add(expected, row.index);
    expected = row.index + 1;
    ++summary.rows;
    if (!row.ok()) ++summary.failed;
  };
  try {
    merge_sources(dir / "manifest.csv", pointers, sources, accept, on_row, SameIndex::refuse_conflict);
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const io::OutputError*>(&e) != nullptr) throw;
    throw SweepUsageError(About{Input::merge}, e.what());
  }
  missing.add(expected, definition.variants);
  missing.name_shards();
  if (summary.foreign > 0) {
    summary.notes.push_back(
        fmt::format("{} rows of the parts belong to another sweep (their variants differ from "
                    "{}'s) and were ignored",
                    summary.foreign, kSweepFile));
  }
  write_reports(dir, definition, summary.notes);
  return summary;
}

}  // namespace pita::sweep
