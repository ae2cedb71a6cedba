// "shapes": the body a motion carries, at the layer's frames (or an animation
// frame's time and trail). In a pose scene the panel's shapes (plane) or the
// scene's solids (space) under the poses; in an arrow scene the scene's shapes
// under the similarity that takes the handle onto D(t) (Sec. 7.1).
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/LU>
#include <fmt/format.h>

#include "core/carrier.hpp"
#include "render/carried_shapes.hpp"
#include "render/layer_cost.hpp"
#include "render/layers/pose_layers.hpp"
#include "render/panel_builder.hpp"
#include "render/solid_faces.hpp"

namespace pita::render {

namespace {

// `fade` < 1 only for the trail of an animation's moving frame (fade 1: a
// figure's frame, or a fixed one of "times").
void draw_shapes_body(PosePanel<Affine2>& panel, const scene::ShapesLayer& layer, const Affine2& pose, double white,
                      double fade, bool moving, int index, std::vector<Face>&) {
  scene::ShapesLayer style = layer;
  if (white > 0.0) {
    style.line.color = lightened(style.line.color, white);
    if (style.fill) style.fill = lightened(*style.fill, white);
  }
  for (Shape& shape : carried_shapes(panel.shapes(), pose, style, panel.scene().canvas.y_up, fade)) {
    panel.push(index, std::move(shape), moving);
  }
}

// A solid's own colour fills its faces (and outlines it without a fill).
void draw_shapes_body(PosePanel<Affine3>& panel, const scene::ShapesLayer& layer, const Affine3& pose, double white,
                      double fade, bool, int index, std::vector<Face>& faces) {
  for (const scene::Solid& solid : panel.shapes()) {
    LineStyle line = layer.line;
    if (solid.color && !layer.fill) line.color = *solid.color;
    line.color = lightened(line.color, white);
    std::optional<Color> fill;
    if (layer.fill) fill = lightened(solid.color.value_or(*layer.fill), white);
    add_solid_faces(panel, solid, pose, fill, line, fade, index, faces);
  }
}

}  // namespace

template <class Pose>
void draw_pose_layer(PosePanel<Pose>& panel, const scene::ShapesLayer& layer) {
  // "times": fixed frames, drawn alike in the figure and in every animation
  // frame (a marker, Fig. 24's square at B); otherwise the layer's samples,
  // or the animation's moving frame and its trail.
  const FrameSelection* selection = layer.times.empty() ? panel.selection() : nullptr;
  const std::vector<double> ts =
      !layer.times.empty() ? layer.times
                           : selected_times(selection, selection != nullptr ? std::vector<double>{}
                                                                            : panel.times(layer.samples, layer.range));
  // "lightness": "area" (SAM Fig. 9, N48): white mixed in by the frame's
  // area (in space, its volume): |det L|.
  std::vector<double> measures;
  if (layer.lightness_by_area) {
    for (const double t : ts) measures.push_back(std::abs(panel.pose_at(t).L.determinant()));
  }
  const std::vector<double> whites = lightness_whites(measures);
  std::vector<Face> faces;  // space: painted back to front once every frame is in
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const double fade = selection != nullptr ? trail_fade(i, ts.size()) : 1.0;
    const double white = whites.empty() ? 0.0 : whites[i];
    draw_shapes_body(panel, layer, panel.pose_at(ts[i]), white, fade, selection != nullptr, static_cast<int>(i), faces);
  }
  if constexpr (in_space_v<Pose>) paint_faces(panel, std::move(faces), selection != nullptr);
}

template void draw_pose_layer(PosePanel<Affine2>&, const scene::ShapesLayer&);
template void draw_pose_layer(PosePanel<Affine3>&, const scene::ShapesLayer&);

// In an arrow scene.
namespace detail {

// "shapes" (Sec. 7.1): the scene's shapes at each frame, carried by the
// similarity that takes the handle onto D(t) (core/carrier.hpp).
void PanelBuilder::add(const scene::ShapesLayer& layer) {
  // "times": fixed frames, in the figure and in every animation frame alike.
  const bool fixed = !layer.times.empty();
  const std::vector<Arrow> pattern =
      fixed ? frames(motion_, layer.times) : frames(sequence_times(layer.samples, layer.range));
  const bool moving = selection() != nullptr && !fixed;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    for (Shape& shape :
         carried_shapes(scene::figure_of<scene::KeyframeKeys>(panel_).shapes, carrier(handle(), pattern[i]), layer,
                        scene_.canvas.y_up, moving ? fade(i, pattern.size()) : 1.0)) {
      push(static_cast<int>(i), std::move(shape));
      drawing_.items.back().moving = moving;
    }
  }
}

}  // namespace detail

// Its cost (render/layer_cost.hpp).
namespace detail {

// ------------------------------------------------------------- pose layers
void LayerCost::operator()(const scene::ShapesLayer& l) {
  if (!l.times.empty()) {  // exactly these frames
    add(layer_ + "/times", fmt::format("{} frames of shapes", l.times.size()),
        static_cast<double>(l.times.size()) * (shapes_units() + motion::frame_cost(panel_) - 1.0));
    return;
  }
  frames(l.samples, "shapes", shapes_units());
}

}  // namespace detail

}  // namespace pita::render
