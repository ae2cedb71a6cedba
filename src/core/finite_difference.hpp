// Finite-difference weights on arbitrary nodes (Fornberg 1988): the weights
// w_j such that f^(m)(x0) ~ sum_j w_j f(x_j), exact for polynomials of degree
// < nodes.size(). With the five centred nodes x0 + h {-2, -1, 0, 1, 2} they
// are the classical fourth-order stencils
//     f'(x0)  ~ (f_{-2} - 8 f_{-1} + 8 f_1 - f_2) / (12 h),
//     f''(x0) ~ (-f_{-2} + 16 f_{-1} - 30 f_0 + 16 f_1 - f_2) / (12 h^2);
// with six one-sided nodes x0 + h {0, ..., 5} both derivatives keep fourth
// order (docs/paper-notes.md N40).
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace pita {

// weights[m][j]: the weight of f(nodes[j]) in the m-th derivative at x0, for
// m = 0 .. max_order. The nodes must be distinct.
std::vector<std::vector<double>> fornberg_weights(double x0, const std::vector<double>& nodes, int max_order);

// The classical stencils on equally spaced nodes, written out: the
// derivatives of f, a function of one real variable whose values add and
// scale (double, Complex, Eigen vectors), from its values at x + k h. Each
// sums its terms in the order its formula is written, so that every caller
// gets the same bits. h may be negative (a one-sided stencil then looks left).

// The value type of f.
template <class F>
using StencilValue = std::decay_t<std::invoke_result_t<const F&, double>>;

// f'(x) ~ (f(x + h) - f(x - h)) / (2 h): second order.
template <class F>
StencilValue<F> central_derivative(const F& f, double x, double h) {
  return StencilValue<F>((f(x + h) - f(x - h)) / (2.0 * h));
}

// f'(x) ~ (f(x - 2h) - 8 f(x - h) + 8 f(x + h) - f(x + 2h)) / (12 h): fourth order.
template <class F>
StencilValue<F> central_derivative4(const F& f, double x, double h) {
  return StencilValue<F>((f(x - 2 * h) - 8.0 * f(x - h) + 8.0 * f(x + h) - f(x + 2 * h)) / (12.0 * h));
}

// f'(x) ~ sum_k c_k (f(x + k h) - f(x - k h)) / h, k = 1 .. 4, with
// c = 4/5, -1/5, 4/105, -1/280: eighth order.
template <class F>
StencilValue<F> central_derivative8(const F& f, double x, double h) {
  static constexpr double c[4] = {4.0 / 5.0, -1.0 / 5.0, 4.0 / 105.0, -1.0 / 280.0};
  StencilValue<F> derivative = c[0] * (f(x + h) - f(x - h));
  for (int k = 1; k < 4; ++k) derivative += c[k] * (f(x + (k + 1) * h) - f(x - (k + 1) * h));
  derivative /= h;
  return derivative;
}

// f'(x) ~ (-25 f(x) + 48 f(x + h) - 36 f(x + 2h) + 16 f(x + 3h) - 3 f(x + 4h)) / (12 h):
// one-sided, fourth order.
template <class F>
StencilValue<F> one_sided_derivative4(const F& f, double x, double h) {
  return StencilValue<F>(
      (-25.0 * f(x) + 48.0 * f(x + h) - 36.0 * f(x + 2.0 * h) + 16.0 * f(x + 3.0 * h) - 3.0 * f(x + 4.0 * h)) /
      (12.0 * h));
}

// f''(x) ~ (-f(x + 2h) + 16 f(x + h) - 30 f(x) + 16 f(x - h) - f(x - 2h)) / (12 h^2): fourth order.
template <class F>
StencilValue<F> central_second_derivative4(const F& f, double x, double h) {
  return StencilValue<F>((-f(x + 2 * h) + 16.0 * f(x + h) - 30.0 * f(x) + 16.0 * f(x - h) - f(x - 2 * h)) /
                         (12.0 * h * h));
}

// f''(x) ~ (2 f(x) - 5 f(x + h) + 4 f(x + 2h) - f(x + 3h)) / h^2: one-sided,
// second order.
template <class F>
StencilValue<F> one_sided_second_derivative(const F& f, double x, double h) {
  return StencilValue<F>((2.0 * f(x) - 5.0 * f(x + h) + 4.0 * f(x + 2 * h) - f(x + 3 * h)) / (h * h));
}

}  // namespace pita
