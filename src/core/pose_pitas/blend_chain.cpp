#include "core/pose_pitas/blend_chain.hpp"

#include <stdexcept>
#include <string>

#include "core/chains/chain.hpp"

namespace pita {

namespace {

template <class Pose>
Pose pita_at(const PosePita<Pose>& pita, double t) {
  return std::visit([t](const auto& triple) { return triple.at(t); }, pita);
}

}  // namespace

template <class Pose>
PoseBlendChain<Pose>::PoseBlendChain(PoseMethod method, std::span<const TimedPoseOf<Pose>> poses) {
  if (poses.size() < 3) throw std::invalid_argument("a pose PITA needs at least 3 poses");
  for (const TimedPoseOf<Pose>& pose : poses) knots_.push_back(pose.t);
  for (std::size_t j = 0; j + 2 < poses.size(); ++j) {
    try {
      triples_.push_back(make_pose_pita<Pose>(method, {poses[j], poses[j + 1], poses[j + 2]}));
    } catch (const NoPosePitaPower& error) {
      // Count the poses from the first of all (P5 names its pose in where()).
      const std::size_t first = j + error.first();
      const bool own_pose = error.where() == "pose " + std::to_string(error.first());
      throw NoPosePitaPower(error, first, own_pose ? "pose " + std::to_string(first) : error.where(), error.time());
    }
  }
}

template <class Pose>
Pose PoseBlendChain<Pose>::at(double t) const {
  const std::size_t i = span_of(knots_, t);
  // X, the triple centred on pose i, exists from the second span on; Y, the
  // triple centred on pose i + 1, up to the last but one.
  if (i == 0) return pita_at(triples_[0], t);
  if (i + 2 >= knots_.size()) return pita_at(triples_[i - 1], t);
  const double s = (t - knots_[i]) / (knots_[i + 1] - knots_[i]);
  const Pose x = pita_at(triples_[i - 1], t), y = pita_at(triples_[i], t);
  // D = M(X, Y, s)   (PITA Eq. 20 with the SAM's power, N79)
  return formed_morph(x, y, "between the two pose PITAs the blend chain joins on span " + std::to_string(i), t).at(s);
}

template class PoseBlendChain<Affine2>;
template class PoseBlendChain<Affine3>;

}  // namespace pita
