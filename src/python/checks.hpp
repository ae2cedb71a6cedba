// The checks the Python module makes of what a user passes, as plain C++ (no
// Python, no pybind11): the module calls them, and so does the fuzz target
// fuzz/fuzz_python_entry.cpp. Each throws std::invalid_argument, which
// pybind11 raises as ValueError, with a message that names the argument.
#pragma once

#include <cmath>
#include <complex>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/arrow.hpp"
#include "scene/limits.hpp"

namespace pita::python {

// Elements of the times (or of the broadcast of matrices and times) one call
// of the module evaluates: `pita eval`'s work limit (scene::kMaxEvalWork, 1e8
// frames of a plain method), checked from the shapes before any array is
// copied, converted or broadcast.
inline constexpr double kMaxElements = scene::kMaxEvalWork;

// A double as Python's repr() writes it ("-1.0", "1e+300", "nan").
inline std::string python_repr(double x) {
  std::string text = fmt::format("{}", x);
  if (text.find_first_of(".eni") == std::string::npos) text += ".0";
  return text;
}

// The product of a shape, as a double (never overflows); throws for a
// negative extent.
inline double shape_size(const std::vector<std::int64_t>& shape, const std::string& name) {
  double size = 1.0;
  for (const std::int64_t extent : shape) {
    if (extent < 0) throw std::invalid_argument(fmt::format("{}: a shape with a negative extent", name));
    size *= static_cast<double>(extent);
  }
  return size;
}

// The shape as NumPy writes it: "(200000000,)", "(3, 4)", "()".
inline std::string shape_text(const std::vector<std::int64_t>& shape) {
  if (shape.size() == 1) return fmt::format("({},)", shape.front());
  std::string text = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) text += (i ? ", " : "") + std::to_string(shape[i]);
  return text + ")";
}

// Refuses an array of more than `limit` elements (kMaxElements by default),
// from its shape alone.
inline void check_elements(const std::vector<std::int64_t>& shape, const std::string& name,
                           double limit = kMaxElements) {
  const double size = shape_size(shape, name);
  if (size > limit) {
    throw std::invalid_argument(
        fmt::format("{}: {:.0f} elements (shape {}), above the limit of {:.0e} a call; "
                    "evaluate in smaller pieces",
                    name, size, shape_text(shape), limit));
  }
}

// NumPy's broadcast of two shapes (np.broadcast_shapes), computed without
// arrays; throws when they do not broadcast.
inline std::vector<std::int64_t> broadcast_shape(const std::vector<std::int64_t>& a, const std::vector<std::int64_t>& b,
                                                 const std::string& names) {
  const std::size_t n = std::max(a.size(), b.size());
  std::vector<std::int64_t> out(n, 1);
  for (std::size_t i = 0; i < n; ++i) {
    const std::int64_t x = i < n - a.size() ? 1 : a[i - (n - a.size())];
    const std::int64_t y = i < n - b.size() ? 1 : b[i - (n - b.size())];
    if (x < 0 || y < 0) throw std::invalid_argument(fmt::format("{}: a shape with a negative extent", names));
    if (x != y && x != 1 && y != 1) {
      throw std::invalid_argument(
          fmt::format("{}: shapes {} and {} do not broadcast", names, shape_text(a), shape_text(b)));
    }
    out[i] = x == 1 ? y : x;
  }
  return out;
}

// The shape of a matrix a pose or an affinity is read from: 2x3 or 3x3
// (plane), 3x4 or 4x4 (space); `linear`: the linear part L alone (2x2, 3x3).
// Checked before its entries are read.
inline void check_pose_shape(std::int64_t rows, std::int64_t cols, const std::string& name, bool linear = false) {
  const bool good = linear ? (rows == cols && (rows == 2 || rows == 3))
                           : ((cols == 3 || cols == 4) && (rows == cols || rows == cols - 1));
  if (!good) {
    throw std::invalid_argument(
        linear ? fmt::format("{}: L must be 2x2 or 3x3 (got {}x{})", name, rows, cols)
               : fmt::format("{}: a pose is a 2x3 or 3x3 matrix (plane) or a 3x4 or 4x4 matrix (space); got {}x{}",
                             name, rows, cols));
  }
}

// An arrow pita can compute with, as a scene's keyframe must be (finite, m >
// 0, |w| within scene::kMaxWinding, whose turns are then exact): from the
// constructor and from a pickle alike.
inline Arrow checked_arrow(Point p, double m, double w) {
  if (!std::isfinite(p.real()) || !std::isfinite(p.imag())) throw std::invalid_argument("p: must be finite");
  if (!std::isfinite(m) || !(m > 0.0)) {
    throw std::invalid_argument(fmt::format("m: magnitude must be > 0 (got {})", python_repr(m)));
  }
  if (!std::isfinite(w) || std::abs(w) > scene::kMaxWinding) {
    throw std::invalid_argument(
        fmt::format("w: the winding must be within +-{:g} rad (got {}); beyond, w + 2 pi k "
                    "loses the angle's precision",
                    scene::kMaxWinding, python_repr(w)));
  }
  return Arrow{p, m, w};
}

}  // namespace pita::python
