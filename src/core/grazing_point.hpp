// The grazing point of a moving edge (SAM paper Sec. 7.2, SAM Eq. 8, Fig. 10).
//
// An edge from `from` to `to` is given in reference coordinates; at time t
// the pose A(t) = [L | c] carries its point x(s) = from + s d, d = to - from,
// to A(t) x(s), and dA/dt = [L' | c'] moves that point with the velocity
// L' x(s) + c'. The point is grazing ("characteristic", Sec. 7.2) when its
// velocity is parallel to the edge's direction L d, i.e. when the normal
// n = J L d (J the rotation by pi/2) is orthogonal to it:
//     n . (L' from + c') + s n . (L' d) = 0,
//     s = -n . (L' from + c') / n . (L' d).
// The swept region's boundary lies on the initial and final edges, the
// paths of the two ends, and the curve of the grazing points with s in [0, 1]
// (the envelope; Sec. 7.2, Abdel-Malek et al.).
//
// Under a SAM A^t o B (Sec. 2.3 (6)), the velocity field is x -> C x + v,
// {C, v} = log A, the same at every time, and C commutes with L_A^t; so
// n . (C y + v) for y on the edge at time t is det(L_A^t) times the same
// expression at time 0: s does not depend on t. This is SAM Eq. 8,
//     s = -n . log(A)(q) / n . (log(L) t),   q = B(from), t = L_B d,
// (the printed SAM Eq. 8 lacks the minus sign and measures s in units of t;
// docs/paper-notes.md N49): the grazing point is a fixed point of the edge,
// and its path is a portion of the envelope (Fig. 10, bottom).
#pragma once

#include <optional>

#include <Eigen/Core>

#include "core/affine2.hpp"

namespace pita {

// A segment in reference coordinates.
struct Edge {
  Eigen::Vector2d from = Eigen::Vector2d::Zero();
  Eigen::Vector2d to = Eigen::Vector2d::UnitX();
};

// The parameter s of the grazing point of `edge` at the instant where the
// pose is `pose` and its time derivative `velocity` ({dL/dt, dc/dt}, as
// PoseMotion::velocity gives it). nullopt when the edge's direction does not
// turn at that instant (every point of its line grazes, or none), or when
// the grazing point is farther than limits::kFarGrazingPoint edge lengths
// from `from`. Precondition: pose.L d != 0.
std::optional<double> grazing_parameter(const Affine2& pose, const Affine2& velocity, const Edge& edge);

// SAM Eq. 8 for the SAM A^t o B: the constant s from generator = log A ({log L,
// v}, affine_power.hpp's log) and the first pose B, as above.
std::optional<double> sam_grazing_parameter(const Affine2& generator, const Affine2& first, const Edge& edge);

}  // namespace pita
