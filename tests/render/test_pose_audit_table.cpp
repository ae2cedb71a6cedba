// The pose property table (src/render/pose_audit_table.cpp): a block per
// dimension, one filled cell per method and property, green where it holds,
// red where it fails, amber for a share of existence below 100%; the same
// report gives the same bytes, in each format.
#include <string>

#include <gtest/gtest.h>

#include "analysis/pose_audit.hpp"
#include "render/figure.hpp"
#include "render/pose_audit_table.hpp"

namespace pita::render {
namespace {

analysis::PoseAuditReport small_report(std::vector<int> dimensions) {
  analysis::PoseAuditOptions options;
  options.methods = {PoseMethod::p5, PoseMethod::p6};
  options.dimensions = std::move(dimensions);
  options.configs = 9;
  return analysis::run_pose_audit(options);
}

TEST(PosePropertyTable, OneCellPerDimensionMethodAndPropertyColouredByTheVerdict) {
  const analysis::PoseAuditReport report = small_report({});
  const PropertyTable table = pose_property_table(report);
  int green = 0, red = 0, amber = 0;
  for (const Item& item : table.drawing.items) {
    if (const auto* f = std::get_if<FilledPath>(&item.shape)) {
      if (f->fill.g > f->fill.r) {
        ++green;
      } else if (f->fill.g > 0.85) {
        ++amber;
      } else {
        ++red;
      }
    }
  }
  int holds = 0, shares = 0;
  for (const analysis::PoseAuditCell& c : report.cells) {
    holds += c.holds;
    shares += !c.holds && c.property == analysis::PoseProperty::exists;
  }
  EXPECT_EQ(green, holds);
  EXPECT_EQ(amber, shares);
  EXPECT_EQ(red, static_cast<int>(report.cells.size()) - holds - shares);
  EXPECT_GT(red, 0);  // P5 is not affine-invariant
  // Two blocks are taller than one.
  EXPECT_GT(table.height, pose_property_table(small_report({3})).height);
}

TEST(PosePropertyTable, RendersInEachFormatTheSameBytesForTheSameReport) {
  const analysis::PoseAuditReport report = small_report({2});
  const std::string svg = render_pose_property_table(report, Format::svg);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_EQ(svg, render_pose_property_table(report, Format::svg));
  EXPECT_EQ(render_pose_property_table(report, Format::png).substr(1, 3), "PNG");
  EXPECT_EQ(render_pose_property_table(report, Format::pdf).substr(0, 5), "%PDF-");
}

}  // namespace
}  // namespace pita::render
