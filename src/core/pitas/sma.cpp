#include "core/pitas/sma.hpp"

#include "core/mean_morph.hpp"

namespace pita {

SteadyMorphMotion::SteadyMorphMotion(const Keyframe& a, const Keyframe& b, MeanKind path_mean, MeanKind magnitude_mean)
    : a_(a), b_(b), path_mean_(path_mean), magnitude_mean_(magnitude_mean), twirl_(twirl_between(a.arrow, b.arrow)) {}

Arrow SteadyMorphMotion::at(double t) const {
  const double q = (t - a_.t) / (b_.t - a_.t);  // PITA Eq. 14, 21
  if (path_mean_ == MeanKind::geometric && magnitude_mean_ == MeanKind::geometric) {
    return apply_power(twirl_, q, a_.arrow);
  }
  return mean_morph(a_.arrow, b_.arrow, q, path_mean_, magnitude_mean_);
}

}  // namespace pita
