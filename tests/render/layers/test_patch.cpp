// The "patch" layer's grid (src/render/layers/patch.cpp): a line per row and
// per column through the centres of the bodies, here for a patch of pure
// translations, where the centres are known in closed form.
#include <vector>

#include <gtest/gtest.h>

#include "render/figure.hpp"
#include "scene/scene.hpp"

namespace pita::render {
namespace {

TEST(PatchLayer, GridJoinsTheCentresAlongRowsAndColumns) {
  // Corners: A the identity, B moved by (4, 0), C by (0, -3), D by (4, -3);
  // every pose of the patch is then the translation by (4u, -3v), and the
  // unit square's centre (0.5, 0.5) lands at (0.5 + 4u, 0.5 - 3v).
  const scene::Scene scene = scene::parse_scene(R"({"method": "polySAM",
      "shapes": [{"polygon": [[0, 0], [1, 0], [1, 1], [0, 1]]}],
      "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[1, 0, 4], [0, 1, 0]]},
                {"t": 2, "matrix": [[1, 0, 0], [0, 1, -3]]}, {"t": 3, "matrix": [[1, 0, 4], [0, 1, -3]]}],
      "layers": [{"type": "patch", "columns": 5, "rows": 4, "grid": {"color": "#123456"}}]})",
                                                "patch.json");
  const Figure figure = build_figure(scene);
  std::vector<std::vector<Point>> lines;
  int bodies = 0;
  for (const Item& item : figure.drawings[0].items) {
    const auto* line = std::get_if<Polyline>(&item.shape);
    if (line != nullptr && line->line.color.b > 0.3 && line->line.color.r < 0.1) {
      lines.push_back(line->points);
    } else {
      ++bodies;
    }
  }
  EXPECT_EQ(bodies, 20);
  ASSERT_EQ(lines.size(), 9u);  // 4 rows of 5, then 5 columns of 4
  for (int j = 0; j < 4; ++j) {
    ASSERT_EQ(lines[static_cast<std::size_t>(j)].size(), 5u);
    for (int i = 0; i < 5; ++i) {
      const Point p = lines[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)];
      EXPECT_NEAR(p.real(), 0.5 + 4.0 * i / 4.0, 1e-9) << i << "," << j;
      EXPECT_NEAR(p.imag(), 0.5 - 3.0 * j / 3.0, 1e-9) << i << "," << j;
    }
  }
  for (int i = 0; i < 5; ++i) {
    const std::vector<Point>& column = lines[static_cast<std::size_t>(4 + i)];
    ASSERT_EQ(column.size(), 4u);
    EXPECT_NEAR(column.front().real(), 0.5 + i, 1e-9);
    EXPECT_NEAR(column.back().imag(), -2.5, 1e-9);
  }
}

}  // namespace
}  // namespace pita::render
