// The "spiral" chain (docs/paper-notes.md N33): the SMA (PITA Eq. 21) between each
// pair of consecutive keyframes, the course project's primary scheme. C0 at
// the knots; before the first knot and after the last it extrapolates the
// first and last SMA along their log-spirals.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "core/chains/chain.hpp"

namespace pita {

class SpiralChain final : public Motion {
 public:
  SpiralChain(std::span<const Keyframe> keyframes, const WindowMotion& sma);
  Arrow at(double t) const override;

 private:
  std::vector<double> knots_;
  std::vector<std::unique_ptr<Motion>> spans_;  // spans_[i] from keyframe i to i + 1
};

}  // namespace pita
