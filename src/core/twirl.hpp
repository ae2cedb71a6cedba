// Twirls (Sec. 2.2, PITA Eq. 5-8) and the twirl between two arrows (PITA Eq. 17-19).
//
// A twirl is a similarity that also acts on windings: T(f, m, w) dilates by
// m > 0 and turns by the real angle w about the fixed point f, and adds w to
// the winding of any arrow it moves (PITA Eq. 7). Its powers are T^t = T(f, m^t, tw)
// (PITA Eq. 8).
//
// Representation. Writing L = ln m + i w (the winding-aware log of the linear
// part), we store a twirl by an anchor point a, the displacement u = T.a - a of
// that anchor, and L:
//     T^t . x = a + e^{tL} (x - a) + phi_t(L) u,   phi_t(L) = expm1(tL)/expm1(L)
// (docs/paper-notes.md N1). This never forms the fixed point
// f = a - u / (e^L - 1), so it stays exact as the twirl tends to a pure
// translation (L -> 0), where phi_t -> t.
#pragma once

#include <optional>

#include "core/arrow.hpp"
#include "core/complex_math.hpp"
#include "core/limits.hpp"

namespace pita {

class Twirl {
 public:
  // The identity.
  Twirl() = default;
  // The twirl that moves `anchor` by `displacement` and whose linear part has
  // log `log` = ln m + i w.
  Twirl(Point anchor, Vector displacement, Complex log);

  Point anchor() const { return anchor_; }                // a
  Vector displacement() const { return displacement_; }   // u = T.a - a
  Complex log() const { return log_; }                    // L = ln m + i w
  double ratio() const { return std::exp(log_.real()); }  // m (PITA Eq. 17)
  double winding() const { return log_.imag(); }          // w (PITA Eq. 18)
  // True when |e^L - 1| < kTwirlTranslation: no finite fixed point.
  bool is_translation() const { return translation_; }

  // phi_t(L) u, the displacement of the anchor under T^t, given e^{tL} - 1.
  Vector anchor_motion(double t, Complex expm1_tL) const {
    return translation_ ? t * displacement_ : expm1_tL * offset_;
  }
  // a - f = u / (e^L - 1), cached (no division on the hot path).
  Vector anchor_offset() const { return offset_; }

 private:
  Point anchor_{};
  Vector displacement_{};
  Complex log_{};
  Vector offset_{};
  bool translation_ = true;
};

// T(f, m, w): the twirl about fixed point f by ratio m > 0 and winding w (PITA Eq. 5-7).
inline Twirl twirl(Point f, double m, double w) { return {f, Vector{}, Complex{std::log(m), w}}; }

// The identity twirl.
inline Twirl identity_twirl() { return {}; }

// A pure translation by v.
inline Twirl translation(Vector v) { return {Point{}, v, Complex{}}; }

// T^t (PITA Eq. 8), as a twirl with the same anchor. The anchor moves by
// phi_t(L) u with phi_t(L) = (e^{tL} - 1)/(e^L - 1); its limit t is used when
// |e^L - 1| < kTwirlTranslation (limits.hpp says why frames stay continuous).
inline Twirl pow(const Twirl& T, double t) {
  const Complex tl = t * T.log();
  return {T.anchor(), T.anchor_motion(t, expm1(tl)), tl};
}

// T . x for a point (PITA Eq. 5), written T * x like the paper's T.x (Sophus's operator*).
inline Point operator*(const Twirl& T, Point x) {
  return T.anchor() + std::exp(T.log()) * (x - T.anchor()) + T.displacement();
}

// T . v for a vector (PITA Eq. 6): only the linear part acts.
inline Vector apply_to_vector(const Twirl& T, Vector v) { return std::exp(T.log()) * v; }

// T . A for an arrow (PITA Eq. 7): moves the origin, scales the magnitude, and adds
// the twirl's winding to the arrow's winding.
inline Arrow operator*(const Twirl& T, const Arrow& A) {
  return {T * A.p, A.m * std::exp(T.log().real()), A.w + T.log().imag()};
}

// T^t . A, computed with a single complex exponential (the hot path of every
// steady construction).
inline Arrow apply_power(const Twirl& T, double t, const Arrow& A) {
  const Complex tl = t * T.log();
  const ExpPair e = exp_pair(tl);
  const Point p = T.anchor() + e.exp * (A.p - T.anchor()) + T.anchor_motion(t, e.expm1);
  return {p, A.m * e.modulus, A.w + tl.imag()};
}

// T^t . x for a point.
inline Point apply_power(const Twirl& T, double t, Point x) {
  const ExpPair e = exp_pair(t * T.log());
  return T.anchor() + e.exp * (x - T.anchor()) + T.anchor_motion(t, e.expm1);
}

// d/dt (T^t . x), the velocity of point x under the steady motion T^t:
// L e^{tL} (x - f) = L e^{tL} ((x - a) + (a - f)), and, when the twirl is a
// translation (limits.hpp), L e^{tL} (x - a) + u, the derivative of the
// fallback phi_t = t.
inline Vector power_velocity(const Twirl& T, double t, Point x) {
  const Complex rate = T.log() * std::exp(t * T.log());
  if (T.is_translation()) return rate * (x - T.anchor()) + T.displacement();
  return rate * ((x - T.anchor()) + T.anchor_offset());
}

// T^{-1}: maps T.a back to a.
inline Twirl inverse(const Twirl& T) {
  // T^{-1} . y = a + e^{-L}(y - a - u); anchored at a' = a + u, it sends a' to a.
  return {T.anchor() + T.displacement(), -T.displacement(), -T.log()};
}

// S . T (apply T first, then S).
Twirl compose(const Twirl& S, const Twirl& T);

// The fixed point f = a - u/(e^L - 1) of the twirl (PITA Eq. 19, sign as
// docs/paper-notes.md N1), or nothing when the twirl is a translation.
inline std::optional<Point> fixed_point(const Twirl& T) {
  if (T.is_translation()) return std::nullopt;
  return T.anchor() - T.anchor_offset();
}

// ------------------------------------------------------------ shared verbs
// The verbs every value type of the core shares under the same names (as
// Sophus's groups do), so that generic code calls any of them: apply,
// compose, inverse, pow above, and log / exp below.

// T . x and T . A, spelled as the verb. (Points are std::complex, so an
// unqualified call also finds std::apply by ADL: write pita::apply.)
inline Point apply(const Twirl& T, Point x) { return T * x; }
inline Arrow apply(const Twirl& T, const Arrow& A) { return T * A; }

// The generator of a twirl: the velocity field x -> L x + v of the steady
// motion T^t (a similarity's Lie algebra element, L = ln m + i w).
struct TwirlLog {
  Complex L{};
  Vector v{};
};

// log T: T . x = e^L x + c with c = T . 0, and v = L c / (e^L - 1), whose
// limit c (a translation) is used where |e^L - 1| < kTwirlTranslation, as
// pow does. In the isolated whole-turn case of Sec. 4.1 (e^L = 1, L != 0,
// distinct origins) no generator exists: the fallback gives the translation
// by c, and exp(log T) is not T there.
TwirlLog log(const Twirl& T);

// exp G: the twirl x -> e^L x + ((e^L - 1)/L) v, anchored at the origin;
// exp(t log T) = T^t.
Twirl exp(const TwirlLog& G);

// The twirl T_{A,B} that maps arrow A onto arrow B (PITA Eq. 17-19): ratio B.m/A.m,
// winding B.w - A.w, anchor A.p, displacement B.p - A.p.
inline Twirl twirl_between(const Arrow& A, const Arrow& B) {
  return {A.p, B.p - A.p, Complex{std::log(B.m / A.m), B.w - A.w}};
}

}  // namespace pita
