// DIR/index.html of a sweep (docs/reference/sweep.md "index.html"): a table of every variant
// (its values, status, metrics and, when the sweep drew figures, a
// thumbnail), paged and sortable by any column, usable at a million rows.
// The page holds no data: it loads DIR/index/rows-K.js (the rows of the
// manifest from K * kIndexRowsPerFile on) for the page it shows, and
// DIR/index/column-C.js (one column of every row) for the column it sorts by,
// with <script> elements, so that it works opened from the disk (file://).
#pragma once

#include <cstdint>
#include <string>

#include "sweep/sheet.hpp"

namespace pita::sweep {

// Rows of the manifest per DIR/index/rows-K.js.
inline constexpr std::int64_t kIndexRowsPerFile = 1000;
// Rows the table shows at once (the page's own choice: 50, 100, 500).
inline constexpr int kIndexPageRows = 100;

// Writes DIR/index/ and DIR/index.html from DIR/manifest.csv, read row by row
// (a few passes; nothing held but a buffer per open file). Each file is
// atomic, index.html last; data files of a larger earlier run are removed.
// Returns "" or what was left out.
std::string write_index_html(const SheetInput& input);

}  // namespace pita::sweep
