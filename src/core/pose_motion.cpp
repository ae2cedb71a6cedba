#include "core/pose_motion.hpp"

#include <array>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace pita {

namespace {

bool is_fig2_morph(PoseMethod method) {
  return method == PoseMethod::rarap || method == PoseMethod::asap || method == PoseMethod::tsb;
}

}  // namespace

std::array<Point, 3> default_reference_triangle() { return {Point{0.0, 0.0}, Point{1.0, 0.0}, Point{0.0, 1.0}}; }

PoseMotion::PoseMotion(PoseMethod method, std::vector<TimedPose> poses, int subdivisions,
                       const std::array<Point, 3>& reference)
    : method_(method), poses_(std::move(poses)) {
  if (info(method).in_space) {
    family_.emplace(method, poses_, subdivisions);
    return;
  }
  check_poses(method, poses_);
  if (method == PoseMethod::alexa) {
    try {
      morph_.emplace(LogMatrixBlend(poses_[0].pose, poses_[1].pose));
    } catch (const NoRealLogarithm& error) {
      throw NoSamBetweenPoses(error, 0);
    }
    return;
  }
  if (is_fig2_morph(method)) {
    const Affine2& from = poses_[0].pose;
    const Affine2& to = poses_[1].pose;
    const Point centre = (reference[0] + reference[1] + reference[2]) / 3.0;
    const Eigen::Vector2d c(centre.real(), centre.imag());
    // All three need C o B^-1 to preserve orientation (ARAP interpolates no
    // reflection; TSB's triangle would flatten on the way).
    const double det = compose(to, inverse(from)).L.determinant();
    if (!(det > 0.0)) {
      char reason[200];
      std::snprintf(reason, sizeof reason,
                    "%s: one pose is mirrored and the other is not (C o B^-1 has determinant %g <= 0); "
                    "the morph interpolates no reflection: mirror both poses or neither",
                    std::string(info(method).id).c_str(), det);
      throw std::invalid_argument(reason);
    }
    if (method == PoseMethod::rarap) morph_.emplace(RarapMorph(from, to, c));
    if (method == PoseMethod::asap) morph_.emplace(SpiralResidueMorph(from, to, c));
    if (method == PoseMethod::tsb) morph_.emplace(TriangleSpiralBlend(from, to, reference));
    return;
  }
}

// The Fig. 2 morphs and Alexa's: two poses, extrapolated outside the knots.
Affine2 PoseMotion::evaluate(double t) const {
  if (family_) return family_->at(t);
  if (t == poses_[0].t) return poses_[0].pose;
  if (t == poses_[1].t) return poses_[1].pose;
  const double u = (t - poses_[0].t) / (poses_[1].t - poses_[0].t);
  return std::visit([u](const auto& morph) { return morph.at(u); }, *morph_);
}

Affine2 PoseMotion::at(double t) const { return evaluate(t); }

Affine2 PoseMotion::velocity(double t) const {
  if (family_) return family_->velocity(t);
  const double duration = poses_[1].t - poses_[0].t;
  const double u = (t - poses_[0].t) / duration;
  const Affine2 rate = std::visit([u](const auto& morph) { return morph.velocity(u); }, *morph_);
  return {rate.L / duration, rate.b / duration};
}

}  // namespace pita
