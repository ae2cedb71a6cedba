#include "render/pose_audit_table.hpp"

#include <cmath>

#include <fmt/format.h>

#include "analysis/pose_audit_report.hpp"
#include "render/decision_tree.hpp"
#include "scene/scene.hpp"

namespace pita::render {

namespace pose_table {

constexpr double kRowHeight = 24.0, kPropertyWidth = 180.0, kColumnWidth = 100.0, kPaperWidth = 160.0, kMargin = 20.0,
                 kHeader = 30.0, kBlockGap = 16.0;

const Color kHolds{0.80, 0.93, 0.80, 1.0};
const Color kFails{0.97, 0.80, 0.78, 1.0};
const Color kShare{0.98, 0.90, 0.70, 1.0};  // exists, below 100%
const Color kInk{0.0, 0.0, 0.0, 1.0};
const Color kTitleInk{0.15, 0.15, 0.45, 1.0};

// One significant digit; rounding noise (below 1e-9) as "<1e-9", so that the
// figure does not change with the last bits of a compiler's arithmetic.
std::string value_text(const analysis::PoseAuditCell& c) {
  if (c.property == analysis::PoseProperty::exists) return fmt::format("{:.0f}%", 100.0 * c.value);
  const std::string verdict = c.holds ? "yes" : "no";
  if (c.measured == 0) return verdict + " (none)";
  if (c.value == 0.0) return verdict + " 0";
  if (std::abs(c.value) < 1e-9) return verdict + " <1e-9";
  return fmt::format("{} {:.0e}", verdict, c.value);
}

Color fill_of(const analysis::PoseAuditCell& c) {
  if (c.property == analysis::PoseProperty::exists) return c.holds ? kHolds : kShare;
  return c.holds ? kHolds : kFails;
}

}  // namespace pose_table

PropertyTable pose_property_table(const analysis::PoseAuditReport& report) {
  using namespace pose_table;
  PropertyTable t;
  Drawing& d = t.drawing;
  const auto push = [&](Shape s) { d.items.push_back(Item{"/audit", -1, std::move(s), false}); };
  const auto label = [&](std::string text, double x, double y, double size, const Color& ink) {
    push(Label{std::move(text), {x, y}, size, ink});
  };
  const std::size_t rows = report.properties.size(), columns = report.methods.size();
  const double x0 = kMargin, grid_x = x0 + kPropertyWidth;
  const double paper_x = grid_x + kColumnWidth * static_cast<double>(columns);
  const double table_w = kPropertyWidth + kColumnWidth * static_cast<double>(columns) + kPaperWidth;
  const LineStyle grid{Color{0.4, 0.4, 0.4, 1.0}, 0.8, 1.0, {}};
  double y0 = kMargin;
  for (int dimension : report.dimensions) {
    const auto row_y = [&](std::size_t i) { return y0 + kHeader + kRowHeight * static_cast<double>(i); };
    label(fmt::format("{}D: {}", dimension, dimension == 2 ? "poses of the plane" : "poses of space"), x0 + 4.0,
          y0 + kHeader / 2, 13.0, kTitleInk);
    for (std::size_t j = 0; j < columns; ++j) {
      label(std::string(info(report.methods[j]).id), grid_x + kColumnWidth * static_cast<double>(j) + 6.0,
            y0 + kHeader / 2, 12.0, kInk);
    }
    label("PITA paper", paper_x + 6.0, y0 + kHeader / 2, 12.0, kInk);
    for (std::size_t i = 0; i < rows; ++i) {
      const analysis::PoseProperty property = report.properties[i];
      const double y = row_y(i);
      label(std::string(info(property).id), x0 + 6.0, y + kRowHeight / 2, 12.0, kInk);
      for (std::size_t j = 0; j < columns; ++j) {
        const analysis::PoseAuditCell& c = report.cell(dimension, report.methods[j], property);
        const double x = grid_x + kColumnWidth * static_cast<double>(j);
        push(FilledPath{{rectangle_corners(x, y, kColumnWidth, kRowHeight)}, fill_of(c), 1.0, std::nullopt});
        label(value_text(c), x + 4.0, y + kRowHeight / 2, 10.0, kInk);
      }
      label(std::string(info(property).fig10), paper_x + 6.0, y + kRowHeight / 2, 11.0, kInk);
    }
    for (std::size_t i = 0; i <= rows; ++i) push(Polyline{{{x0, row_y(i)}, {x0 + table_w, row_y(i)}}, false, grid});
    for (std::size_t j = 0; j <= columns; ++j) {
      const double x = grid_x + kColumnWidth * static_cast<double>(j);
      push(Polyline{{{x, row_y(0)}, {x, row_y(rows)}}, false, grid});
    }
    y0 = row_y(rows) + kBlockGap;
  }
  double y = y0 + 10.0;
  label(fmt::format("Measured by pita audit poses: seed {}, {} random triples per dimension and {} crafted.",
                    report.options.seed, report.options.configs, analysis::crafted_pose_configs<Affine2>().size()),
        x0, y, 12.0, kInk);
  y += 18.0;
  label("Green: holds; red: fails; amber: the motion exists on only this share of the random triples.", x0, y, 12.0,
        kInk);
  y += 18.0;
  label(
      "The number is the worst value measured (the smallest reaction for knot-controlled), the median ARA for "
      "steady (docs/reference/audit.md).",
      x0, y, 12.0, kInk);
  t.width = table_w + 2 * kMargin;
  t.height = y + kMargin;
  return t;
}

std::string render_pose_property_table(const analysis::PoseAuditReport& report, Format format) {
  const PropertyTable table = pose_property_table(report);
  const int w = static_cast<int>(std::ceil(table.width)), h = static_cast<int>(std::ceil(table.height));
  // A scene holding only the canvas: the keyframes are never drawn (the
  // table is the figure's one drawing).
  const std::string text = fmt::format(
      R"({{"method": "P1", "keyframes": [{{"t": 0, "p": [0, 0], "m": 1, "w": 0}}, {{"t": 0.5, "p": [1, 0], "m": 1, "w": 0}},
          {{"t": 1, "p": [2, 0], "m": 1, "w": 0}}],
          "title": "Fig. 10 for affine poses, measured: what carries over to the pose methods",
          "canvas": {{"width": {}, "height": {}, "margin": 0, "y_axis": "down",
                     "view": {{"min": [0, 0], "max": [{}, {}]}}}}}})",
      w, h + 40, w, h);
  const scene::Scene scene = scene::parse_scene(text, "pita audit poses");
  Figure figure;
  figure.drawings.push_back(table.drawing);
  figure.placements = checked_layout(scene, figure.drawings);
  return render_figure(scene, figure, format);
}

}  // namespace pita::render
