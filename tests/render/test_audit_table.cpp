// The property table (src/render/audit_table.cpp): one filled cell per
// method and property, coloured by the verdict, ringed where the paper
// prints otherwise; and the "property-table" layer that draws it in a panel.
#include <string>

#include <gtest/gtest.h>

#include "analysis/audit.hpp"
#include "analysis/paper_table.hpp"
#include "render/audit_table.hpp"
#include "render/figure.hpp"
#include "scene/scene.hpp"

namespace pita::render {
namespace {

analysis::AuditReport small_report() {
  analysis::AuditOptions options;
  options.methods = {Method::P2, Method::P4, Method::P6};
  options.configs = 10;
  return analysis::run_audit(options);
}

TEST(PropertyTable, OneCellPerMethodAndPropertyColouredByTheVerdict) {
  const analysis::AuditReport report = small_report();
  const PropertyTable table = property_table(report);
  int green = 0, red = 0, rings = 0;
  for (const Item& item : table.drawing.items) {
    if (const auto* f = std::get_if<FilledPath>(&item.shape)) {
      (f->fill.g > f->fill.r ? green : red) += 1;
    }
    if (const auto* p = std::get_if<Polyline>(&item.shape); p != nullptr && p->closed) ++rings;
  }
  int holds = 0;
  for (const analysis::AuditCell& c : report.cells) holds += c.holds;
  EXPECT_EQ(green, holds);
  EXPECT_EQ(red, static_cast<int>(report.cells.size()) - holds);
  // Rings: P2 handle-invariant (row H prints 2), P4 smooth, handle-invariant
  // and winding-aware (the print omits P4 from H and W).
  EXPECT_EQ(rings, static_cast<int>(analysis::disagreements(report).size()));
  EXPECT_GE(rings, 4);
  EXPECT_GT(table.width, 0.0);
  EXPECT_GT(table.height, 0.0);
}

TEST(PropertyTable, RendersInEachFormat) {
  const analysis::AuditReport report = small_report();
  EXPECT_NE(render_property_table(report, Format::svg).find("<svg"), std::string::npos);
  EXPECT_EQ(render_property_table(report, Format::png).substr(1, 3), "PNG");
  EXPECT_EQ(render_property_table(report, Format::pdf).substr(0, 5), "%PDF-");
}

TEST(PropertyTable, LayerDrawsTheTableAtItsCorner) {
  const scene::Scene scene = scene::parse_scene(R"({"method": "P6", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 0.5, "p": [1, 1], "m": 1, "w": 0}, {"t": 1, "p": [2, 0], "m": 1, "w": 0}],
      "canvas": {"y_axis": "down"},
      "layers": [{"type": "property-table", "methods": ["P1"], "configs": 3, "at": [100, 50]}]})",
                                                "t.json");
  const Figure figure = build_figure(scene);
  ASSERT_EQ(figure.drawings.size(), 1u);
  const std::optional<scene::Box> box = bounds(figure.drawings[0]);
  ASSERT_TRUE(box.has_value());
  EXPECT_GE(box->min.real(), 100.0);
  EXPECT_GE(box->min.imag(), 50.0);
  int cells = 0;
  for (const Item& item : figure.drawings[0].items) cells += std::holds_alternative<FilledPath>(item.shape);
  EXPECT_EQ(cells, static_cast<int>(analysis::all_properties().size()));
}

}  // namespace
}  // namespace pita::render
