// One variant of a sweep, run: its scene read and checked as a scene of its
// own, its figures and frames rendered, the metrics of its figure's first
// panel measured, and all its files written at once; or its failure recorded, its
// stale outputs removed and its scene kept to reproduce the error by hand.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "sweep/grid.hpp"
#include "sweep/manifest.hpp"
#include "sweep/sweep.hpp"
#include "sweep/variant.hpp"

namespace pita::sweep {

// "svg", "png", "pdf", "csv", "json": the names of --format and of the files.
std::string_view output_kind_name(OutputKind kind);
std::optional<OutputKind> output_kind_named(std::string_view name);

// What every variant of a run shares.
struct VariantJob {
  const SweepOptions& options;
  const Grid& grid;
  const BaseScene& base;
  const std::filesystem::path dir;
  const std::string name;  // the sweep's name (the base scene's stem)
  const std::string salt;  // of the content hash
};

// What a variant's row does not say.
struct VariantOutcome {
  bool write_failed = false;     // a file could not be written (the row says which)
  bool metrics_skipped = false;  // measuring its motion costs more than `pita measure` allows: no metrics
  // A digest of what its outputs show, titles aside (its figure's shapes,
  // render/figure_digest.hpp; its frames; its metrics); 0 for a failed row.
  std::uint64_t digest = 0;
};

// Variant `index` of the job: its manifest row. Its frames (csv, json) obey
// `pita eval`'s work limit (a failed row above it); its metrics `pita
// measure`'s cost limit (left empty above it, `outcome` says so).
Row run_variant(const VariantJob& job, std::int64_t index, VariantOutcome& outcome);

}  // namespace pita::sweep
