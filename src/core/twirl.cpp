#include "core/twirl.hpp"

#include "core/limits.hpp"

namespace pita {

Twirl::Twirl(Point anchor, Vector displacement, Complex log) : anchor_(anchor), displacement_(displacement), log_(log) {
  const Complex den = expm1(log);
  translation_ = std::norm(den) < limits::kTwirlTranslation * limits::kTwirlTranslation;
  // a + e^L (f - a) + u = f  =>  a - f = u / (e^L - 1).
  offset_ = translation_ ? Vector{} : displacement / den;
}

Twirl compose(const Twirl& S, const Twirl& T) {
  // (S.T).x = S.(T.x). Keep T's anchor: (S.T).a = S.(a + u_T).
  const Point image = S * (T.anchor() + T.displacement());
  return {T.anchor(), image - T.anchor(), S.log() + T.log()};
}

TwirlLog log(const Twirl& T) {
  const Point c = T * Point{};
  const Complex em1 = expm1(T.log());
  if (std::abs(em1) < limits::kTwirlTranslation) return {T.log(), c};
  return {T.log(), T.log() * c / em1};
}

Twirl exp(const TwirlLog& G) {
  const Complex em1 = expm1(G.L);
  // (e^L - 1)/L, with its limit 1 at L = 0.
  const Complex ratio = std::abs(G.L) < limits::kTwirlTranslation ? Complex{1.0, 0.0} + 0.5 * G.L : em1 / G.L;
  return {Point{}, ratio * G.v, G.L};
}

}  // namespace pita
