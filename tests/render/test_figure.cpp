// Whole figures: layout, output formats, determinism.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "render/figure.hpp"
#include "render/layout.hpp"
#include "render/panel_drawing.hpp"
#include "render_support.hpp"

namespace pita::render::test {
namespace {

std::uint32_t big_endian(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t k = 0; k < 4; ++k) v = (v << 8) | static_cast<unsigned char>(bytes[at + k]);
  return v;
}

scene::Scene eight_panels() {
  std::vector<scene::Panel> panels;
  for (Method m : {Method::P1, Method::P2, Method::P3, Method::P4, Method::P5, Method::P6,
                   Method::P7, Method::P8}) {
    panels.push_back(panel(m, three_keyframes()));
  }
  scene::Scene s = scene_with({scene::PatternLayer{}, scene::KeyframesLayer{}}, panels);
  s.title = "Eight PITAs";
  s.canvas.width = 1200;
  s.canvas.height = 900;
  s.canvas.columns = 4;
  return s;
}

TEST(Layout, GridOfPanelsBelowTheTitle) {
  const scene::Scene s = eight_panels();
  const Figure f = build_figure(s);
  ASSERT_EQ(f.placements.size(), 8u);
  for (std::size_t i = 0; i < 8; ++i) {
    const Rect& cell = f.placements[i].cell;
    EXPECT_DOUBLE_EQ(cell.width, 300.0);
    const double column = static_cast<double>(i % 4), row = static_cast<double>(i / 4);
    EXPECT_DOUBLE_EQ(cell.x, 300.0 * column);
    EXPECT_DOUBLE_EQ(cell.y, kTitleBand + (900.0 - kTitleBand) / 2 * row);
  }
}

TEST(Layout, ViewFitsTheDrawingInsideThePlot) {
  const scene::Scene s = eight_panels();
  const Figure f = build_figure(s);
  for (std::size_t i = 0; i < 8; ++i) {
    const PanelPlacement& p = f.placements[i];
    const auto box = bounds(f.drawings[i]);
    ASSERT_TRUE(box);
    for (Point corner : {box->min, box->max, Point{box->min.real(), box->max.imag()}}) {
      const Point c = p.transform(corner);
      EXPECT_GE(c.real(), p.plot.x - 1e-9);
      EXPECT_LE(c.real(), p.plot.x + p.plot.width + 1e-9);
      EXPECT_GE(c.imag(), p.plot.y - 1e-9);
      EXPECT_LE(c.imag(), p.plot.y + p.plot.height + 1e-9);
    }
    // y up: a point above maps higher on the canvas (smaller y).
    EXPECT_LT(p.transform({0.0, 1.0}).imag(), p.transform({0.0, 0.0}).imag());
  }
}

TEST(Output, PngHasTheRequestedSize) {
  const scene::Scene s = eight_panels();
  const Figure f = build_figure(s);
  const std::string png = render_figure(s, f, Format::png, 1.5);
  ASSERT_GT(png.size(), 24u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  EXPECT_EQ(big_endian(png, 16), 1800u);
  EXPECT_EQ(big_endian(png, 20), 1350u);
}

TEST(Output, SvgAndPdfAreWellFormedAndDeterministic) {
  const scene::Scene s = eight_panels();
  const Figure f = build_figure(s);
  for (Format format : {Format::svg, Format::pdf, Format::png}) {
    const std::string first = render_figure(s, f, format);
    const std::string second = render_figure(s, build_figure(s), format);
    EXPECT_TRUE(first == second) << extension(format) << " differs between two renderings";
  }
  const std::string svg = render_figure(s, f, Format::svg);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("width=\"1200px\""), std::string::npos) << svg.substr(0, 300);
  const std::string pdf = render_figure(s, f, Format::pdf);
  EXPECT_EQ(pdf.substr(0, 5), "%PDF-");
  EXPECT_NE(pdf.find("/CreationDate (20000101000000Z)"), std::string::npos);  // fixed date
}

TEST(Output, OversizedPngIsRefused) {
  scene::Scene s = eight_panels();
  s.canvas.width = 8000;
  const Figure f = build_figure(s);
  EXPECT_THROW(render_figure(s, f, Format::png, 4.0), RenderError);
}

}  // namespace
}  // namespace pita::render::test
