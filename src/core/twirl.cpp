#include "core/twirl.hpp"

namespace pita {

Twirl compose(const Twirl& S, const Twirl& T) {
  // (S.T).x = S.(T.x). Keep T's anchor: (S.T).a = S.(a + u_T).
  const Point image = S * (T.anchor + T.displacement);
  return {T.anchor, image - T.anchor, S.log + T.log};
}

std::optional<Point> fixed_point(const Twirl& T) {
  const Complex den = expm1(T.log);
  if (std::abs(den) < limits::kTwirlTranslation) return std::nullopt;
  // a + e^L (f - a) + u = f  =>  f = a - u / (e^L - 1).
  return T.anchor - T.displacement / den;
}

}  // namespace pita
