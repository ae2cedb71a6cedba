#include "core/chains/spiral_chain.hpp"

#include <stdexcept>

namespace pita {

SpiralChain::SpiralChain(std::span<const Keyframe> keyframes, const WindowMotion& sma) {
  if (keyframes.size() < 2) throw std::invalid_argument("the spiral chain needs at least 2 keyframes");
  for (const Keyframe& key : keyframes) knots_.push_back(key.t);
  for (std::size_t i = 0; i + 1 < keyframes.size(); ++i) spans_.push_back(sma(keyframes.subspan(i, 2)));
}

Arrow SpiralChain::at(double t) const { return spans_[span_of(knots_, t)]->at(t); }

}  // namespace pita
