#include "core/chains/neville_chain.hpp"

#include <stdexcept>

#include "core/limits.hpp"

namespace pita {

NevilleChain::NevilleChain(std::span<const Keyframe> keyframes, const WindowMotion& window, int window_size,
                           bool winding_aware)
    : window_size_(window_size), winding_aware_(winding_aware) {
  const auto size = static_cast<std::size_t>(window_size);
  if (keyframes.size() < size) throw std::invalid_argument("too few keyframes for the neville chain");
  if (keyframes.size() > static_cast<std::size_t>(limits::kMaxNevilleKeyframes)) {
    throw std::invalid_argument("the neville chain takes at most " + std::to_string(limits::kMaxNevilleKeyframes) +
                                " keyframes (got " + std::to_string(keyframes.size()) +
                                "): it is global, so its cost per frame grows as n^2 and its swings with n; "
                                "use the local \"blend\" chain");
  }
  for (const Keyframe& key : keyframes) knots_.push_back(key.t);
  for (std::size_t j = 0; j + size <= keyframes.size(); ++j) bottom_.push_back(window(keyframes.subspan(j, size)));
}

Arrow NevilleChain::at(double t) const {
  std::vector<Arrow> level;
  level.reserve(bottom_.size());
  for (const auto& motion : bottom_) level.push_back(motion->at(t));
  // Level L holds the motions through L consecutive keyframes; entry j of it
  // covers keyframes j .. j + L - 1.
  for (std::size_t count = static_cast<std::size_t>(window_size_) + 1; count <= knots_.size(); ++count) {
    for (std::size_t j = 0; j + 1 < level.size(); ++j) {
      const double s = (t - knots_[j]) / (knots_[j + count - 1] - knots_[j]);
      level[j] = steady_blend(level[j], level[j + 1], s, winding_aware_);
    }
    level.pop_back();
  }
  return level.front();
}

}  // namespace pita
