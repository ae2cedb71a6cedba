// "poses": the panel's body at each of its poses, in the layer's colours, and
// (four-point-SAM) the poses the last subdivision step inserts (SAM Fig. 13's
// green blocks, docs/paper-notes.md N43).
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "core/affine_power.hpp"
#include "core/overloaded.hpp"
#include "core/sam_splines.hpp"
#include "render/layer_cost.hpp"
#include "render/layers/pose_layers.hpp"
#include "render/solid_faces.hpp"
#include "scene/color.hpp"

namespace pita::render {

namespace {

// The shapes at `pose`: closed ones filled with the colour, open ones stroked.
void draw_pose_body(PosePanel<Affine2>& panel, const scene::PosesLayer& layer, int index, const Affine2& pose,
                    Color color, std::vector<Face>&) {
  const LineStyle line{color, layer.width, 1.0, {}};
  for (const scene::ShapeOutline& shape : panel.shapes()) {
    std::vector<Point> points;
    points.reserve(shape.points.size());
    for (const Point p : shape.points) points.push_back(pita::apply(pose, p));
    if (shape.closed) {
      panel.push(index, FilledPath{{std::move(points)}, color, layer.fill_opacity, line});
    } else {
      panel.push(index, Polyline{std::move(points), false, line});
    }
  }
}

// The solids at `pose`, outlined in the colour and filled with a lighter one;
// with "fill_opacity": 0 outlined only (every edge), so that they hide none
// of the copies under them (SAM 3D Fig. 13).
void draw_pose_body(PosePanel<Affine3>& panel, const scene::PosesLayer& layer, int index, const Affine3& pose,
                    Color color, std::vector<Face>& faces) {
  const LineStyle line{color, layer.width, 1.0, {}};
  const std::optional<Color> fill =
      layer.fill_opacity > 0.0 ? std::optional<Color>(lightened(color, 0.55)) : std::nullopt;
  for (const scene::Solid& solid : panel.shapes()) add_solid_faces(panel, solid, pose, fill, line, 1.0, index, faces);
}

}  // namespace

template <class Pose>
void draw_pose_layer(PosePanel<Pose>& panel, const scene::PosesLayer& layer) {
  const auto& poses = panel.keys().poses;
  if (poses.empty()) panel.fail("this layer draws the poses, and the panel has no poses");
  std::vector<Face> faces;  // space: painted back to front at the end
  // The four-point subdivision keeps the old poses at the even places of the
  // subdivided sequence (subdivide_four_point): the last step inserts the odd ones.
  const auto& keys = panel.keys();
  if (layer.inserted && keys.method == PoseMethod::four_point && keys.subdivisions > 0) {
    (void)panel.motion();  // the panel's motion, or its error, first
    std::vector<Pose> controls;
    for (const auto& pose : poses) controls.push_back(pose.pose);
    try {
      for (int step = 0; step < keys.subdivisions; ++step) controls = subdivide_four_point(controls);
    } catch (const NoRealLogarithm& error) {
      panel.fail(fmt::format("the four-point subdivision needs a SAM that does not exist: {}", error.what()));
    }
    for (std::size_t k = 1; k < controls.size(); k += 2) {
      draw_pose_body(panel, layer, static_cast<int>(poses.size() + k / 2), controls[k], *layer.inserted, faces);
    }
  }
  for (std::size_t i = 0; i < poses.size(); ++i) {
    draw_pose_body(panel, layer, static_cast<int>(i), poses[i].pose, scene::series_color(layer.colors, i), faces);
  }
  if constexpr (in_space_v<Pose>) paint_faces(panel, std::move(faces), false);
}

template void draw_pose_layer(PosePanel<Affine2>&, const scene::PosesLayer&);
template void draw_pose_layer(PosePanel<Affine3>&, const scene::PosesLayer&);

// Its cost (render/layer_cost.hpp).
namespace detail {

void LayerCost::operator()(const scene::PosesLayer& l) {
  // With "inserted", a four-point panel of the plane's last step adds n 2^(steps-1) poses.
  const auto [poses, inserted] = std::visit(
      overloaded{
          [&](const scene::PlanePoseKeys& given) {
            const auto n = static_cast<double>(given.poses.size());
            return std::pair(n, l.inserted && given.subdivisions > 0 ? std::ldexp(n, given.subdivisions - 1) : 0.0);
          },
          [](const scene::SpacePoseKeys& given) { return std::pair(static_cast<double>(given.poses.size()), 0.0); },
          [](const scene::TrackMethod&) { return std::pair(0.0, 0.0); }},
      panel_.keys);
  add(layer_, "the shapes at the poses", (poses + inserted) * shapes_units());
}

}  // namespace detail

}  // namespace pita::render
