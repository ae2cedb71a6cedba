// pita.sma, pita.ear_power, pita.sam and pita.has_sam: the steady morph of two
// arrows and the real powers of affinities (EAR), vectorised over NumPy
// arrays, computed by core/ with the GIL released.
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/affine_power.hpp"
#include "core/affine_power_of_space.hpp"
#include "core/overloaded.hpp"
#include "core/steady_affine_morph.hpp"
#include "core/steady_morph.hpp"
#include "python/bindings.hpp"
#include "python/checks.hpp"
#include "python/chunks.hpp"

namespace pita::python {

namespace {

// A stack of matrices (..., rows, cols) as NumPy gives it, read once.
struct MatrixStack {
  std::vector<double> values;      // C order
  std::vector<py::ssize_t> batch;  // the shape before the last two axes
  py::ssize_t rows = 0, cols = 0;
  int dimension = 2;         // of the affinities
  bool homogeneous = false;  // (n+1) x (n+1), else n x (n+1)
  std::size_t count() const { return values.size() / static_cast<std::size_t>(rows * cols); }
};

MatrixStack read_stack(const py::handle& value, const char* name) {
  MatrixStack stack;
  py::object raw = py::module_::import("numpy").attr("asarray")(value);
  if (py::hasattr(value, "matrix") && !py::isinstance<py::array>(value)) {  // a pita.Pose
    raw = pose_matrix(read_pose(value, name));
  }
  const py::array array = raw;
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    throw py::type_error(fmt::format("{}: expected an array of real numbers, got dtype {}", name,
                                     py::str(array.dtype()).cast<std::string>()));
  }
  if (array.ndim() < 2) throw py::value_error(fmt::format("{}: expected a matrix or an array of matrices", name));
  stack.rows = array.shape(array.ndim() - 2);
  stack.cols = array.shape(array.ndim() - 1);
  stack.dimension = static_cast<int>(stack.cols) - 1;
  stack.homogeneous = stack.rows == stack.cols;
  if ((stack.dimension != 2 && stack.dimension != 3) || !(stack.homogeneous || stack.rows == stack.cols - 1)) {
    throw py::value_error(
        fmt::format("{}: an affinity is a 2x3 or 3x3 matrix (plane) or a 3x4 or 4x4 matrix "
                    "(space); got {}x{}",
                    name, stack.rows, stack.cols));
  }
  for (py::ssize_t d = 0; d + 2 < array.ndim(); ++d) stack.batch.push_back(array.shape(d));
  // The count from the shape, before the matrices are converted or copied.
  check_elements({stack.batch.begin(), stack.batch.end()}, name);
  const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  stack.values.assign(values.data(), values.data() + values.size());
  return stack;
}

template <class Affine>
Affine affinity_at(const MatrixStack& stack, std::size_t k) {
  const double* M = stack.values.data() + k * static_cast<std::size_t>(stack.rows * stack.cols);
  const int n = stack.dimension;
  Affine A;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) A.L(i, j) = M[i * stack.cols + j];
    A.b(i) = M[i * stack.cols + n];
  }
  return A;
}

template <class Affine>
void store(const Affine& A, const MatrixStack& stack, double* out) {
  const int n = stack.dimension;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) out[i * stack.cols + j] = A.L(i, j);
    out[i * stack.cols + n] = A.b(i);
  }
  if (stack.homogeneous) {
    for (int j = 0; j <= n; ++j) out[n * stack.cols + j] = j == n ? 1.0 : 0.0;
  }
}

// Whether a homogeneous stack's last rows are [0, ..., 0, 1].
void check_homogeneous(const MatrixStack& stack, const char* name) {
  if (!stack.homogeneous) return;
  const auto n = static_cast<std::size_t>(stack.dimension);
  const auto size = static_cast<std::size_t>(stack.rows * stack.cols);
  for (std::size_t k = 0; k < stack.count(); ++k) {
    for (std::size_t j = 0; j <= n; ++j) {
      if (stack.values[k * size + n * (n + 1) + j] != (j == n ? 1.0 : 0.0)) {
        throw py::value_error(
            fmt::format("{}: the last row of a homogeneous matrix must be [0, ..., 0, 1] "
                        "(matrix {})",
                        name, k));
      }
    }
  }
}

template <class Affine>
py::array ear_powers(const MatrixStack& stack, const Times& times, const std::vector<py::ssize_t>& shape) {
  // The broadcast of the stack's batch and the times' shape, element by element.
  const py::module_ np = py::module_::import("numpy");
  const py::tuple batch = py::cast(stack.batch), tshape = py::cast(times.shape);
  const std::vector<py::ssize_t> out_batch =
      np.attr("broadcast_shapes")(batch, tshape).cast<std::vector<py::ssize_t>>();
  // Index maps: which matrix and which time each output element uses.
  const py::array_t<std::int64_t> matrix_index = np.attr("ascontiguousarray")(
      np.attr("broadcast_to")(np.attr("arange")(stack.count()).attr("reshape")(batch), py::cast(out_batch))
          .attr("ravel")(),
      "int64");
  const py::array_t<std::int64_t> time_index = np.attr("ascontiguousarray")(
      np.attr("broadcast_to")(np.attr("arange")(times.values.size()).attr("reshape")(tshape), py::cast(out_batch))
          .attr("ravel")(),
      "int64");
  py::array_t<double> out = new_array(out_batch, {stack.rows, stack.cols});
  (void)shape;
  const std::int64_t* mi = matrix_index.data();
  const std::int64_t* ti = time_index.data();
  double* result = out.mutable_data();
  const auto size = static_cast<std::size_t>(stack.rows * stack.cols);
  const std::size_t n = static_cast<std::size_t>(matrix_index.size());
  // EAR's case selection and log once per matrix: consecutive elements of one
  // matrix (a single matrix at many times) share them.
  std::optional<AffinePowers<Affine>> powers;
  std::int64_t built = -1;
  std::optional<std::string> failure;
  std::size_t failed = 0;
  for_each_chunk(n, [&](std::size_t begin, std::size_t end) {
    for (std::size_t e = begin; e < end; ++e) {
      if (mi[e] != built) {
        try {
          powers.emplace(affinity_at<Affine>(stack, static_cast<std::size_t>(mi[e])));
        } catch (const NoRealLogarithm& error) {
          failure = error.what();
          failed = static_cast<std::size_t>(mi[e]);
          return false;
        }
        built = mi[e];
      }
      store(powers->at(times.values[static_cast<std::size_t>(ti[e])]), stack, result + e * size);
    }
    return true;
  });
  if (failure) raise_no_sam(*failure, stack.batch.empty() ? std::nullopt : std::make_optional(failed));
  return out;
}

// One matrix given as a list or tuple of rows of Python numbers, a
// 2-dimensional array of real numbers or a pita.Pose, read without NumPy's
// asarray and index maps: the call for a single matrix (a loop of Python
// calls) costs the dispatch and the math. nullopt when the value is anything
// else (an array of matrices, another dtype, a ragged or too large list, a
// bool, a value that is not finite, a homogeneous last row other than
// [0, ..., 0, 1]): the general path then reads it and gives its errors.
std::optional<MatrixStack> read_single(const py::handle& value) {
  constexpr py::ssize_t kMaxSide = 4;
  std::array<double, kMaxSide * kMaxSide> entries{};
  py::ssize_t rows = 0, cols = 0;
  PyObject* object = value.ptr();
  if (PyList_Check(object) || PyTuple_Check(object)) {
    rows = PySequence_Fast_GET_SIZE(object);
    if (rows < 2 || rows > kMaxSide) return std::nullopt;
    PyObject** items = PySequence_Fast_ITEMS(object);
    for (py::ssize_t i = 0; i < rows; ++i) {
      PyObject* row = items[i];
      if (!PyList_Check(row) && !PyTuple_Check(row)) return std::nullopt;
      const py::ssize_t n = PySequence_Fast_GET_SIZE(row);
      if (i == 0) cols = n;
      if (n != cols || n < 3 || n > kMaxSide) return std::nullopt;
      PyObject** xs = PySequence_Fast_ITEMS(row);
      for (py::ssize_t j = 0; j < n; ++j) {
        double& x = entries[static_cast<std::size_t>(i * cols + j)];
        if (PyFloat_Check(xs[j])) {
          x = PyFloat_AS_DOUBLE(xs[j]);
        } else if (PyLong_CheckExact(xs[j])) {  // not a bool: NumPy refuses an array of them
          int overflow = 0;
          const long long k = PyLong_AsLongLongAndOverflow(xs[j], &overflow);
          if (overflow != 0 || (k == -1 && PyErr_Occurred() != nullptr)) {
            PyErr_Clear();
            return std::nullopt;
          }
          x = static_cast<double>(k);  // as NumPy converts an int64 array to float64
        } else {
          return std::nullopt;
        }
      }
    }
  } else if (py::isinstance<py::array>(value)) {
    const auto given = py::reinterpret_borrow<py::array>(value);
    const char kind = given.dtype().kind();
    if (given.ndim() != 2 || (kind != 'f' && kind != 'i' && kind != 'u')) return std::nullopt;
    rows = given.shape(0), cols = given.shape(1);
    if (rows < 2 || rows > kMaxSide || cols < 3 || cols > kMaxSide) return std::nullopt;
    // float64 as it is; another dtype converted as read_stack converts it
    const auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(given);
    if (!array) return std::nullopt;
    std::copy(array.data(), array.data() + rows * cols, entries.begin());
  } else if (is_pose(value)) {  // [L | b], as read_stack reads a pose
    const Pose pose = read_pose(value, "M");
    std::visit(
        [&](const auto& A) {
          rows = A.b.size(), cols = rows + 1;
          write_pose(A, entries.data());
        },
        pose);
  } else {
    return std::nullopt;
  }
  MatrixStack stack;
  stack.rows = rows, stack.cols = cols;
  stack.dimension = static_cast<int>(cols) - 1;
  stack.homogeneous = rows == cols;
  if (!(stack.homogeneous || rows == cols - 1)) return std::nullopt;
  stack.values.assign(entries.begin(), entries.begin() + rows * cols);
  for (const double x : stack.values) {
    if (!std::isfinite(x)) return std::nullopt;
  }
  if (stack.homogeneous) {
    const auto n = static_cast<std::size_t>(stack.dimension);
    for (std::size_t j = 0; j <= n; ++j) {
      if (stack.values[n * (n + 1) + j] != (j == n ? 1.0 : 0.0)) return std::nullopt;
    }
  }
  return stack;
}

// M^t of one matrix at one time: what ear_powers computes for it (the same
// AffinePowers, at the same t), without the index maps and the GIL's release.
template <class Affine>
py::array ear_power_of_one(const MatrixStack& stack, double t) {
  py::array_t<double> out({stack.rows, stack.cols});
  try {
    store(AffinePowers<Affine>(affinity_at<Affine>(stack, 0)).at(t), stack, out.mutable_data());
  } catch (const NoRealLogarithm& error) {
    raise_no_sam(error.what(), std::nullopt);
  }
  return out;
}

py::object ear_power(const py::handle& M, const py::handle& t) {
  // The small case first: one matrix, one time given as a Python number.
  if ((PyFloat_Check(t.ptr()) || (PyLong_Check(t.ptr()) && !PyBool_Check(t.ptr())))) {
    if (const std::optional<MatrixStack> one = read_single(M)) {
      const Times time = read_times(t, "t");
      return one->dimension == 2 ? ear_power_of_one<Affine2>(*one, time.values.front())
                                 : ear_power_of_one<Affine3>(*one, time.values.front());
    }
  }
  // The broadcast of the matrices and the times, from their shapes alone,
  // before either is converted or copied.
  if (!is_pose(M)) {
    const std::vector<std::int64_t> m_shape = array_shape(M), t_shape = array_shape(t);
    if (m_shape.size() >= 2) {
      const std::vector<std::int64_t> batch(m_shape.begin(), m_shape.end() - 2);
      check_elements(broadcast_shape(batch, t_shape, "M and t"), "M and t");
    }
  }
  const MatrixStack stack = read_stack(M, "M");
  check_homogeneous(stack, "M");
  const Times times = read_times(t, "t");
  for (const double x : stack.values) {
    if (!std::isfinite(x)) throw py::value_error("M: every entry must be finite");
  }
  return stack.dimension == 2 ? ear_powers<Affine2>(stack, times, {}) : ear_powers<Affine3>(stack, times, {});
}

py::object sma(const py::handle& a, const py::handle& b, const py::handle& t) {
  const Arrow A = read_arrow(a, "A"), B = read_arrow(b, "B");
  const Times times = read_times(t, "t");
  if (times.scalar) return arrow_object(steady_morph(A, B, times.values.front()));
  const std::size_t n = times.values.size();
  py::array_t<double> p = new_array(times.shape, {2}), m = new_array(times.shape, {}), w = new_array(times.shape, {}),
                      q = new_array(times.shape, {2});
  double *pp = p.mutable_data(), *pm = m.mutable_data(), *pw = w.mutable_data(), *pq = q.mutable_data();
  for_each_chunk(n, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const Arrow D = steady_morph(A, B, times.values[i]);
      const Point e = D.q();
      pp[2 * i] = D.p.real(), pp[2 * i + 1] = D.p.imag(), pm[i] = D.m, pw[i] = D.w;
      pq[2 * i] = e.real(), pq[2 * i + 1] = e.imag();
    }
    return true;
  });
  return arrow_samples_type()(p, m, w, q);
}

py::object sam(const py::handle& a, const py::handle& b, const py::handle& t) {
  const Pose A = read_pose(a, "A"), B = read_pose(b, "B");
  if (A.index() != B.index()) throw py::value_error("A and B: a pose of the plane and one of space have no SAM");
  const Times times = read_times(t, "t");
  return std::visit(
      [&](const auto& from) -> py::object {
        using Affine = std::decay_t<decltype(from)>;
        const Affine& to = std::get<Affine>(B);
        std::optional<SteadyAffineMorph<Affine>> morph;
        try {
          morph.emplace(from, to);
        } catch (const NoRealLogarithm& error) {
          raise_no_sam(error.what(), std::nullopt);
        }
        const py::ssize_t n = from.b.size();
        py::array_t<double> out = new_array(times.shape, {n, n + 1});
        double* result = out.mutable_data();
        const auto size = static_cast<std::size_t>(n * (n + 1));
        for_each_chunk(times.values.size(), [&](std::size_t begin, std::size_t end) {
          for (std::size_t i = begin; i < end; ++i) write_pose(morph->at(times.values[i]), result + i * size);
          return true;
        });
        return out;
      },
      A);
}

// What pita.has_sam answers.
struct SamExistence {
  bool exists = false;
  std::string root_case;  // "G1", "G2", "S1", "S2", "G3" (plane); "" for space
  std::string reason;     // "" when it exists
};

SamExistence existence(const Pose& M) {
  SamExistence answer;
  // The root case of Algorithm 1 is named in the plane only.
  std::visit(overloaded{[&](const Affine2& A) {
                          try {
                            const AffinePowers powers(A);
                            answer.root_case = std::string(name(powers.root_case()));
                            answer.exists = true;
                          } catch (const NoRealLogarithm& error) {
                            answer.root_case = std::string(name(error.root_case()));
                            answer.reason = error.what();
                          }
                        },
                        [&](const Affine3& A) {
                          try {
                            const AffinePowers powers(A);
                            answer.exists = true;
                          } catch (const NoRealLogarithm& error) {
                            answer.reason = error.what();
                          }
                        }},
             M);
  return answer;
}

}  // namespace

void bind_affine(py::module_& m) {
  m.def("sma", &sma, py::arg("A"), py::arg("B"), py::arg("t"),
        R"(The steady morph M(A, B, t) between two arrows (PITA Eq. 20): M(A, B, 0) = A,
M(A, B, 1) = B, and every frame is the one before it moved by the same similarity (a
log-spiral motion); windings included, so an extra turn of B is an extra turn of the motion.
t outside [0, 1] extrapolates.

A and B are pita.Arrow (or {"p", "m", "w"} dicts, or (p, m, w) tuples). For a number t it
returns a pita.Arrow; for an array of times, ArrowSamples(p, m, w, q) of arrays shaped like t.)");
  m.def("ear_power", &ear_power, py::arg("M"), py::arg("t"),
        R"(The real power M^t of affinities by EAR, the closed form of the SAM paper's appendix A
(A.1-A.5, Algorithm 1 in the plane; A.6 in space): M^t = e^{t log M}, with M^0 the identity and
M^1 = M.

M is [L | b] (2x3 or 3x4) or homogeneous (3x3 or 4x4), or an array of them (..., 2, 3);
t a number or an array. Their shapes broadcast as NumPy's do (M's shape before its last two
axes with t's), and the result has M's form. Raises pita.NoSamError when L has no real
logarithm (two negative eigenvalues: case G3), with .index for an array: the flat index of the
first such matrix (np.unravel_index(e.index, M.shape[:-2]) for a stack of several axes).)");
  m.def("sam", &sam, py::arg("A"), py::arg("B"), py::arg("t"),
        R"(The Steady Affine Morph from pose A (t = 0) to pose B (t = 1) (SAM paper Sec. 2.2):
S(t) = (B A^-1)^t A, every vertex moving with a constant velocity field in the moving frame.

A and B are pita.Pose or matrices ([L | b] or homogeneous), both of the plane or both of
space. Returns [L | b] matrices of shape t.shape + (2, 3) (plane) or + (3, 4) (space).
Raises pita.NoSamError when B A^-1 has no real power.)");

  py::class_<SamExistence>(m, "SamExistence", "Whether an affinity has real powers (a SAM), and why not.")
      .def_readonly("exists", &SamExistence::exists)
      .def_readonly("case", &SamExistence::root_case,
                    "Appendix A.5's case in the plane: G1, G2, S1, S2, or G3 (none); \"\" in space.")
      .def_readonly("reason", &SamExistence::reason, "Why there is none, with the eigenvalues; \"\" when it exists.")
      .def("__bool__", [](const SamExistence& e) { return e.exists; })
      .def("__repr__", [](const SamExistence& e) {
        return fmt::format("SamExistence(exists={}, case={}, reason={})", e.exists ? "True" : "False",
                           py::repr(py::str(e.root_case)).cast<std::string>(),
                           py::repr(py::str(e.reason)).cast<std::string>());
      });
  refuse_uninitialised<SamExistence>();
  m.def(
      "has_sam",
      [](const py::handle& a, const py::object& b) {
        const Pose A = read_pose(a, b.is_none() ? "M" : "A");
        if (b.is_none()) return existence(A);
        const Pose B = read_pose(b, "B");
        if (A.index() != B.index()) throw py::value_error("A and B: a pose of the plane and one of space have no SAM");
        return std::visit(
            [&](const auto& from) {
              using Affine = std::decay_t<decltype(from)>;
              if (from.L.determinant() == 0.0) throw py::value_error("A: the pose is singular (det L = 0)");
              return existence(Pose{compose(std::get<Affine>(B), inverse(from))});
            },
            A);
      },
      py::arg("M"), py::arg("B") = py::none(),
      R"(Whether the affinity M has real powers, so that a SAM by M exists (SAM paper Sec. 5.1,
appendix A.5): truthy when it does; .case is the case of Algorithm 1 in the plane and .reason
says why there is none. has_sam(A, B) asks it of the SAM from pose A to pose B (M = B A^-1).)");
}

}  // namespace pita::python
