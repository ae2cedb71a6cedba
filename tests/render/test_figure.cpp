// Whole figures (src/render/figure.cpp): output formats, sizes, determinism.
// Where the panels go is test_layout.cpp.
#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "render/figure.hpp"
#include "render/panel_drawing.hpp"  // RenderError
#include "render_support.hpp"

namespace pita::render::test {
namespace {

std::uint32_t big_endian(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t k = 0; k < 4; ++k) v = (v << 8) | static_cast<unsigned char>(bytes[at + k]);
  return v;
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
