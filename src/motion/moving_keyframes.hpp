// Animated patterns (PITA Sec. 7.4): keyframes that move, each by the steady
// morph SMA from its "from" arrow (tau = 0) to its "to" arrow (tau = 1). The
// pattern at tau is the panel's method through the keyframes at tau
// (docs/paper-notes.md N35).
#pragma once

#include "scene/scene.hpp"

namespace pita::motion {

// Whether any keyframe of the scene (or of one of its panels) moves.
bool has_moving_keyframes(const scene::Scene& scene);

// The scene with every moving keyframe at tau: keyframes[i].arrow becomes
// SMA(from_i, to_i, tau) (PITA Eq. 20, the steady morph, winding included), and the
// scene no longer moves (keyframes_to empty). Knots, methods, layers and
// everything else are kept. tau outside [0, 1] extrapolates the SMA.
scene::Scene scene_at(const scene::Scene& scene, double tau);

}  // namespace pita::motion
