// "patch" (SAM Fig. 11): the body at sam_patch(A, B, C, D, u, v) on a grid of
// (u, v), the panel's first poses as the corners A (top left), B (top right),
// C (bottom left) and D (bottom right, or regular_patch_corner(A, B, C)); the
// corner D drawn in the layer's "corner" line.
#include <vector>

#include <fmt/format.h>

#include "core/affine_power.hpp"
#include "core/sam_splines.hpp"
#include "render/layer_cost.hpp"
#include "render/layers/pose_layers.hpp"
#include "render/solid_faces.hpp"

namespace pita::render {

namespace {

void draw_patch_body(PosePanel<Affine2>& panel, const scene::PatchLayer& layer, int index, const Affine2& pose,
                     bool corner, std::vector<Face>&) {
  for (const scene::ShapeOutline& shape : panel.shapes()) {
    LineStyle line = layer.line;
    if (shape.color) line.color = *shape.color;
    if (corner && layer.corner) line = *layer.corner;  // F_D highlighted
    std::vector<Point> points;
    points.reserve(shape.points.size());
    for (const Point p : shape.points) points.push_back(pita::apply(pose, p));
    if (layer.fill && shape.closed) {
      panel.push(index, FilledPath{{std::move(points)}, *layer.fill, layer.fill_opacity, line});
    } else {
      panel.push(index, Polyline{std::move(points), shape.closed, line});
    }
  }
}

void draw_patch_body(PosePanel<Affine3>& panel, const scene::PatchLayer& layer, int index, const Affine3& pose,
                     bool corner, std::vector<Face>& faces) {
  for (const scene::Solid& solid : panel.shapes()) {
    const LineStyle line = corner && layer.corner ? *layer.corner : layer.line;
    std::optional<Color> fill;
    if (layer.fill) fill = solid.color.value_or(*layer.fill);
    add_solid_faces(panel, solid, pose, fill, line, 1.0, index, faces);
  }
}

}  // namespace

template <class Pose>
void draw_pose_layer(PosePanel<Pose>& panel, const scene::PatchLayer& layer) {
  const auto& poses = panel.keys().poses;
  const std::size_t needed = layer.regular ? 3 : 4;
  if (poses.size() < needed) {
    panel.fail(
        fmt::format("a patch takes the panel's first {} poses as corners (top left, top right, "
                    "bottom left{}); the panel has {}",
                    needed, layer.regular ? "" : ", bottom right", poses.size()));
  }
  const Pose &A = poses[0].pose, &B = poses[1].pose, &C = poses[2].pose;
  std::vector<Face> faces;  // space: painted back to front at the end
  try {
    const Pose D = layer.regular ? regular_patch_corner(A, B, C) : poses[3].pose;
    std::vector<Pose> grid;  // row-major
    for (int j = 0; j < layer.rows; ++j) {
      const double v = static_cast<double>(j) / (layer.rows - 1);
      for (int i = 0; i < layer.columns; ++i) {
        const double u = static_cast<double>(i) / (layer.columns - 1);
        grid.push_back(sam_patch(A, B, C, D, u, v));
        if (!grid.back().L.allFinite() || !grid.back().b.allFinite()) panel.fail("the patch overflows");
      }
    }
    const std::vector<BodyPoint<Pose>> body = layer.grid ? panel.body_points() : std::vector<BodyPoint<Pose>>{};
    if (!body.empty()) {  // the rows and columns, through the image of the body's centre
      BodyPoint<Pose> centre = body.front();
      for (std::size_t k = 1; k < body.size(); ++k) centre += body[k];
      centre /= static_cast<double>(body.size());
      const auto at = [&](int i, int j) {
        return panel.image(pita::apply(grid[static_cast<std::size_t>(j * layer.columns + i)], centre));
      };
      for (int j = 0; j < layer.rows; ++j) {
        std::vector<Point> row;
        for (int i = 0; i < layer.columns; ++i) row.push_back(at(i, j));
        panel.push(-1, Polyline{std::move(row), false, *layer.grid});
      }
      for (int i = 0; i < layer.columns; ++i) {
        std::vector<Point> column;
        for (int j = 0; j < layer.rows; ++j) column.push_back(at(i, j));
        panel.push(-1, Polyline{std::move(column), false, *layer.grid});
      }
    }
    for (int j = 0, index = 0; j < layer.rows; ++j) {
      for (int i = 0; i < layer.columns; ++i, ++index) {
        const bool corner = i == layer.columns - 1 && j == layer.rows - 1;
        draw_patch_body(panel, layer, index, grid[static_cast<std::size_t>(index)], corner, faces);
      }
    }
  } catch (const NoRealLogarithm& error) {
    panel.fail(fmt::format("the patch needs a SAM that does not exist: {}", error.what()));
  }
  if constexpr (in_space_v<Pose>) paint_faces(panel, std::move(faces), false);
}

template void draw_pose_layer(PosePanel<Affine2>&, const scene::PatchLayer&);
template void draw_pose_layer(PosePanel<Affine3>&, const scene::PatchLayer&);

// Its cost (render/layer_cost.hpp).
namespace detail {

void LayerCost::operator()(const scene::PatchLayer& l) {
  add(layer_ + "/columns", fmt::format("{} x {} shapes of a patch", l.columns, l.rows),
      static_cast<double>(l.columns) * l.rows * shapes_units());
}

}  // namespace detail

}  // namespace pita::render
