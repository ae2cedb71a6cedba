// The "neville" chain (docs/paper-notes.md N33): Aitken-Neville's recursion
// over all n keyframes with the method as its bottom level (three keyframes,
// or two for the SMA) and steady morphs (PITA Eq. 20) above it:
//   N[j..k](t) = M(N[j..k-1](t), N[j+1..k](t), (t - t_j)/(t_k - t_j)).
// For four keyframes it is Sec. 7.6's construction (PITA Eq. 48-50) on arrows;
// with the SMA at the bottom and three keyframes it is P9 (PITA Eq. D.2).
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "core/chains/chain.hpp"

namespace pita {

class NevilleChain final : public Motion {
 public:
  // `keyframes`: n >= window_size, knots strictly increasing; window_size 2 or 3.
  NevilleChain(std::span<const Keyframe> keyframes, const WindowMotion& window, int window_size,
               bool winding_aware = true);
  Arrow at(double t) const override;

 private:
  std::vector<double> knots_;
  int window_size_;
  bool winding_aware_;
  std::vector<std::unique_ptr<Motion>> bottom_;  // bottom_[j] through keyframes j .. j + window_size - 1
};

}  // namespace pita
