#include "render/audit_table.hpp"

#include <cmath>

#include <fmt/format.h>

#include "analysis/paper_table.hpp"
#include "render/decision_tree.hpp"
#include "scene/scene.hpp"

namespace pita::render {

namespace {

constexpr double kRowHeight = 24.0, kPropertyWidth = 170.0, kColumnWidth = 74.0, kPaperWidth = 130.0, kMargin = 20.0,
                 kHeader = 30.0;

const Color kHolds{0.80, 0.93, 0.80, 1.0};
const Color kFails{0.97, 0.80, 0.78, 1.0};
const Color kTableInk{0.0, 0.0, 0.0, 1.0};
const Color kDiffers{0.85, 0.35, 0.0, 1.0};

std::string letters(const std::vector<Method>& methods) {
  std::string out;
  for (Method m : methods) {
    if (!out.empty()) out += ' ';
    out += info(m).id;
  }
  return out.empty() ? "none" : out;
}

// One significant digit; rounding noise (below 1e-9) as "<1e-9", so that
// the figure does not change with the last bits of a compiler's arithmetic.
std::string value_text(double v) {
  if (v == 0.0) return "0";
  if (std::abs(v) < 1e-9) return "<1e-9";
  return fmt::format("{:.0e}", v);
}

}  // namespace

PropertyTable property_table(const analysis::AuditReport& report) {
  // Fig. 10's layout: a row per property with its letter (its left half),
  // then, per PITA, the letters of the properties it has (its right half,
  // "the inverse"). The measured verdicts fill the grid; the last column
  // says which PITAs the paper gives each property.
  PropertyTable t;
  Drawing& d = t.drawing;
  const auto push = [&](Shape s) { d.items.push_back(Item{"/audit", -1, std::move(s), false}); };
  const auto label = [&](std::string text, double x, double y, double size, const Color& ink) {
    push(Label{std::move(text), {x, y}, size, ink});
  };
  const double x0 = kMargin, y0 = kMargin;
  const std::size_t rows = report.properties.size(), columns = report.methods.size();
  const double grid_x = x0 + kPropertyWidth;
  const double paper_x = grid_x + kColumnWidth * static_cast<double>(columns);
  const double table_w = kPropertyWidth + kColumnWidth * static_cast<double>(columns) + kPaperWidth;
  const auto row_y = [&](std::size_t i) { return y0 + kHeader + kRowHeight * static_cast<double>(i); };
  // Column headers: the methods, and the paper's column.
  for (std::size_t j = 0; j < columns; ++j) {
    label(std::string(info(report.methods[j]).id), grid_x + kColumnWidth * static_cast<double>(j) + 6.0,
          y0 + kHeader / 2, 13.0, kTableInk);
  }
  label("the paper (P1-P8)", paper_x + 6.0, y0 + kHeader / 2, 12.0, kTableInk);
  for (std::size_t i = 0; i < rows; ++i) {
    const analysis::Property property = report.properties[i];
    const analysis::PropertyInfo& p = info(property);
    const double y = row_y(i);
    label(p.letter.empty() ? std::string("-") : std::string(p.letter), x0 + 4.0, y + kRowHeight / 2, 12.0, kDiffers);
    label(std::string(p.id), x0 + 22.0, y + kRowHeight / 2, 12.0, kTableInk);
    for (std::size_t j = 0; j < columns; ++j) {
      const Method m = report.methods[j];
      const analysis::AuditCell& c = report.cell(m, property);
      const double x = grid_x + kColumnWidth * static_cast<double>(j);
      push(FilledPath{
          {rectangle_corners(x, y, kColumnWidth, kRowHeight)}, c.holds ? kHolds : kFails, 1.0, std::nullopt});
      label(fmt::format("{} {}", c.holds ? "yes" : "no", value_text(c.value)), x + 4.0, y + kRowHeight / 2, 10.0,
            kTableInk);
      const std::optional<bool> said = analysis::printed(m, property);
      if (said && *said != c.holds) {
        push(Polyline{rectangle_corners(x + 2.0, y + 2.0, kColumnWidth - 4.0, kRowHeight - 4.0), true,
                      LineStyle{kDiffers, 2.0, 1.0, {}}});
      }
    }
    for (const analysis::PrintedRow& row : analysis::printed_table()) {
      if (row.property == property) label(letters(row.printed), paper_x + 6.0, y + kRowHeight / 2, 11.0, kTableInk);
    }
  }
  // The inverse (Fig. 10's right half): per method, the letters it has.
  const double inverse_y = row_y(rows);
  label("has (H W P K O A L)", x0 + 4.0, inverse_y + kRowHeight / 2, 12.0, kTableInk);
  for (std::size_t j = 0; j < columns; ++j) {
    const std::string has = property_letters(report, report.methods[j]);
    label(has.empty() ? std::string("-") : has, grid_x + kColumnWidth * static_cast<double>(j) + 6.0,
          inverse_y + kRowHeight / 2, 12.0, kTableInk);
  }
  // The grid.
  const LineStyle grid{Color{0.4, 0.4, 0.4, 1.0}, 0.8, 1.0, {}};
  for (std::size_t i = 0; i <= rows + 1; ++i) {
    push(Polyline{{{x0, row_y(i)}, {x0 + table_w, row_y(i)}}, false, grid});
  }
  for (std::size_t j = 0; j <= columns; ++j) {
    const double x = grid_x + kColumnWidth * static_cast<double>(j);
    push(Polyline{{{x, row_y(0)}, {x, row_y(rows + 1)}}, false, grid});
  }
  double y = row_y(rows + 1) + 26.0;
  label(fmt::format("Measured by pita audit: seed {}, {} random configurations and {} crafted. Green: holds; red: "
                    "fails; ringed: the paper prints otherwise.",
                    report.options.seed, report.options.configs, analysis::crafted_configs().size()),
        x0, y, 12.0, kTableInk);
  y += 18.0;
  label(
      "The number is the worst value measured: the largest deviation, or, for winding-aware and "
      "knot-controlled, the smallest reaction (pita's docs/reference/audit.md).",
      x0, y, 12.0, kTableInk);
  t.width = table_w + 2 * kMargin;
  t.height = y + kMargin;
  return t;
}

std::string render_property_table(const analysis::AuditReport& report, Format format) {
  const PropertyTable table = property_table(report);
  const int w = static_cast<int>(std::ceil(table.width)), h = static_cast<int>(std::ceil(table.height));
  // A scene holding only the canvas: the keyframes are never drawn (the
  // table is the figure's one drawing).
  const std::string text = fmt::format(
      R"({{"method": "P1", "keyframes": [{{"t": 0, "p": [0, 0], "m": 1, "w": 0}}, {{"t": 0.5, "p": [1, 0], "m": 1, "w": 0}},
          {{"t": 1, "p": [2, 0], "m": 1, "w": 0}}],
          "title": "Fig. 10, measured: the properties of Sec. 4 per method",
          "canvas": {{"width": {}, "height": {}, "margin": 0, "y_axis": "down",
                     "view": {{"min": [0, 0], "max": [{}, {}]}}}}}})",
      w, h + 40, w, h);
  const scene::Scene scene = scene::parse_scene(text, "pita audit");
  Figure figure;
  figure.drawings.push_back(table.drawing);
  figure.placements = checked_layout(scene, figure.drawings);
  return render_figure(scene, figure, format);
}

}  // namespace pita::render
