#include "core/chains/blend_chain.hpp"

#include <stdexcept>

namespace pita {

BlendChain::BlendChain(std::span<const Keyframe> keyframes, const WindowMotion& triple, bool winding_aware)
    : winding_aware_(winding_aware) {
  if (keyframes.size() < 3) throw std::invalid_argument("the blend chain needs at least 3 keyframes");
  for (const Keyframe& key : keyframes) knots_.push_back(key.t);
  for (std::size_t j = 0; j + 2 < keyframes.size(); ++j) triples_.push_back(triple(keyframes.subspan(j, 3)));
}

Arrow BlendChain::at(double t) const {
  const std::size_t i = span_of(knots_, t);
  // X, the triple centred on keyframe i, exists from the second span on; Y,
  // the triple centred on keyframe i + 1, up to the last but one.
  const bool has_x = i >= 1;
  const bool has_y = i + 2 < knots_.size();
  if (!has_x) return triples_[i]->at(t);
  if (!has_y) return triples_[i - 1]->at(t);
  const double s = (t - knots_[i]) / (knots_[i + 1] - knots_[i]);
  // Both triples pass through keyframe i at t_i and keyframe i + 1 at
  // t_{i+1}, so there M's twirl is the identity and D' is the shared
  // triple's: C1 at every interior knot.
  return steady_blend(triples_[i - 1]->at(t), triples_[i]->at(t), s, winding_aware_);
}

}  // namespace pita
