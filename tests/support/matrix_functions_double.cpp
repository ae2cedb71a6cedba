// The double half of matrix_functions.hpp (two files, so that the two halves
// compile in parallel). Each function is Eigen's on the dynamic-size matrix:
// one instantiation of the Schur-Pade machinery serves every size (three
// fixed sizes took three times as long to compile, docs/explanation/build-time.md "Build time").
#include <unsupported/Eigen/MatrixFunctions>

#include "support/matrix_functions.hpp"

namespace pita::oracle {
namespace {

using MatrixX = Eigen::MatrixXd;

MatrixX log_of(const MatrixX& M) { return M.log(); }
MatrixX exp_of(const MatrixX& M) { return M.exp(); }
MatrixX pow_of(const MatrixX& M, double t) { return M.pow(t); }

}  // namespace

Eigen::Matrix2d log(const Eigen::Matrix2d& M) { return log_of(M); }
Eigen::Matrix3d log(const Eigen::Matrix3d& M) { return log_of(M); }
Eigen::Matrix4d log(const Eigen::Matrix4d& M) { return log_of(M); }
Eigen::Matrix2d exp(const Eigen::Matrix2d& M) { return exp_of(M); }
Eigen::Matrix3d exp(const Eigen::Matrix3d& M) { return exp_of(M); }
Eigen::Matrix4d exp(const Eigen::Matrix4d& M) { return exp_of(M); }
Eigen::Matrix3d pow(const Eigen::Matrix3d& M, double t) { return pow_of(M, t); }
Eigen::Matrix4d pow(const Eigen::Matrix4d& M, double t) { return pow_of(M, t); }

}  // namespace pita::oracle
