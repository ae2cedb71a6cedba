#include "core/point_motions.hpp"

#include "core/limits.hpp"
#include "core/twirl.hpp"

namespace pita {

LogSpiral::LogSpiral(Point pa, Point pb, Point pc) : pa_(pa), pb_(pb), pc_(pc) {
  const Vector ab = pb - pa;
  const Vector bc = pc - pb;
  const double scale = std::abs(ab) + std::abs(bc);
  degenerate_ =
      std::abs(ab) <= limits::kLogSpiralDegenerate * scale || std::abs(bc) <= limits::kLogSpiralDegenerate * scale;
  // The twirl between zero-turn arrows ab and bc: anchor a, displacement b - a,
  // log = ln(|bc|/|ab|) + i Arg(bc/ab) (principal).
  if (!degenerate_) spiral_ = Twirl(pa, ab, std::log(bc / ab));
}

Point LogSpiral::at(const LagrangeWeights& l) const {
  if (degenerate_) return parabolic_point(l, pa_, pb_, pc_);
  return apply_power(spiral_, l.y + 2.0 * l.z, pa_);  // u = y + 2z
}

}  // namespace pita
