// Shapes and images carried by an affinity (src/render/carried_shapes.cpp),
// and an image painted where it belongs (the painter, through cairo).
#include <filesystem>
#include <string>

#include <cairo.h>
#include <gtest/gtest.h>

#include "render/carried_shapes.hpp"
#include "render/figure.hpp"
#include "scene/scene.hpp"

namespace pita::render {
namespace {

const std::filesystem::path kPicture = std::filesystem::path(PITA_SOURCE_DIR) / "scenes" / "images" / "picture.png";

scene::ShapeOutline image_in(Point low, Point high) {
  scene::ShapeOutline shape;
  shape.points = {low, Point{high.real(), low.imag()}, high, Point{low.real(), high.imag()}};
  shape.image = scene::ImageRef{kPicture.string(), "picture.png", 160, 120, "/shapes/1/image"};
  return shape;
}

TEST(CarriedShapes, AnImageStandsUprightInItsBox) {
  const scene::ShapeOutline shape = image_in({2.0, 1.0}, {6.0, 4.0});
  // y up: the top-left pixel at (x0, y1), the bottom-right at (x1, y0)
  const Affine2 up = image_placement(shape, true);
  EXPECT_LT(std::abs(apply(up, Point{0, 0}) - Point{2.0, 4.0}), 1e-15);
  EXPECT_LT(std::abs(apply(up, Point{160, 120}) - Point{6.0, 1.0}), 1e-15);
  // y down: the top-left pixel at (x0, y0)
  const Affine2 down = image_placement(shape, false);
  EXPECT_LT(std::abs(apply(down, Point{0, 0}) - Point{2.0, 1.0}), 1e-15);
  EXPECT_LT(std::abs(apply(down, Point{160, 120}) - Point{6.0, 4.0}), 1e-15);
}

TEST(CarriedShapes, OutlinesAreMappedAndFadedImagesKeepTheirFile) {
  scene::ShapeOutline square;
  square.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  scene::ShapesLayer layer;
  layer.fill = scene::Color{0, 1, 0, 1};
  Affine2 map;
  map.L << 0.0, -2.0, 2.0, 0.0;  // rotate by 90 degrees, scale 2
  map.b << 1.0, 1.0;
  const std::vector<Shape> drawn = carried_shapes({square, image_in({0, 0}, {4, 3})}, map, layer, true, 0.5);
  ASSERT_EQ(drawn.size(), 2u);
  const auto& filled = std::get<FilledPath>(drawn[0]);
  EXPECT_LT(std::abs(filled.contours[0][1] - Point{1.0, 3.0}), 1e-15);  // (1, 0) -> 1 + 2i + (1, 1)
  EXPECT_DOUBLE_EQ(filled.opacity, layer.fill_opacity * 0.5);
  EXPECT_DOUBLE_EQ(filled.outline->opacity, 0.5);
  const auto& image = std::get<Image>(drawn[1]);
  EXPECT_EQ(image.name, "picture.png");
  EXPECT_DOUBLE_EQ(image.opacity, 0.5);
  const auto corners = image_corners(image);
  // pixel (0, 0) is the box's top-left (0, 3), mapped: 1 + 2i * 3i = (1 - 6, 1)
  EXPECT_LT(std::abs(corners[0] - Point{-5.0, 1.0}), 1e-12);
}

// The picture drawn through cairo: sky at the top of its box, grass at the bottom.
TEST(CarriedShapes, PaintedImageShowsTheRightWayUp) {
  scene::Scene scene = scene::parse_scene(
      R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [1, 0], "m": 1, "w": 0},
          {"t": 2, "p": [2, 0], "m": 1, "w": 0}], "shapes": [{"image": "images/picture.png", "box": [[0, 0], [4, 3]]}],
          "handle": {"p": [0, 0], "q": [1, 0]}, "canvas": {"width": 160, "height": 120, "margin": 0,
          "view": {"min": [0, 0], "max": [4, 3]}}, "layers": [{"type": "handle", "width": 0.1}]})",
      (std::filesystem::path(PITA_SOURCE_DIR) / "scenes" / "inline.json").string());
  const Figure figure = build_figure(scene);
  const std::string png = render_figure(scene, figure, Format::png);
  struct Reader {
    const std::string* bytes;
    std::size_t at = 0;
  } reader{&png};
  cairo_surface_t* surface = cairo_image_surface_create_from_png_stream(
      [](void* closure, unsigned char* data, unsigned int length) {
        auto* r = static_cast<Reader*>(closure);
        if (r->at + length > r->bytes->size()) return CAIRO_STATUS_READ_ERROR;
        std::copy_n(r->bytes->data() + r->at, length, data);
        r->at += length;
        return CAIRO_STATUS_SUCCESS;
      },
      &reader);
  ASSERT_EQ(cairo_surface_status(surface), CAIRO_STATUS_SUCCESS);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  const auto pixel = [&](int x, int y) {
    const unsigned char* p = data + y * stride + 4 * x;  // B, G, R, A
    return std::array<int, 3>{p[2], p[1], p[0]};
  };
  const auto sky = pixel(5, 5), grass = pixel(5, 115);
  EXPECT_GT(sky[2], 200) << "blue sky at the top";
  EXPECT_GT(grass[1], grass[0] + 40) << "green grass at the bottom";
  EXPECT_LT(grass[2], 120);
  cairo_surface_destroy(surface);
}

}  // namespace
}  // namespace pita::render
