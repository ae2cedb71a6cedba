#include "core/sam_splines.hpp"

#include <algorithm>

namespace pita {

template <class Pose>
Pose sam(const Pose& from, double t, const Pose& to) {
  return SteadyAffineMorph<Pose>(from, to).at(t);
}

template <class Pose>
Pose sam_moved(const Pose& pose, const Pose& from, double t, const Pose& to) {
  return compose(SteadyAffineMorph<Pose>(from, to).powers().at(t), pose);
}

template <class Pose>
Pose bezier_sam(const Pose& A, const Pose& B, const Pose& C, double t) {
  return sam(sam(A, t, B), t, sam(B, t, C));
}

template <class Pose>
Pose bezier_sam(const Pose& A, const Pose& B, const Pose& C, const Pose& D, double t) {
  return sam(bezier_sam(A, B, C, t), t, bezier_sam(B, C, D, t));
}

template <class Pose>
Pose left_control(const Pose& A, const Pose& B, const Pose& C) {
  return sam_moved(sam(A, 0.75, B), C, 0.25, B);
}

template <class Pose>
Pose sam_patch(const Pose& A, const Pose& B, const Pose& C, const Pose& D, double u, double v) {
  return sam(sam(A, u, B), v, sam(C, u, D));
}

template <class Pose>
Pose regular_patch_corner(const Pose& A, const Pose& B, const Pose& C) {
  return sam_moved(C, A, 1.0, B);
}

template <class Pose>
SamBiarcOf<Pose>::SamBiarcOf(const Pose& A, const Pose& B, const Pose& C)
    : A_(A), B_(B), C_(C), left_(left_control(A, B, C)), right_(left_control(C, B, A)) {}

template <class Pose>
Pose SamBiarcOf<Pose>::at(double u) const {
  if (u <= 0.5) return bezier_sam(A_, left_, B_, 2.0 * u);
  return bezier_sam(B_, right_, C_, 2.0 * u - 1.0);
}

template <class Pose>
std::vector<Pose> subdivide_four_point(const std::vector<Pose>& poses) {
  const std::size_t n = poses.size();
  if (n < 3) return poses;
  const auto left = [](const Pose& A, const Pose& B, const Pose& C) {
    return sam_moved(sam(A, 0.625, B), C, 0.125, B);
  };
  std::vector<Pose> predicted_left(n), predicted_right(n);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    predicted_left[i] = left(poses[i - 1], poses[i], poses[i + 1]);
    predicted_right[i] = left(poses[i + 1], poses[i], poses[i - 1]);
  }
  std::vector<Pose> result(2 * n - 1);
  for (std::size_t i = 0; i < n; ++i) result[2 * i] = poses[i];
  for (std::size_t i = 1; i + 2 < n; ++i) {
    result[2 * i + 1] = sam(predicted_right[i], 0.5, predicted_left[i + 1]);
  }
  result[1] = predicted_left[1];
  result[2 * n - 3] = predicted_right[n - 2];
  return result;
}

#define PITA_INSTANTIATE_SAM_SPLINES(Pose)                                                     \
  template Pose sam(const Pose&, double, const Pose&);                                         \
  template Pose sam_moved(const Pose&, const Pose&, double, const Pose&);                      \
  template Pose bezier_sam(const Pose&, const Pose&, const Pose&, double);                     \
  template Pose bezier_sam(const Pose&, const Pose&, const Pose&, const Pose&, double);        \
  template Pose left_control(const Pose&, const Pose&, const Pose&);                           \
  template Pose sam_patch(const Pose&, const Pose&, const Pose&, const Pose&, double, double); \
  template Pose regular_patch_corner(const Pose&, const Pose&, const Pose&);                   \
  template class SamBiarcOf<Pose>;                                                             \
  template std::vector<Pose> subdivide_four_point(const std::vector<Pose>&);

PITA_INSTANTIATE_SAM_SPLINES(Affine2)
PITA_INSTANTIATE_SAM_SPLINES(Affine3)

#undef PITA_INSTANTIATE_SAM_SPLINES

}  // namespace pita
