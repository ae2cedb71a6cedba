#include "render/property_table.hpp"

#include <cmath>

#include <fmt/format.h>

#include "analysis/paper_table.hpp"
#include "scene/scene.hpp"

namespace pita::render {

namespace {

constexpr double kRowHeight = 26.0, kMethodWidth = 70.0, kColumnWidth = 86.0, kMargin = 20.0, kHeader = 64.0;

const Color kHolds{0.80, 0.93, 0.80, 1.0};
const Color kFails{0.97, 0.80, 0.78, 1.0};
const Color kInk{0.0, 0.0, 0.0, 1.0};
const Color kDiffers{0.85, 0.35, 0.0, 1.0};

std::vector<Point> rectangle(double x, double y, double w, double h) {
  return {{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}};
}

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
  PropertyTable t;
  Drawing& d = t.drawing;
  const auto push = [&](Shape s) { d.items.push_back(Item{"/audit", -1, std::move(s), false}); };
  const double x0 = kMargin, y0 = kMargin;
  const double table_w = kMethodWidth + kColumnWidth * static_cast<double>(report.properties.size());
  // Column headers: the property's name on two lines, its letter in Fig. 10.
  for (std::size_t j = 0; j < report.properties.size(); ++j) {
    const analysis::PropertyInfo& p = info(report.properties[j]);
    const double x = x0 + kMethodWidth + kColumnWidth * static_cast<double>(j) + 4.0;
    std::string name(p.id);
    const std::size_t dash = name.find('-');
    const std::string first = dash == std::string::npos ? name : name.substr(0, dash + 1);
    const std::string second = dash == std::string::npos ? "" : name.substr(dash + 1);
    push(Label{first, {x, y0 + 14.0}, 11.0, kInk});
    push(Label{second, {x, y0 + 30.0}, 11.0, kInk});
    push(Label{p.letter.empty() ? std::string("Sec. ") + std::string(p.section.substr(0, p.section.find(','))) : std::string(p.letter),
               {x, y0 + 48.0}, 11.0, kDiffers});
  }
  for (std::size_t i = 0; i < report.methods.size(); ++i) {
    const Method m = report.methods[i];
    const double y = y0 + kHeader + kRowHeight * static_cast<double>(i);
    push(Label{std::string(info(m).id), {x0 + 6.0, y + kRowHeight / 2}, 13.0, kInk});
    for (std::size_t j = 0; j < report.properties.size(); ++j) {
      const analysis::AuditCell& c = report.cell(m, report.properties[j]);
      const double x = x0 + kMethodWidth + kColumnWidth * static_cast<double>(j);
      push(FilledPath{{rectangle(x, y, kColumnWidth, kRowHeight)}, c.holds ? kHolds : kFails, 1.0, std::nullopt});
      const std::optional<bool> said = analysis::printed(m, report.properties[j]);
      push(Label{fmt::format("{} {}", c.holds ? "yes" : "no", value_text(c.value)), {x + 5.0, y + kRowHeight / 2}, 11.0, kInk});
      if (said && *said != c.holds) {
        push(Polyline{rectangle(x + 2.0, y + 2.0, kColumnWidth - 4.0, kRowHeight - 4.0), true,
                      LineStyle{kDiffers, 2.0, 1.0, {}}});
      }
    }
  }
  // The grid.
  const double rows_h = kRowHeight * static_cast<double>(report.methods.size());
  const LineStyle grid{Color{0.4, 0.4, 0.4, 1.0}, 0.8, 1.0, {}};
  for (std::size_t i = 0; i <= report.methods.size(); ++i) {
    const double y = y0 + kHeader + kRowHeight * static_cast<double>(i);
    push(Polyline{{{x0, y}, {x0 + table_w, y}}, false, grid});
  }
  for (std::size_t j = 0; j <= report.properties.size(); ++j) {
    const double x = x0 + kMethodWidth + kColumnWidth * static_cast<double>(j);
    push(Polyline{{{x, y0 + kHeader}, {x, y0 + kHeader + rows_h}}, false, grid});
  }
  // The paper's list of PITAs per property beside the measured one.
  double y = y0 + kHeader + rows_h + 28.0;
  push(Label{fmt::format("Measured by pita audit: seed {}, {} random configurations and {} crafted. "
                         "Ringed: the paper prints otherwise (P1-P8).",
                         report.options.seed, report.options.configs, analysis::crafted_configs().size()),
             {x0, y}, 12.0, kInk});
  y += 18.0;
  push(Label{"The number is the worst value measured: the largest deviation, or, for winding-aware and "
             "knot-controlled, the smallest reaction.",
             {x0, y}, 12.0, kInk});
  y += 24.0;
  for (const analysis::PrintedRow& row : analysis::printed_table()) {
    std::vector<Method> measured;
    bool present = false;
    for (analysis::Property p : report.properties) present = present || p == row.property;
    if (!present) continue;
    for (Method m : report.methods) {
      if (report.cell(m, row.property).holds) measured.push_back(m);
    }
    push(Label{fmt::format("{}: paper {}; measured {}", info(row.property).id, letters(row.printed), letters(measured)),
               {x0, y}, 11.0, kInk});
    y += 18.0;
  }
  t.width = std::max(table_w, 760.0) + 2 * kMargin;
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
