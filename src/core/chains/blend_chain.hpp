// The "blend" chain (docs/paper-notes.md N33): on the span [t_i, t_{i+1}]
//   D(t) = M(X(t), Y(t), s),  s = (t - t_i)/(t_{i+1} - t_i),
// with X the method through keyframes i-1, i, i+1, Y the method through
// i, i+1, i+2 and M the steady morph (PITA Eq. 20). The first and last spans, and
// times outside the knots, use the one triple they have.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "core/chains/chain.hpp"

namespace pita {

class BlendChain final : public Motion {
 public:
  // `keyframes`: n >= 3, knots strictly increasing.
  BlendChain(std::span<const Keyframe> keyframes, const WindowMotion& triple, bool winding_aware = true);
  Arrow at(double t) const override;

 private:
  std::vector<double> knots_;
  bool winding_aware_;
  std::vector<std::unique_ptr<Motion>> triples_;  // triples_[j] through keyframes j, j+1, j+2
};

}  // namespace pita
