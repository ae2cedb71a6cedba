#include "analysis/arrow_distance.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pita::analysis {

double endpoint_distance(const Arrow& A, const Arrow& B) {
  return std::max(std::abs(A.p - B.p), std::abs(A.q() - B.q()));
}

double pattern_distance(std::span<const Arrow> first, std::span<const Arrow> second) {
  if (first.size() != second.size()) throw std::invalid_argument("pattern_distance: patterns of different sizes");
  double largest = 0.0;
  for (std::size_t i = 0; i < first.size(); ++i) largest = std::max(largest, endpoint_distance(first[i], second[i]));
  return largest;
}

}  // namespace pita::analysis
