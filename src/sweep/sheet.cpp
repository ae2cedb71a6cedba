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

#include "io/output_file.hpp"
#include "render/budget.hpp"
#include "render/cairo_handles.hpp"
#include "render/figure.hpp"
#include "render/painter.hpp"
#include "render/png_writer.hpp"
#include "scene/scene.hpp"

namespace pita::sweep {

namespace {

namespace fs = std::filesystem;

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

constexpr double kLabel = 16;  // caption height under a cell
constexpr double kTitle = 36;  // the sheet's title
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
double first_aspect(const SheetInput& input, const std::vector<const Row*>& by_cell) {
  for (const Row* row : by_cell) {
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

// `by_cell`: the row drawn in each cell; `sampled`: the cells are a sample of the variants.
ContactGrid contact_grid(const SheetInput& input, const std::vector<const Row*>& by_cell, bool sampled) {
  std::vector<std::size_t> varying;
  for (std::size_t k = 0; k < input.axis_sizes.size(); ++k) {
    if (input.axis_sizes[k] > 1) varying.push_back(k);
  }
  const std::size_t n = by_cell.size();
  ContactGrid grid;
  grid.two_d = !sampled && !input.zip && varying.size() == 2 && input.axis_sizes[varying[1]] <= kMaxContactColumns;
  grid.row_axis = grid.two_d ? varying[0] : 0;
  grid.column_axis = grid.two_d ? varying[1] : 0;
  grid.columns = grid.two_d ? input.axis_sizes[grid.column_axis] : static_cast<std::size_t>(std::ceil(std::sqrt(n)));
  grid.rows = grid.two_d ? input.axis_sizes[grid.row_axis] : (n + grid.columns - 1) / grid.columns;
  grid.cell_w = std::clamp(2400.0 / static_cast<double>(grid.columns), 120.0, 320.0);
  grid.cell_h = grid.cell_w * first_aspect(input, by_cell);
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
    io::write_files_atomically(files);
    return why;
  }

 private:
  std::string svg_bytes_, png_bytes_;
  Surface svg_, png_;
  Context contexts_[2];
};

// The title: the base scene and the pointers swept (and which are rows and
// columns, or how the variants shown were chosen).
void paint_title(SheetPainter& painter, const SheetInput& input, const ContactGrid& grid, std::size_t cells) {
  painter.each([&](cairo_t* cr) {
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    std::string title = fmt::format("pita sweep of {}: ", input.name);
    for (std::size_t k = 0; k < input.pointers.size(); ++k) title += (k ? ", " : "") + input.pointers[k];
    if (grid.two_d) {
      title +=
          fmt::format("  (rows: {}, columns: {})", input.pointers[grid.row_axis], input.pointers[grid.column_axis]);
    }
    if (static_cast<std::int64_t>(cells) < input.variants) {
      title += fmt::format("  ({} of {} variants, evenly spaced; index.html lists all)", cells, input.variants);
    }
    render::paint_text(cr, title, "Sans Bold", 14, kInk, 8, 8, render::TextAlign::left);
  });
}

// Cell i, of variant `index`: its figure scaled into it (or why there is
// none), its label, and on a two-axis grid the row's and column's values at the edges.
void paint_cell(SheetPainter& painter, const SheetInput& input, const ContactGrid& grid, std::size_t i,
                std::int64_t index, const Row* row) {
  const double x = grid.x(i), y = grid.y(i), cell_w = grid.cell_w, cell_h = grid.cell_h;
  std::string label = fmt::format("#{}", index);
  if (row != nullptr && !grid.two_d) {
    for (std::size_t k = 0; k < row->values.size(); ++k) label += (k == 0 ? ": " : ", ") + row->values[k];
  }
  if (grid.two_d && row != nullptr) {
    if (i % grid.columns == 0) {
      painter.each([&](cairo_t* cr) {
        render::paint_text(cr, row->values[grid.row_axis], "Sans", kFontSize, kInk, grid.left - 8, y + cell_h / 2 - 6,
                           render::TextAlign::right);
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
    cairo_rectangle(cr, x, y + cell_h, cell_w, kLabel + 8);  // a long label stops at its cell
    cairo_clip(cr);
    render::paint_text(cr, label, "Sans", kFontSize, failure.empty() ? kInk : kFailed, x, y + cell_h + 2,
                       render::TextAlign::left);
  });
}

}  // namespace

std::vector<std::int64_t> contact_sample(std::int64_t variants) {
  const std::int64_t cells = std::clamp<std::int64_t>(variants, 0, kMaxContactCells);
  std::vector<std::int64_t> sample(static_cast<std::size_t>(cells));
  for (std::int64_t i = 0; i < cells; ++i) {
    sample[static_cast<std::size_t>(i)] = variants > kMaxContactCells ? i * (variants - 1) / (kMaxContactCells - 1) : i;
  }
  return sample;
}

std::string write_contact_sheet(const SheetInput& input) {
  if (input.variants == 0) return "";
  // The variants drawn: all, or kMaxContactCells evenly spaced from the first to the last.
  const bool sampled = input.variants > kMaxContactCells;
  const std::vector<std::int64_t> cell_index = contact_sample(input.variants);
  const std::size_t cells = cell_index.size();
  std::map<std::int64_t, Row> rows;  // at most kMaxContactCells: the manifest read row by row
  {
    std::optional<ManifestReader> reader = ManifestReader::open(input.dir / "manifest.csv", input.pointers);
    Row r;
    while (reader && reader->next(r)) {
      if (std::binary_search(cell_index.begin(), cell_index.end(), r.index)) rows[r.index] = r;
    }
  }
  std::vector<const Row*> by_index(cells, nullptr);  // by cell
  for (std::size_t i = 0; i < cells; ++i) {
    if (const auto found = rows.find(cell_index[i]); found != rows.end()) by_index[i] = &found->second;
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
    return fmt::format(
        "contact.svg and contact.png not drawn: their {} figures would draw about {:.3g} points, more "
        "than the contact sheet's budget of {:.3g} (index.html shows every figure)",
        figures, units, kMaxContactUnits);
  }
  const ContactGrid grid = contact_grid(input, by_index, sampled);
  SheetPainter painter(grid);
  paint_title(painter, input, grid, cells);
  for (std::size_t i = 0; i < cells; ++i) paint_cell(painter, input, grid, i, cell_index[i], by_index[i]);
  return painter.finish(input);
}

}  // namespace pita::sweep
