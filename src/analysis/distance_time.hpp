// The distance-time function of a paced motion (the chapter's Sec. 3.2.2,
// Fig. 3.9-3.18): how much of its path a point of the frame has covered by
// scene time t, both as fractions (of the path's length and of the knot
// range [t_0, t_n]). A linear timing without arc length gives the motion's
// own distance-time curve; an ease with arc length gives the ease itself.
#pragma once

#include <span>
#include <vector>

#include "core/arrow.hpp"
#include "motion/scene_motion.hpp"

namespace pita::analysis {

// (x, y) per time: x = (t - t_0)/(t_n - t_0), y = s(tau(t)) / s(t_n), s the
// arc length of the point's path over the motion's own time. Throws
// std::invalid_argument when the path has zero length.
std::vector<Point> distance_time(const motion::SceneMotion& motion, scene::TrackedPoint point,
                                 std::span<const double> times);

}  // namespace pita::analysis
