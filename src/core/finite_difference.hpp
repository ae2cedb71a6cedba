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
#include <vector>

namespace pita {

// weights[m][j]: the weight of f(nodes[j]) in the m-th derivative at x0, for
// m = 0 .. max_order. The nodes must be distinct.
std::vector<std::vector<double>> fornberg_weights(double x0, const std::vector<double>& nodes,
                                                  int max_order);

}  // namespace pita
