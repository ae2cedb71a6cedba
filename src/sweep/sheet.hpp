// The picture of a whole sweep (docs/reference/sweep.md "pita sweep"): DIR/contact.svg /
// contact.png, every variant's figure on one picture (rows and columns for a
// two-parameter sweep), or an evenly spaced sample of a large sweep's. The
// table of every variant is index.html (sweep/index_page.hpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "sweep/manifest.hpp"

namespace pita::sweep {

// A contact picture holds at most this many variants; a larger sweep's shows
// this many, evenly spaced from the first variant to the last (its title
// says so; index.html lists them all).
inline constexpr std::int64_t kMaxContactCells = 256;
// ... and at most this much drawing in all (render::estimate_cost units,
// eight figures at the render budget): 32 heavy variants drew 1.6 GB of SVG
// in memory. Checked before anything is drawn; above it the sheet is left
// out (said in the summary).
inline constexpr double kMaxContactUnits = 8 * 2e6;
// Columns of a two-parameter grid: a wider second axis is laid out in rows.
inline constexpr std::size_t kMaxContactColumns = 40;

struct SheetInput {
  std::filesystem::path dir;
  std::string name;                   // the scene's stem
  std::string base_path;              // variants read as this file (relative images)
  std::vector<std::string> pointers;  // the varied pointers
  std::vector<std::size_t> axis_sizes;
  bool zip = false;
  std::int64_t variants = 0;
  bool figures = false;  // the sweep wrote figures (svg, png or pdf)
};

// The variants a contact sheet of `variants` shows, in increasing order: all
// of them up to kMaxContactCells, else that many evenly spaced from the first
// variant (0) to the last (variants - 1).
std::vector<std::int64_t> contact_sample(std::int64_t variants);

// DIR/contact.svg and DIR/contact.png from DIR/manifest.csv, each variant's
// figure redrawn from its scene file DIR/<name>-<index>.scene.json; a failed
// or missing variant is an empty cell marked so. Returns "" or why nothing
// was drawn. Atomic.
std::string write_contact_sheet(const SheetInput& input);

}  // namespace pita::sweep
