#include "scene/arrow_json.hpp"

namespace pita::scene {

nlohmann::ordered_json point_json(Point p) { return nlohmann::ordered_json::array({p.real(), p.imag()}); }

nlohmann::ordered_json arrow_json(const Arrow& a) {
  return nlohmann::ordered_json{{"p", point_json(a.p)}, {"m", a.m}, {"w", a.w}};
}

}  // namespace pita::scene
