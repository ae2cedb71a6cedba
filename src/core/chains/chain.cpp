#include "core/chains/chain.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include "core/chains/bezier_spiral_chain.hpp"
#include "core/chains/blend_chain.hpp"
#include "core/chains/neville_chain.hpp"
#include "core/chains/spiral_chain.hpp"
#include "core/complex_math.hpp"
#include "core/steady_morph.hpp"

namespace pita {

namespace {

constexpr std::array<ChainInfo, 4> kChains{{
    {Chain::blend, "blend", "steady blend of the method through the two triples that share the span (C1)", true, 1},
    {Chain::neville, "neville",
     "Neville's recursion over all keyframes, the method at the bottom, steady morphs above (PITA Eq. 48-50)", true, 1},
    {Chain::spiral, "spiral", "the SMA between consecutive keyframes (C0)", false, 0},
    {Chain::bezier_spiral, "bezier-spiral",
     "a cubic Bezier of p and of q per span, the span's SMA at 1/3 and 2/3 as controls (C0)", false, 0},
}};

}  // namespace

std::span<const ChainInfo> all_chains() { return kChains; }

const ChainInfo& info(Chain chain) {
  for (const ChainInfo& about : kChains) {
    if (about.chain == chain) return about;
  }
  throw std::logic_error("unregistered chain");
}

const ChainInfo* find_chain(std::string_view name) {
  for (const ChainInfo& about : kChains) {
    if (about.name == name) return &about;
  }
  return nullptr;
}

std::string chain_names() {
  std::string names;
  for (const ChainInfo& about : kChains) {
    if (!names.empty()) names += ", ";
    names += '"';
    names += about.name;
    names += '"';
  }
  return names;
}

double chain_frame_cost(Chain chain, std::size_t count) {
  const double n = static_cast<double>(count);
  switch (chain) {
    case Chain::blend:
      return 3.0;
    case Chain::neville:
      return std::max(n - 2.0, 1.0) + std::max((n - 2.0) * (n - 3.0) / 2.0, 0.0);
    case Chain::spiral:
      return 1.0;
    case Chain::bezier_spiral:
      return 2.0;
  }
  return 1.0;
}

std::size_t span_of(std::span<const double> knots, double t) {
  if (knots.size() < 2) return 0;
  // The last knot <= t, clamped to the spans there are (NaN lands in span 0).
  const auto after = std::upper_bound(knots.begin(), knots.end(), t);
  const auto index = static_cast<std::size_t>(std::max<std::ptrdiff_t>(after - knots.begin() - 1, 0));
  return std::min(index, knots.size() - 2);
}

Arrow steady_blend(const Arrow& X, Arrow Y, double s, bool winding_aware) {
  if (s == 0.0) return X;
  if (s == 1.0) return Y;
  if (!winding_aware) Y.w = X.w + principal_angle(Y.w - X.w);
  return steady_morph(X, Y, s);
}

std::unique_ptr<Motion> make_chain(Chain chain, std::span<const Keyframe> keyframes, const WindowMotion& window,
                                   int window_size, const WindowMotion& sma, bool winding_aware) {
  switch (chain) {
    case Chain::blend:
      if (window_size != 3) {
        throw std::invalid_argument(
            "the blend chain blends a method through three keyframes, and the SMA interpolates two: use the "
            "\"spiral\", \"bezier-spiral\" or \"neville\" chain, or P9 (an SMA of SMAs) for the blend of "
            "consecutive spirals");
      }
      return std::make_unique<BlendChain>(keyframes, window, winding_aware);
    case Chain::neville:
      return std::make_unique<NevilleChain>(keyframes, window, window_size, winding_aware);
    case Chain::spiral:
      return std::make_unique<SpiralChain>(keyframes, sma);
    case Chain::bezier_spiral:
      return std::make_unique<BezierSpiralChain>(keyframes, sma);
  }
  throw std::logic_error("unhandled chain");
}

}  // namespace pita
