// The points of the body a pose panel moves, by one rule for the plane and
// for space (docs/paper-notes.md N28, N37): what render's pose layers draw
// (paths, velocities, the "ara" layer's grid) and what `pita measure`'s ARA
// and velocity jump average over.
#pragma once

#include <vector>

#include "core/pose_traits.hpp"
#include "scene/scene.hpp"

namespace pita::scene {

// Every vertex of the body, in order: of the shapes the panel draws (its
// outlines in the plane, the scene's solids in space); the reference simplex (the triangle, the
// tetrahedron) when there are none, as in a scene built without shapes (the
// readers always give some: "shapes" defaults to the reference simplex).
template <class Pose>
std::vector<typename PoseTraits<Pose>::BodyPoint> body_points(const Scene& scene, const Panel& panel);

}  // namespace pita::scene
