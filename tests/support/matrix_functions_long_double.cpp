// The long double half of matrix_functions.hpp; dynamic-size, as the double half.
#include <unsupported/Eigen/MatrixFunctions>

#include "support/matrix_functions.hpp"

namespace pita::oracle {
namespace {

using MatrixX = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;

MatrixX log_of(const MatrixX& M) { return M.log(); }
MatrixX exp_of(const MatrixX& M) { return M.exp(); }
MatrixX pow_of(const MatrixX& M, long double t) { return M.pow(t); }

}  // namespace

MatrixLd<3> log(const MatrixLd<3>& M) { return log_of(M); }
MatrixLd<4> log(const MatrixLd<4>& M) { return log_of(M); }
MatrixLd<3> exp(const MatrixLd<3>& M) { return exp_of(M); }
MatrixLd<4> exp(const MatrixLd<4>& M) { return exp_of(M); }
MatrixLd<3> pow(const MatrixLd<3>& M, long double t) { return pow_of(M, t); }
MatrixLd<4> pow(const MatrixLd<4>& M, long double t) { return pow_of(M, t); }

}  // namespace pita::oracle
