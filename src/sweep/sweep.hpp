// pita sweep (docs/reference/sweep.md "pita sweep"): the variants of a scene, each with values
// set at JSON Pointers, run in-process on a pool of threads; their figures
// and frames, a manifest with metrics, a contact sheet and an HTML index.
// Resumable (a variant whose outputs exist under the same content hash is
// skipped), interruptible (SIGINT/SIGTERM leave complete files and a manifest
// of what finished), and sharded for batch clusters (--shard K/N, --merge).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sweep/grid.hpp"

namespace pita::sweep {

// What a sweep may write for each variant; `metrics` alone writes no file
// per variant, only its manifest row (a sweep of millions of variants).
enum class OutputKind { svg, png, pdf, csv, json, metrics };

// Whether `formats` asks for the manifest's rows only (no file per variant).
bool metrics_only(const std::vector<OutputKind>& formats);

struct SweepOptions {
  std::string scene_path;
  std::vector<std::string> vary;  // POINTER=SPEC, as typed
  bool zip = false;
  std::string output;  // DIR
  std::vector<OutputKind> formats = {OutputKind::svg};
  int jobs = 1;
  std::optional<std::pair<int, int>> shard;  // K, N
  bool force = false;
  bool wait = false;      // another run holds the folder's lock: wait for it (else exit 2)
  bool progress = false;  // a bar on a terminal, else a line every 10 s (the CLI: not --quiet, not in CI)
  std::string version;    // pita's version: part of every content hash
};

struct SweepSummary {
  std::int64_t variants = 0;          // in this run (this shard's)
  std::int64_t ok = 0;                // written now
  std::int64_t skipped = 0;           // resumed: already done
  std::int64_t failed = 0;            // invalid or without motion
  bool write_failed = false;          // an output could not be written (exit 3)
  std::vector<std::string> failures;  // "variant 7 (/keyframes/1/m = -1): ..."
  std::vector<std::string> notes;     // what else was (not) written
};

// Runs the sweep. Throws SweepUsageError (exit 2), scene::SceneError (a bad
// base scene, exit 2), io::OutputError (the manifest could not be
// written, exit 3). An interruption writes the manifest of what finished
// and exits with 128 + the signal.
SweepSummary run_sweep(const SweepOptions& options);

struct MergeSummary {
  std::int64_t variants = 0;
  std::int64_t rows = 0;
  std::int64_t failed = 0;
  std::int64_t foreign = 0;                                    // rows of another sweep, ignored
  std::int64_t missing_count = 0;                              // variants in no part
  std::vector<std::pair<std::int64_t, std::int64_t>> missing;  // their first ranges [first, last]
  // When every part is of one split into N shards: N, and for each shard K
  // with variants missing, (K, how many) in order of K (at most 1000 listed).
  int shards = 0;
  std::vector<std::pair<int, std::int64_t>> missing_shards;
  std::vector<std::string> parts;  // the manifest parts joined
  std::vector<std::string> notes;
};

// Joins DIR/manifest.K-of-N.csv into DIR/manifest.csv and writes index.html
// and contact.*. Throws SweepUsageError when DIR holds no sweep, when a part
// holds a variant twice or two parts disagree on one, or when another run
// holds DIR's manifest.csv (with `wait`, waits for it).
MergeSummary merge_sweep(const std::string& dir, bool wait);

// "0-3, 7, 9-11": ranges [first, last] as text.
std::string index_ranges(const std::vector<std::pair<std::int64_t, std::int64_t>>& ranges);

}  // namespace pita::sweep
