// The instantaneous centers of a similarity motion (docs/paper-notes.md N40).
//
// A frame D(t) = (p, q) carries a point of local coordinate z (complex, in
// the frame of the arrow) to x(t) = p(t) + z v(t), v = q - p. Differentiating
// and eliminating z = (x - p)/v gives the velocity and acceleration fields of
// the plane at time t, both complex-affine in x:
//     x'  = p'  + (v' / v)(x - p),     zero at  c_v = p - p' v / v'
//                                                   = (p q' - q p') / (q' - p'),
//     x'' = p'' + (v''/ v)(x - p),     zero at  c_a = p - p'' v / v''
//                                                   = (p q'' - q p'') / (q'' - p'').
// c_v is the instantaneous center of rotation (the point whose velocity is
// zero at t); c_a the point whose acceleration is zero, about which every
// acceleration is x'' = (v''/v)(x - c_a). For P7 (PITA Eq. 35: x'' = K (x - f) for
// every point of the arrow) c_a is the global fixed point f at every t; for
// P8 (PITA Eq. 39) v''/v = e is constant, so x'' = e (x - c_a(t)) with a moving
// c_a: the "constant relation" of Fig. 9's caption in both cases.
#pragma once

#include <optional>

#include "core/arrow.hpp"

namespace pita {

// The zero of the affine field x -> dp + (dv / v)(x - p): p - dp v / dv.
// nullopt when the field is (nearly) a pure translation: dv = 0, or the zero
// lies farther than limits::kFarCenter |v| from p, or is not finite.
std::optional<Point> field_zero(Point p, Vector v, Vector dp, Vector dv);

// c_v and c_a above from p, q and their derivatives.
inline std::optional<Point> velocity_center(Point p, Point q, Vector dp, Vector dq) {
  return field_zero(p, q - p, dp, dq - dp);
}
inline std::optional<Point> acceleration_center(Point p, Point q, Vector ddp, Vector ddq) {
  return field_zero(p, q - p, ddp, ddq - ddp);
}

}  // namespace pita
