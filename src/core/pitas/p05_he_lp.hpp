// P5:He-LP (Sec. 3.2, PITA Eq. 33, appendices A and C): the exponential of the
// Lagrange-weighted mean of the logs of the keyframes' homogeneous matrices,
// taken about the centroid o of the three origins (appendix C's heuristic).
// Logs use principal angles (docs/paper-notes.md N6), so P5 is not winding-aware
// and pops when a keyframe angle crosses +-pi. It is invariant to translations
// only (item 7): see HsLp for the similarity-invariant variant.
//
// In complex form a similarity z -> e^l z + p has log (l, v) with
// v = p l / (e^l - 1) (PITA Eq. A.7-A.8), and exp(l, v) = (e^l, (e^l - 1)/l v) (A.6).
#pragma once

#include "core/keyframe.hpp"
#include "core/pitas/motion.hpp"

namespace pita {

// Where the logs are taken: about the centroid of the origins (P5, appendix
// C's heuristic) or about the global origin g (H(t) of prior art [22], the
// He-G variant of Fig. C.31, which translations change; docs/paper-notes.md N56).
enum class HomogeneousCenter { centroid, global_origin };

class HeLp final : public Motion {
 public:
  explicit HeLp(const KeyframeTriple& k, HomogeneousCenter center = HomogeneousCenter::centroid);
  Arrow at(double t) const override;

 private:
  KeyframeTriple k_;
  Complex log_[3];              // ln m + i Arg(e^{iw}) of each keyframe
  Complex translation_log_[3];  // v of each keyframe, about the centroid
  Point centroid_;
};

}  // namespace pita
