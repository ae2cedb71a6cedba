// DIR/manifest.csv: one row per variant of a sweep (docs/reference/sweep.md "pita sweep"):
//   index, one column per varied pointer (its value), status ("ok" or the
//   error with its pointer), outputs (";"-separated file names in DIR), hash
//   (the variant's content hash), then the metric columns of kMetricColumns.
// Read back by a resumed sweep (what to skip) and by --merge (the shards).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <istream>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "io/output_file.hpp"

namespace pita::sweep {

// The metrics of the figure's first panel (the scene's own motion without
// panels; pita measure, docs/reference/measure.md "pita measure"):
// empty where they do not apply (pose metrics on arrows and the reverse).
inline constexpr std::array<std::string_view, 18> kMetricColumns = {"path_length_p",
                                                                    "path_length_q",
                                                                    "turning_p",
                                                                    "turning_q",
                                                                    "winding_min",
                                                                    "winding_max",
                                                                    "discrepancy_max",
                                                                    "discrepancy_max_previous",
                                                                    "discrepancy_max_average",
                                                                    "discrepancy_t_of_max",
                                                                    "most_sensitive",
                                                                    "gain",
                                                                    "pop_jump",
                                                                    "pops",
                                                                    "ara",
                                                                    "area_monotone",
                                                                    "inflections_p",
                                                                    "inflections_q"};

struct Row {
  std::int64_t index = 0;
  std::vector<std::string> values;   // one per axis, as value_text prints them
  std::string status;                // "ok", or the error
  std::vector<std::string> outputs;  // file names in DIR
  std::string hash;
  std::array<std::string, kMetricColumns.size()> metrics{};
  bool ok() const { return status == "ok"; }
  bool operator==(const Row&) const = default;
};

// The CSV text of `rows` (sorted by index) under a header naming `pointers`.
std::string manifest_csv(const std::vector<std::string>& pointers, const std::vector<Row>& rows);
std::string manifest_csv(const std::vector<std::string>& pointers, const std::map<std::int64_t, Row>& rows);

// The header line, and one row's line (appended to `out`).
std::string manifest_header(const std::vector<std::string>& pointers);
void append_row(std::string& out, const Row& row);

// Reads a manifest row by row, without holding it: what a sweep of millions
// of variants resumes and merges from.
class ManifestReader {
 public:
  // nullopt when the file does not exist. Throws io::OutputError naming
  // the file when it exists but cannot be opened, std::runtime_error when it
  // is not a regular file (a FIFO, a device) or its header is not that of
  // these pointers; `headless`: a journal, rows only.
  static std::optional<ManifestReader> open(const std::filesystem::path& path, const std::vector<std::string>& pointers,
                                            bool headless = false);
  // Whether the rows of the manifest at `path` are in strictly increasing
  // order of index (what a run writes; a part edited by hand may not be).
  // Reads it once, holding one row.
  static bool is_sorted(const std::filesystem::path& path, const std::vector<std::string>& pointers);
  // The manifest's rows sorted by index, held in memory: for a part written
  // out of order. Throws std::runtime_error naming the file and both lines
  // of an index that appears twice.
  static std::optional<ManifestReader> open_sorted(const std::filesystem::path& path,
                                                   const std::vector<std::string>& pointers);
  // The next row; false at the end (or at a last line cut short). Throws
  // std::runtime_error naming the file and line of a malformed row.
  bool next(Row& row);
  // Where the row last returned by next() is: "manifest.0-of-2.csv:7".
  std::string where() const;

 private:
  // The longest field a manifest may hold: rows pita writes are far shorter
  // (a status is a message, an outputs list a few names).
  static constexpr std::size_t kMaxRecordBytes = std::size_t{1} << 20;
  ManifestReader() = default;
  bool record(std::vector<std::string>& fields);
  bool read_row(Row& row);
  std::unique_ptr<std::istream> in_;
  std::string path_;
  std::size_t pointers_ = 0;
  int line_ = 0;
  bool complete_ = true;
  // open_sorted: the rows and their lines, served in order from `at_`.
  std::vector<std::pair<int, Row>> held_;
  std::size_t at_ = 0;
  bool holding_ = false;
  int row_line_ = 0;
};

// Reads a manifest written by manifest_csv; nullopt when the file does not
// exist. Throws std::runtime_error naming the file and line when it is not a
// manifest of these pointers.
std::optional<std::vector<Row>> read_manifest(const std::filesystem::path& path,
                                              const std::vector<std::string>& pointers);

// "manifest.csv", or "manifest.K-of-N.csv" for shard K of N.
std::string manifest_name(std::optional<std::pair<int, int>> shard);

// DIR/<name>-<index>.<extension>: fig01-eight-pitas-7.svg (the index as it
// is, so that a script finds variant i without knowing the sweep's size).
std::string variant_file(const std::string& name, std::int64_t index, std::int64_t variants,
                         const std::string& extension);

// RFC 4180 quoting of one field (quotes, commas, line breaks).
std::string csv_field(std::string_view text);

// What merge_sources does with accepted rows of one index in several sources.
enum class SameIndex {
  later_wins,       // a resumed run: the journal's row replaces the old manifest's
  refuse_conflict,  // --merge: identical rows are one, different ones an error
};

// A manifest written from sources of rows, each sorted by index, without
// holding them. `accept(row, source)` filters; `on_row` sees each row
// written. Throws std::runtime_error naming the files and lines of a source
// out of order, or (refuse_conflict) of two different rows of one index.
template <typename Accept, typename OnRow>
void merge_sources(const std::filesystem::path& path, const std::vector<std::string>& pointers,
                   std::vector<ManifestReader>& sources, Accept accept, OnRow on_row, SameIndex same) {
  io::StreamingOutput out(path);
  out.write(manifest_header(pointers));
  std::vector<std::optional<Row>> heads(sources.size());
  std::vector<std::int64_t> last(sources.size(), -1);
  const auto advance = [&](std::size_t s) {
    heads[s].reset();
    Row row;
    while (sources[s].next(row)) {
      if (row.index <= last[s]) {
        throw std::runtime_error(fmt::format(
            "{}: variant {} {} (the rows must be in increasing order of index, each "
            "once)",
            sources[s].where(), row.index, row.index == last[s] ? "appears twice" : "comes after a later one"));
      }
      last[s] = row.index;
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
      if (best && same == SameIndex::refuse_conflict && !(*heads[s] == *heads[*best])) {
        throw std::runtime_error(
            fmt::format("variant {} has two different rows, {} and {}: remove the part that is "
                        "stale (a run split into another number of shards?) and merge again",
                        *least, sources[*best].where(), sources[s].where()));
      }
      best = s;
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

}  // namespace pita::sweep
