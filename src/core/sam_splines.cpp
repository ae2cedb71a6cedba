#include "core/sam_splines.hpp"

#include <algorithm>

namespace pita {

Affine2 sam(const Affine2& from, double t, const Affine2& to) {
  return steady_affine_morph(from, to, t);
}

Affine2 sam_moved(const Affine2& pose, const Affine2& from, double t, const Affine2& to) {
  return compose(SteadyAffineMorph(from, to).powers().at(t), pose);
}

Affine2 bezier_sam(const Affine2& A, const Affine2& B, const Affine2& C, double t) {
  return sam(sam(A, t, B), t, sam(B, t, C));
}

Affine2 bezier_sam(const Affine2& A, const Affine2& B, const Affine2& C, const Affine2& D, double t) {
  return sam(bezier_sam(A, B, C, t), t, bezier_sam(B, C, D, t));
}

Affine2 left_control(const Affine2& A, const Affine2& B, const Affine2& C) {
  return sam_moved(sam(A, 0.75, B), C, 0.25, B);
}

Affine2 sam_patch(const Affine2& A, const Affine2& B, const Affine2& C, const Affine2& D, double u,
                  double v) {
  return sam(sam(A, u, B), v, sam(C, u, D));
}

Affine2 regular_patch_corner(const Affine2& A, const Affine2& B, const Affine2& C) {
  return sam_moved(C, A, 1.0, B);
}

SamBiarc::SamBiarc(const Affine2& A, const Affine2& B, const Affine2& C)
    : A_(A), B_(B), C_(C), left_(left_control(A, B, C)), right_(left_control(C, B, A)) {}

Affine2 SamBiarc::at(double u) const {
  if (u <= 0.5) return bezier_sam(A_, left_, B_, 2.0 * u);
  return bezier_sam(B_, right_, C_, 2.0 * u - 1.0);
}

std::vector<Affine2> subdivide_four_point(const std::vector<Affine2>& poses) {
  const std::size_t n = poses.size();
  if (n < 3) return poses;
  const auto left = [](const Affine2& A, const Affine2& B, const Affine2& C) {
    return sam_moved(sam(A, 0.625, B), C, 0.125, B);
  };
  std::vector<Affine2> predicted_left(n), predicted_right(n);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    predicted_left[i] = left(poses[i - 1], poses[i], poses[i + 1]);
    predicted_right[i] = left(poses[i + 1], poses[i], poses[i - 1]);
  }
  std::vector<Affine2> result(2 * n - 1);
  for (std::size_t i = 0; i < n; ++i) result[2 * i] = poses[i];
  for (std::size_t i = 1; i + 2 < n; ++i) {
    result[2 * i + 1] = sam(predicted_right[i], 0.5, predicted_left[i + 1]);
  }
  result[1] = predicted_left[1];
  result[2 * n - 3] = predicted_right[n - 2];
  return result;
}

}  // namespace pita
