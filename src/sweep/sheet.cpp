#include "sweep/sheet.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include <cairo-svg.h>
#include <cairo.h>
#include <fmt/format.h>

#include "render/budget.hpp"
#include "render/figure.hpp"
#include "render/cairo_handles.hpp"
#include "render/output_file.hpp"
#include "render/painter.hpp"
#include "render/png_writer.hpp"
#include "scene/scene.hpp"

namespace pita::sweep {

namespace {

namespace fs = std::filesystem;

// A file name as a relative URL: percent-encoded but for unreserved characters.
std::string url(std::string_view name) {
  std::string out;
  for (const char c : name) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || c == '-' || c == '_' || c == '.' || c == '~') {
      out += c;
    } else {
      out += fmt::format("%{:02X}", u);
    }
  }
  return out;
}

std::string html(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// The first output of the row with one of `extensions`, in that order of preference.
std::string output_with(const Row& row, std::initializer_list<std::string_view> extensions) {
  for (const std::string_view ext : extensions) {
    for (const std::string& f : row.outputs) {
      const std::size_t dot = f.rfind('.');
      if (dot != std::string::npos && std::string_view(f).substr(dot + 1) == ext && !f.ends_with(".scene.json")) {
        return f;
      }
    }
  }
  return "";
}

// The sort script: columns by name, numbers compared as numbers, empty last;
// "#sort=NAME&order=desc" in the address sorts on load.
constexpr std::string_view kScript = R"(<script>
const grid = document.getElementById("grid"), by = document.getElementById("sort"), order = document.getElementById("order");
function key(cell, column) { return cell.dataset[column] ?? ""; }
function sortCells() {
  const column = by.value, sign = order.value === "desc" ? -1 : 1;
  const cells = Array.from(grid.children);
  cells.sort((a, b) => {
    const x = key(a, column), y = key(b, column);
    if (x === "" || y === "") return (x === "") - (y === "") || Number(a.dataset.index) - Number(b.dataset.index);
    const nx = Number(x), ny = Number(y);
    const c = !isNaN(nx) && !isNaN(ny) ? nx - ny : x.localeCompare(y);
    return sign * c || Number(a.dataset.index) - Number(b.dataset.index);
  });
  for (const cell of cells) grid.appendChild(cell);
}
by.addEventListener("change", sortCells);
order.addEventListener("change", sortCells);
const wanted = new URLSearchParams(location.hash.slice(1));
if (wanted.has("sort")) {
  const option = Array.from(by.options).find(o => o.textContent === wanted.get("sort"));
  if (option) by.value = option.value;
  if (wanted.get("order") === "desc") order.value = "desc";
  sortCells();
}
</script>
)";

}  // namespace

std::string write_index_html(const SheetInput& input) {
  // Two passes over the manifest: the counts for the heading, then the cards.
  std::int64_t count = 0, failed = 0;
  {
    std::optional<ManifestReader> reader = ManifestReader::open(input.dir / "manifest.csv", input.pointers);
    Row r;
    while (reader && reader->next(r)) {
      ++count;
      failed += r.ok() ? 0 : 1;
    }
  }
  render::StreamingOutput file(input.dir / "index.html");
  std::string out = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>pita sweep: {0}</title>\n"
      "<style>body{{font-family:sans-serif;margin:1em}} #grid{{display:flex;flex-wrap:wrap;gap:8px}} "
      "figure{{margin:0;width:220px;border:1px solid #ccc;padding:4px}} figure img{{width:100%;height:auto;"
      "background:#fff}} figure.failed{{border-color:#c00;background:#fee}} figcaption{{font-size:12px;"
      "word-break:break-all}}</style></head>\n<body>\n<h1>pita sweep of {0}</h1>\n",
      html(input.name));
  out += fmt::format("<p>{} of {} variants ({} failed) of <code>{}</code>; the values at ", count,
                     input.variants, failed, html(input.base_path));
  for (std::size_t k = 0; k < input.pointers.size(); ++k) {
    out += fmt::format("{}<code>{}</code>", k == 0 ? "" : ", ", html(input.pointers[k]));
  }
  out += ". <a href=\"manifest.csv\">manifest.csv</a></p>\n";
  // The columns one may sort by: index, the varied values, the metrics.
  out += "<p><label>Sort by <select id=\"sort\"><option value=\"index\">index</option>";
  for (std::size_t k = 0; k < input.pointers.size(); ++k) {
    out += fmt::format("<option value=\"v{}\">{}</option>", k, html(input.pointers[k]));
  }
  for (std::size_t m = 0; m < kMetricColumns.size(); ++m) {
    out += fmt::format("<option value=\"m{}\">{}</option>", m, kMetricColumns[m]);
  }
  out += "</select></label> <select id=\"order\"><option value=\"asc\">ascending</option>"
         "<option value=\"desc\">descending</option></select></p>\n<div id=\"grid\">\n";
  std::string left_out;
  if (count > kMaxIndexCards) {
    left_out = fmt::format("index.html shows the first {} of {} variants (manifest.csv has them all)", kMaxIndexCards,
                           count);
    out += fmt::format("<p><b>{}</b></p>\n", html(left_out));
  }
  std::optional<ManifestReader> reader = ManifestReader::open(input.dir / "manifest.csv", input.pointers);
  Row row;
  for (std::int64_t cards = 0; reader && cards < kMaxIndexCards && reader->next(row); ++cards) {
    file.write(out);
    out.clear();
    out += fmt::format("<figure class=\"{}\" data-index=\"{}\"", row.ok() ? "ok" : "failed", row.index);
    for (std::size_t k = 0; k < row.values.size(); ++k) out += fmt::format(" data-v{}=\"{}\"", k, html(row.values[k]));
    std::string tip;
    for (std::size_t m = 0; m < kMetricColumns.size(); ++m) {
      if (row.metrics[m].empty()) continue;
      out += fmt::format(" data-m{}=\"{}\"", m, html(row.metrics[m]));
      tip += fmt::format("{}{} = {}", tip.empty() ? "" : "\n", kMetricColumns[m], row.metrics[m]);
    }
    out += fmt::format(" title=\"{}\">", html(tip));
    const std::string thumb = output_with(row, {"png", "svg"});
    const std::string full = output_with(row, {"svg", "png", "pdf"});
    if (!thumb.empty()) {
      out += fmt::format("<a href=\"{0}\"><img loading=\"lazy\" src=\"{1}\" alt=\"variant {2}\"></a>", url(full),
                         url(thumb), row.index);
    } else if (!full.empty()) {
      out += fmt::format("<a href=\"{}\">figure</a>", url(full));
    }
    out += fmt::format("<figcaption>#{}", row.index);
    for (std::size_t k = 0; k < row.values.size() && k < input.pointers.size(); ++k) {
      out += fmt::format("<br>{} = {}", html(input.pointers[k]), html(row.values[k]));
    }
    if (!row.ok()) out += fmt::format("<br><b>failed</b>: {}", html(row.status));
    if (row.ok() && !row.metrics[6].empty()) out += fmt::format("<br>E max = {}", html(row.metrics[6]));
    if (row.ok() && !row.metrics[14].empty()) out += fmt::format("<br>ARA = {}", html(row.metrics[14]));
    out += "</figcaption></figure>\n";
  }
  out += "</div>\n";
  out += kScript;
  out += "</body></html>\n";
  file.write(out);
  file.commit();
  return left_out;
}

namespace {

using Surface = render::SurfacePtr;
using Context = render::ContextPtr;
constexpr auto append = render::append_to_string;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

constexpr double kLabel = 16;   // caption height under a cell
constexpr double kTitle = 36;   // the sheet's title
constexpr double kFontSize = 11;
const scene::Color kInk{0.1, 0.1, 0.1, 1.0};
const scene::Color kFailed{0.8, 0.0, 0.0, 1.0};

}  // namespace

namespace {

// Where the cells of a contact sheet go. Two axes of a product: a row per
// value of the first, a column per value of the second; otherwise the
// variants in index order, row by row. (Axes of one value do not count: 1 x
// 12 is a one-parameter sweep.) A grid wider than kMaxContactColumns falls
// back to rows of the index order.
struct ContactGrid {
  bool two_d = false;
  std::size_t row_axis = 0, column_axis = 0;
  std::size_t columns = 1, rows = 1;
  double cell_w = 0, cell_h = 0, left = 0, top = 0, width = 0, height = 0;

  double x(std::size_t i) const { return left + static_cast<double>(i % columns) * (cell_w + 8); }
  double y(std::size_t i) const { return top + static_cast<double>(i / columns) * (cell_h + kLabel + 8); }
};

// The cell's shape: that of the first variant that has a figure.
double first_aspect(const SheetInput& input, const std::vector<const Row*>& by_index) {
  for (const Row* row : by_index) {
    if (row == nullptr || !row->ok()) continue;
    try {
      const scene::Scene first = scene::parse_scene(
          read_text(input.dir / variant_file(input.name, row->index, input.variants, "scene.json")), input.base_path);
      return std::clamp(static_cast<double>(first.canvas.height) / first.canvas.width, 0.25, 2.0);
    } catch (const std::exception&) {
      continue;
    }
  }
  return 0.75;
}

ContactGrid contact_grid(const SheetInput& input, const std::vector<const Row*>& by_index) {
  std::vector<std::size_t> varying;
  for (std::size_t k = 0; k < input.axis_sizes.size(); ++k) {
    if (input.axis_sizes[k] > 1) varying.push_back(k);
  }
  const auto n = static_cast<std::size_t>(input.variants);
  ContactGrid grid;
  grid.two_d = !input.zip && varying.size() == 2 && input.axis_sizes[varying[1]] <= kMaxContactColumns;
  grid.row_axis = grid.two_d ? varying[0] : 0;
  grid.column_axis = grid.two_d ? varying[1] : 0;
  grid.columns = grid.two_d ? input.axis_sizes[grid.column_axis] : static_cast<std::size_t>(std::ceil(std::sqrt(n)));
  grid.rows = grid.two_d ? input.axis_sizes[grid.row_axis] : (n + grid.columns - 1) / grid.columns;
  grid.cell_w = std::clamp(2400.0 / static_cast<double>(grid.columns), 120.0, 320.0);
  grid.cell_h = grid.cell_w * first_aspect(input, by_index);
  grid.left = grid.two_d ? 110.0 : 8.0;
  grid.top = kTitle + (grid.two_d ? kLabel + 4 : 0.0);
  grid.width = grid.left + static_cast<double>(grid.columns) * (grid.cell_w + 8) + 8;
  grid.height = grid.top + static_cast<double>(grid.rows) * (grid.cell_h + kLabel + 8) + 8;
  return grid;
}

// The sheet drawn twice at once, as SVG and as PNG.
class SheetPainter {
 public:
  explicit SheetPainter(const ContactGrid& grid)
      : svg_(cairo_svg_surface_create_for_stream(append, &svg_bytes_, grid.width, grid.height)),
        png_(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, static_cast<int>(std::ceil(grid.width)),
                                        static_cast<int>(std::ceil(grid.height)))) {
    cairo_svg_surface_set_document_unit(svg_.get(), CAIRO_SVG_UNIT_PX);
    contexts_[0] = Context(cairo_create(svg_.get()));
    contexts_[1] = Context(cairo_create(png_.get()));
  }

  // paint(cr) on both, each in a cairo_save/restore of its own.
  template <class Paint>
  void each(Paint&& paint) {
    for (Context& c : contexts_) {
      cairo_save(c.get());
      paint(c.get());
      cairo_restore(c.get());
    }
  }

  // contact.svg and contact.png written together; what could not be drawn.
  std::string finish(const SheetInput& input) {
    for (Context& c : contexts_) c.reset();
    std::vector<std::pair<fs::path, std::string>> files;
    std::string why;
    cairo_surface_finish(svg_.get());
    if (cairo_surface_status(svg_.get()) == CAIRO_STATUS_SUCCESS) {
      files.emplace_back(input.dir / "contact.svg", render::canonical_svg_ids(svg_bytes_));
    } else {
      why = fmt::format("contact.svg not drawn: cairo: {}", cairo_status_to_string(cairo_surface_status(svg_.get())));
    }
    cairo_surface_flush(png_.get());
    const cairo_status_t png_status = cairo_surface_status(png_.get()) != CAIRO_STATUS_SUCCESS
                                          ? cairo_surface_status(png_.get())
                                          : render::write_png(png_.get(), png_bytes_);
    if (png_status == CAIRO_STATUS_SUCCESS) {
      files.emplace_back(input.dir / "contact.png", png_bytes_);
    } else {
      why += fmt::format("{}contact.png not drawn: cairo: {}", why.empty() ? "" : "; ",
                         cairo_status_to_string(png_status));
    }
    render::write_files_atomically(files);
    return why;
  }

 private:
  std::string svg_bytes_, png_bytes_;
  Surface svg_, png_;
  Context contexts_[2];
};

// The title: the base scene and the pointers swept (and which are rows and columns).
void paint_title(SheetPainter& painter, const SheetInput& input, const ContactGrid& grid) {
  painter.each([&](cairo_t* cr) {
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    std::string title = fmt::format("pita sweep of {}: ", input.name);
    for (std::size_t k = 0; k < input.pointers.size(); ++k) title += (k ? ", " : "") + input.pointers[k];
    if (grid.two_d) {
      title += fmt::format("  (rows: {}, columns: {})", input.pointers[grid.row_axis], input.pointers[grid.column_axis]);
    }
    render::paint_text(cr, title, "Sans Bold", 14, kInk, 8, 8, render::TextAlign::left);
  });
}

// Cell i: the variant's figure scaled into it (or why there is none), its
// label, and on a two-axis grid the row's and column's values at the edges.
void paint_cell(SheetPainter& painter, const SheetInput& input, const ContactGrid& grid, std::size_t i,
                const Row* row) {
  const double x = grid.x(i), y = grid.y(i), cell_w = grid.cell_w, cell_h = grid.cell_h;
  std::string label = fmt::format("#{}", i);
  if (row != nullptr && !grid.two_d) {
    for (std::size_t k = 0; k < row->values.size(); ++k) label += (k == 0 ? ": " : ", ") + row->values[k];
  }
  if (grid.two_d && row != nullptr) {
    if (i % grid.columns == 0) {
      painter.each([&](cairo_t* cr) {
        render::paint_text(cr, row->values[grid.row_axis], "Sans", kFontSize, kInk, grid.left - 8,
                           y + cell_h / 2 - 6, render::TextAlign::right);
      });
    }
    if (i / grid.columns == 0) {
      painter.each([&](cairo_t* cr) {
        render::paint_text(cr, row->values[grid.column_axis], "Sans", kFontSize, kInk, x + cell_w / 2, kTitle,
                           render::TextAlign::center);
      });
    }
  }
  std::optional<render::Figure> figure;
  std::optional<scene::Scene> scene;
  std::string failure = row == nullptr ? "missing" : row->ok() ? "" : "failed";
  if (failure.empty()) {
    try {
      scene = scene::parse_scene(
          read_text(input.dir / variant_file(input.name, row->index, input.variants, "scene.json")), input.base_path);
      figure = render::build_figure(*scene);
    } catch (const std::exception&) {
      failure = "not drawn";
    }
  }
  painter.each([&](cairo_t* cr) {
    cairo_rectangle(cr, x - 0.5, y - 0.5, cell_w + 1, cell_h + 1);
    cairo_set_source_rgb(cr, 0.8, 0.8, 0.8);
    cairo_set_line_width(cr, 1);
    cairo_stroke(cr);
    if (figure) {
      const double s = std::min(cell_w / scene->canvas.width, cell_h / scene->canvas.height);
      cairo_rectangle(cr, x, y, cell_w, cell_h);
      cairo_clip(cr);
      cairo_translate(cr, x + (cell_w - s * scene->canvas.width) / 2, y + (cell_h - s * scene->canvas.height) / 2);
      cairo_scale(cr, s, s);
      render::paint_figure(cr, *scene, *figure);
    } else {
      render::paint_text(cr, failure, "Sans Bold", 14, kFailed, x + cell_w / 2, y + cell_h / 2 - 8,
                         render::TextAlign::center);
    }
  });
  painter.each([&](cairo_t* cr) {
    render::paint_text(cr, label, "Sans", kFontSize, failure.empty() ? kInk : kFailed, x, y + cell_h + 2,
                       render::TextAlign::left);
  });
}

}  // namespace

std::string write_contact_sheet(const SheetInput& input) {
  if (input.variants > kMaxContactCells) {
    return fmt::format("contact.svg and contact.png not drawn: {} variants is more than {} on one picture (see "
                       "index.html)",
                       input.variants, kMaxContactCells);
  }
  if (input.variants == 0) return "";
  std::map<std::int64_t, Row> rows;  // at most kMaxContactCells
  {
    std::optional<ManifestReader> reader = ManifestReader::open(input.dir / "manifest.csv", input.pointers);
    Row r;
    while (reader && reader->next(r)) rows[r.index] = r;
  }
  const auto n = static_cast<std::size_t>(input.variants);
  std::vector<const Row*> by_index(n, nullptr);
  for (const auto& [index, r] : rows) {
    if (r.index >= 0 && static_cast<std::size_t>(r.index) < n) by_index[static_cast<std::size_t>(r.index)] = &r;
  }
  // The whole sheet's drawing, estimated before any is drawn.
  double units = 0.0;
  std::size_t figures = 0;
  for (const Row* row : by_index) {
    if (row == nullptr || !row->ok()) continue;
    ++figures;
    try {
      const scene::Scene scene = scene::parse_scene(
          read_text(input.dir / variant_file(input.name, row->index, input.variants, "scene.json")), input.base_path);
      units += render::estimate_cost(scene).units;
    } catch (const std::exception&) {  // drawn as "not drawn"
    }
  }
  if (units > kMaxContactUnits) {
    return fmt::format("contact.svg and contact.png not drawn: their {} figures would draw about {:.3g} points, more "
                       "than the contact sheet's budget of {:.3g} (index.html shows every figure)",
                       figures, units, kMaxContactUnits);
  }
  const ContactGrid grid = contact_grid(input, by_index);
  SheetPainter painter(grid);
  paint_title(painter, input, grid);
  for (std::size_t i = 0; i < n; ++i) paint_cell(painter, input, grid, i, by_index[i]);
  return painter.finish(input);
}

}  // namespace pita::sweep
