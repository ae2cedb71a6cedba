// Eigen's generic matrix functions (unsupported/Eigen/MatrixFunctions:
// Schur-Pade log and pow, scaling-and-squaring exp), the independent oracle
// the tests and the benchmark compare pita's closed forms with, compiled once
// in this support library (docs/explanation/build-time.md "Build time": instantiating them took about
// a minute in each of the eleven files that included MatrixFunctions).
//
// Plain functions over fixed sizes, in double and in long double; each is
// Eigen's `M.log()`, `M.exp()`, `M.pow(t)` of M as a dynamic-size matrix (the
// same algorithms; one instantiation for every size).
#pragma once

#include <Eigen/Core>

namespace pita::oracle {

template <int N>
using MatrixLd = Eigen::Matrix<long double, N, N>;

Eigen::Matrix2d log(const Eigen::Matrix2d& M);
Eigen::Matrix3d log(const Eigen::Matrix3d& M);
Eigen::Matrix4d log(const Eigen::Matrix4d& M);
MatrixLd<3> log(const MatrixLd<3>& M);
MatrixLd<4> log(const MatrixLd<4>& M);

Eigen::Matrix2d exp(const Eigen::Matrix2d& M);
Eigen::Matrix3d exp(const Eigen::Matrix3d& M);
Eigen::Matrix4d exp(const Eigen::Matrix4d& M);
MatrixLd<3> exp(const MatrixLd<3>& M);
MatrixLd<4> exp(const MatrixLd<4>& M);

Eigen::Matrix3d pow(const Eigen::Matrix3d& M, double t);
Eigen::Matrix4d pow(const Eigen::Matrix4d& M, double t);
MatrixLd<3> pow(const MatrixLd<3>& M, long double t);
MatrixLd<4> pow(const MatrixLd<4>& M, long double t);

}  // namespace pita::oracle
