// "ara": the ARA (core/steadiness.hpp) of the panel's motion over a regular
// grid of the shapes' bounding box in reference coordinates, printed.
#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "core/steadiness.hpp"
#include "motion/scene_motion.hpp"
#include "render/layer_cost.hpp"
#include "render/layers/pose_layers.hpp"

namespace pita::render {

// By default the figure prints the ARA that `pita measure` and claims compare.
static_assert(scene::AraLayer{}.grid == kDefaultAraGrid);

void draw_pose_layer(PosePanel<Affine2>& panel, const scene::AraLayer& layer) {
  const std::vector<scene::ShapeOutline>& shapes = panel.shapes();
  if (shapes.empty()) panel.fail("an ara layer samples the panel's shapes, and the panel has none");
  std::vector<Eigen::Vector2d> vertices;
  for (const Point p : panel.body_points()) vertices.emplace_back(p.real(), p.imag());
  const std::vector<Eigen::Vector2d> points = ara_grid(vertices, layer.grid);  // as pita measure's (N28)
  const double ara = average_relative_acceleration(panel.motion().poses<Affine2>(), points);
  if (!std::isfinite(ara)) panel.fail("the ARA of this motion is not finite (a pose on the way is singular)");
  panel.push(-1, Label{fmt::format("ARA = {:.{}f}", ara, layer.digits), layer.at, layer.size, layer.color});
}

// Its cost (render/layer_cost.hpp).
namespace detail {

void LayerCost::operator()(const scene::AraLayer& l) {
  // core/steadiness.hpp: at each of 64 times and each grid point, two poses
  // and two velocities, each about 1/16 of a unit (measured: ten panels of
  // 100 x 100 points, 25.6 million evaluations, take 4.2 s, ~0.16 us each).
  add(layer_ + "/grid", fmt::format("{} x {} points of an ARA", l.grid, l.grid),
      static_cast<double>(l.grid) * l.grid * 64 * 4 / 16 + kShapeUnits);
}

}  // namespace detail

}  // namespace pita::render
