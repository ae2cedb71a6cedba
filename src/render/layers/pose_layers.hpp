// The drawers of the layers of pose scenes, one overload per layer kind
// (scene/layers.hpp), each defined in render/layers/<kind>.cpp. A kind that
// draws in both dimensions is a template over the pose (Affine2: the plane,
// Affine3: space); a kind of the plane only takes PosePanel<Affine2>, and a
// 3D scene never holds it (the reader's table, scene/layer_kinds.hpp, refuses
// it; render/pose_drawing.cpp says so again if one gets through).
#pragma once

#include "core/affine2.hpp"
#include "core/affine3.hpp"
#include "render/pose_panel.hpp"
#include "scene/layers.hpp"

namespace pita::render {

// Both dimensions.
template <class Pose>
void draw_pose_layer(PosePanel<Pose>& panel, const scene::ShapesLayer& layer);  // shapes.cpp
template <class Pose>
void draw_pose_layer(PosePanel<Pose>& panel, const scene::PosesLayer& layer);  // poses.cpp
template <class Pose>
void draw_pose_layer(PosePanel<Pose>& panel, const scene::PathsLayer& layer);  // paths.cpp
template <class Pose>
void draw_pose_layer(PosePanel<Pose>& panel, const scene::VelocitiesLayer& layer);  // velocities.cpp
template <class Pose>
void draw_pose_layer(PosePanel<Pose>& panel, const scene::PatchLayer& layer);  // patch.cpp

// The plane only.
void draw_pose_layer(PosePanel<Affine2>& panel, const scene::VersusLayer& layer);          // versus.cpp
void draw_pose_layer(PosePanel<Affine2>& panel, const scene::FieldLayer& layer);           // field.cpp
void draw_pose_layer(PosePanel<Affine2>& panel, const scene::PlotLayer& layer);            // plot.cpp
void draw_pose_layer(PosePanel<Affine2>& panel, const scene::AraLayer& layer);             // ara.cpp
void draw_pose_layer(PosePanel<Affine2>& panel, const scene::MeasuresLayer& layer);        // measures.cpp
void draw_pose_layer(PosePanel<Affine2>& panel, const scene::SweptLayer& layer);           // swept.cpp
void draw_pose_layer(PosePanel<Affine2>& panel, const scene::LabelLayer& layer);           // label.cpp
void draw_pose_layer(PosePanel<Affine2>& panel, const scene::ExistenceLayer& layer);       // existence.cpp
void draw_pose_layer(PosePanel<Affine2>& panel, const scene::Sam3dExistenceLayer& layer);  // sam3d_existence.cpp

// Whether panels of `Pose` draw `Layer` (an overload above takes them).
template <class Pose, class Layer>
concept DrawnIn = requires(PosePanel<Pose>& panel, const Layer& layer) {
  draw_pose_layer(panel, layer);
};

}  // namespace pita::render
