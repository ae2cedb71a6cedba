#include "core/log_matrix_blend.hpp"

#include <string>

#include <Eigen/Core>
#include <unsupported/Eigen/MatrixFunctions>

namespace pita {

namespace {

// The homogeneous log of one pose, or a message naming it.
Affine2 pose_log(const Affine2& pose, const char* which) {
  try {
    return log(pose);
  } catch (const NoRealLogarithm& error) {
    throw NoRealLogarithm(std::string("no Alexa blend of these poses: the ") + which + " pose has no real logarithm (" +
                              error.what() +
                              "); Alexa blends the logs of the poses themselves, so every pose "
                              "needs one, even where a SAM between them exists",
                          error.root_case());
  }
}

}  // namespace

LogMatrixBlend::LogMatrixBlend(const Affine2& B, const Affine2& C)
    : log_B_(pose_log(B, "first")), log_C_(pose_log(C, "second")) {}

Affine2 LogMatrixBlend::generator(double u) const {
  // (1 - u) log B + u log C, written as log B + u (log C - log B).
  return {log_B_.L + u * (log_C_.L - log_B_.L), log_B_.b + u * (log_C_.b - log_B_.b)};
}

Affine2 LogMatrixBlend::at(double u) const { return exp(generator(u)); }

Affine2 LogMatrixBlend::velocity(double u) const {
  const Affine2 M = generator(u);
  Eigen::Matrix<double, 6, 6> H = Eigen::Matrix<double, 6, 6>::Zero();
  H.block<2, 2>(0, 0) = M.L;  // [[M, D], [0, M]], each block homogeneous 3x3
  H.block<2, 1>(0, 2) = M.b;
  H.block<2, 2>(3, 3) = M.L;
  H.block<2, 1>(3, 5) = M.b;
  H.block<2, 2>(0, 3) = log_C_.L - log_B_.L;
  H.block<2, 1>(0, 5) = log_C_.b - log_B_.b;
  const Eigen::Matrix<double, 6, 6> E = H.exp();  // Eigen's scaling and squaring Pade
  return {E.block<2, 2>(0, 3), E.block<2, 1>(0, 5)};
}

}  // namespace pita
