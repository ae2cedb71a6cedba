#include "scene/sampling.hpp"

#include <stdexcept>

namespace pita::scene {

std::vector<double> uniform_times(double first, double last, int count) {
  if (count < 2) throw std::invalid_argument("uniform_times needs at least 2 samples");
  std::vector<double> times(static_cast<std::size_t>(count));
  const double span = last - first;
  const double intervals = static_cast<double>(count - 1);
  for (int i = 0; i < count; ++i) {
    times[static_cast<std::size_t>(i)] = first + span * static_cast<double>(i) / intervals;
  }
  times.back() = last;  // first + (last - first) may differ from last by an ulp
  return times;
}

}  // namespace pita::scene
