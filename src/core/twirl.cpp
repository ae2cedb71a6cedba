#include "core/twirl.hpp"

namespace pita {

Twirl::Twirl(Point anchor, Vector displacement, Complex log)
    : anchor_(anchor), displacement_(displacement), log_(log) {
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

}  // namespace pita
