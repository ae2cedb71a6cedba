#include "core/point_motions.hpp"

#include "core/limits.hpp"
#include "core/twirl.hpp"

namespace pita {

Point log_spiral_point(const LagrangeWeights& l, Point pa, Point pb, Point pc) {
  const Vector ab = pb - pa;
  const Vector bc = pc - pb;
  const double scale = std::abs(ab) + std::abs(bc);
  if (std::abs(ab) <= limits::kLogSpiralDegenerate * scale ||
      std::abs(bc) <= limits::kLogSpiralDegenerate * scale) {
    return parabolic_point(l, pa, pb, pc);
  }
  const double u = l.y + 2.0 * l.z;
  // The twirl between zero-turn arrows ab and bc: anchor a, displacement b - a,
  // log = ln(|bc|/|ab|) + i Arg(bc/ab) (principal).
  const Twirl spiral{pa, ab, std::log(bc / ab)};
  return apply_power(spiral, u, pa);
}

}  // namespace pita
