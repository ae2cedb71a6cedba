// Time samples at which a motion is evaluated.
#pragma once

#include <vector>

namespace pita::scene {

// `count` >= 2 evenly spaced times from `first` to `last`, both included:
// t_i = first + (last - first) i / (count - 1). The ends are exactly `first`
// and `last` (so the keyframes themselves are reproduced at the ends). Throws
// std::invalid_argument if count < 2.
std::vector<double> uniform_times(double first, double last, int count);

}  // namespace pita::scene
