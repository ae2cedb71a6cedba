// Keyframe tracks: motions through n >= 3 timed keyframes (n >= 2 for chains
// of steady morphs), built from a three-keyframe method (or the SMA) and a
// chain rule that says how it extends past three keyframes. The PITA paper
// stops at three keyframes (its conclusion names "more than 3" as the next
// step); Sec. 7.6 (PITA Eq. 48-50) blends two PITAs for four points, and the
// course project on drawn targets chains spirals. docs/paper-notes.md N33
// records how pita reads and completes them.
//
// Every chain passes through every keyframe at its knot and is defined for
// every real t: before the first knot and after the last it continues the
// first and last span's motion.
#pragma once

#include <functional>
#include <memory>
#include <span>
#include <string_view>

#include "core/keyframe.hpp"
#include "core/pitas/motion.hpp"

namespace pita {

enum class Chain {
  blend,          // steady blend of the two overlapping triples of each span (C1)
  neville,        // Neville's recursion over all keyframes, steady blends above the method
  spiral,         // the SMA between consecutive keyframes (C0)
  bezier_spiral,  // a cubic Bezier per span with the span's SMA at 1/3 and 2/3 as controls
};

struct ChainInfo {
  Chain chain;
  std::string_view name;   // as scene files spell it: "blend", "bezier-spiral"
  std::string_view title;  // one line for help and the docs
  // True when the chain is built from the method at three keyframes; false
  // when it is built from steady morphs between consecutive keyframes
  // whatever the method.
  bool uses_method;
  // Continuity at interior knots, 0 or 1 (what the tests measure).
  int continuity;
};

// Every chain, the one table of them (help, schema and docs derive from it).
std::span<const ChainInfo> all_chains();
const ChainInfo& info(Chain chain);
// The chain named `name` (exact spelling); nullptr if none.
const ChainInfo* find_chain(std::string_view name);
// "blend", "neville", ...: every name, quoted and comma-separated (messages).
std::string chain_names();

// The method's own motion through a window of its keyframe count (three, or
// two for the SMA), with any strictly increasing knots.
using WindowMotion = std::function<std::unique_ptr<Motion>(std::span<const Keyframe>)>;

// The chain through `keyframes` (knots strictly increasing, checked by the
// caller). `window` builds the method at `window_size` consecutive keyframes
// (3 for a PITA, 2 for the SMA); `sma` builds the steady morph between two
// consecutive keyframes (spiral and bezier-spiral chains use it).
// Throws std::invalid_argument when the chain cannot be built with this
// window size (blend needs three) or too many keyframes for neville.
// `winding_aware`: whether the method's windings mean turns (MethodInfo);
// when not, blends take the principal winding difference (steady_blend).
std::unique_ptr<Motion> make_chain(Chain chain, std::span<const Keyframe> keyframes, const WindowMotion& window,
                                   int window_size, const WindowMotion& sma, bool winding_aware);

// The steady blend M(X, Y, s) of the chains (PITA Eq. 20): exactly X at s = 0 and
// Y at s = 1 (whatever the other is, so that far windows that overflow cannot
// spoil a knot). For a method that is not winding-aware (P1, P5, P7, P8, ...
// report windings only modulo 2 pi, docs/paper-notes.md N21) Y's winding is
// first moved to the branch nearest X's, so that the blend adds no spurious
// turn.
Arrow steady_blend(const Arrow& X, Arrow Y, double s, bool winding_aware);

// What one frame of the chain over `count` keyframes costs, in frames of the
// method itself (for work budgets): blend 3 (two windows and a blend),
// neville (n - 2) windows and (n - 2)(n - 3)/2 blends, spiral 1, bezier-spiral 2.
double chain_frame_cost(Chain chain, std::size_t count);

// Index i of the span [t_i, t_{i+1}] that holds t, clamped to [0, n - 2]
// (t before the first knot is in span 0, after the last in span n - 2).
std::size_t span_of(std::span<const double> knots, double t);

}  // namespace pita
