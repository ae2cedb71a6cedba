// pita.Arrow and pita.Pose: plain, immutable value types that compare, hash,
// print and pickle as Python values do; and the conversions every part of the
// module shares (times, arrows and poses from what NumPy users pass).
#include <cmath>
#include <functional>
#include <string>

#include <fmt/format.h>
#include <pybind11/operators.h>

#include "core/affine2.hpp"
#include "core/affine3.hpp"
#include "core/arrow.hpp"
#include "core/overloaded.hpp"
#include "core/pose_traits.hpp"
#include "python/bindings.hpp"
#include "python/checks.hpp"
#include "scene/limits.hpp"

namespace pita::python {

namespace {

// collections.namedtuple("ArrowSamples", "p m w q"), made by bind_values and
// never freed (a py::object destroyed after the interpreter would crash).
py::handle g_arrow_samples;

// repr() of a float as Python writes it (shortest round trip).
std::string float_repr(double x) { return py::repr(py::float_(x)).cast<std::string>(); }

std::string arrow_repr(const Arrow& a) {
  return fmt::format("Arrow(p=({}, {}), m={}, w={})", float_repr(a.p.real()), float_repr(a.p.imag()), float_repr(a.m),
                     float_repr(a.w));
}

template <class Matrix>
std::string rows_repr(const Matrix& M) {
  std::string out = "[";
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    out += i ? ", [" : "[";
    for (Eigen::Index j = 0; j < M.cols(); ++j) out += (j ? ", " : "") + float_repr(M(i, j));
    out += "]";
  }
  return out + "]";
}

std::string pose_repr(const Pose& pose) {
  return std::visit(
      [](const auto& A) {
        std::string b = "[";
        for (Eigen::Index i = 0; i < A.b.size(); ++i) b += (i ? ", " : "") + float_repr(A.b(i));
        return fmt::format("Pose(L={}, b={}])", rows_repr(A.L), b);
      },
      pose);
}

// A finite real number, or TypeError / ValueError naming `name`.
double real(const py::handle& value, const std::string& name) {
  if (PyBool_Check(value.ptr()) || !(PyFloat_Check(value.ptr()) || PyLong_Check(value.ptr()) ||
                                     py::isinstance(value, py::module_::import("numbers").attr("Real")))) {
    throw py::type_error(fmt::format("{}: expected a real number, got {}", name, py::repr(value).cast<std::string>()));
  }
  double x = 0.0;
  if (PyLong_Check(value.ptr())) {
    // An int beyond a double (10**400): a ValueError naming the argument,
    // not pybind11's cast error.
    x = PyLong_AsDouble(value.ptr());
    if (x == -1.0 && PyErr_Occurred() != nullptr) {
      PyErr_Clear();
      throw py::value_error(fmt::format("{}: an integer of {} bits, beyond the range of a double (about 1.8e308)", name,
                                        value.attr("bit_length")().cast<long long>()));
    }
  } else {
    x = value.cast<double>();
  }
  if (!std::isfinite(x)) throw py::value_error(fmt::format("{}: must be finite (got {})", name, float_repr(x)));
  return x;
}

// A point: a sequence of two real numbers, or a complex number.
Point point(const py::handle& value, const std::string& name) {
  if (PyComplex_Check(value.ptr())) {
    const std::complex<double> z = value.cast<std::complex<double>>();
    if (!std::isfinite(z.real()) || !std::isfinite(z.imag())) {
      throw py::value_error(fmt::format("{}: must be finite", name));
    }
    return z;
  }
  if (!py::isinstance<py::sequence>(value) && !py::hasattr(value, "__array__")) {
    throw py::type_error(fmt::format("{}: expected a point [x, y], got {}", name, py::repr(value).cast<std::string>()));
  }
  const py::array_t<double, py::array::c_style | py::array::forcecast> xy =
      py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!xy || xy.ndim() != 1 || xy.shape(0) != 2) {
    throw py::value_error(
        fmt::format("{}: expected a point [x, y] of two numbers, got {}", name, py::repr(value).cast<std::string>()));
  }
  const Point p{xy.at(0), xy.at(1)};
  if (!std::isfinite(p.real()) || !std::isfinite(p.imag())) {
    throw py::value_error(fmt::format("{}: must be finite", name));
  }
  return p;
}

Arrow make_arrow(const py::handle& p, const py::handle& m, const py::handle& w) {
  return checked_arrow(point(p, "p"), real(m, "m"), real(w, "w"));
}

// A matrix of doubles, checked: `rows` x `cols`.
Eigen::MatrixXd matrix(const py::handle& value, const std::string& name) {
  // The shape first (np.shape reads it without converting an array): a
  // matrix of a pose is at most 4x4, refused before anything is copied.
  const std::vector<std::int64_t> shape = array_shape(value);
  if (shape.size() != 2) {
    throw py::value_error(fmt::format("{}: expected a matrix (a 2-dimensional array of numbers)", name));
  }
  if (shape[0] > 4 || shape[1] > 4) {
    throw py::value_error(fmt::format("{}: a matrix of a pose is at most 4x4 (got {}x{})", name, shape[0], shape[1]));
  }
  const auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!array || array.ndim() != 2) {
    throw py::value_error(fmt::format("{}: expected a matrix (a 2-dimensional array of numbers)", name));
  }
  Eigen::MatrixXd M(array.shape(0), array.shape(1));
  for (py::ssize_t i = 0; i < array.shape(0); ++i) {
    for (py::ssize_t j = 0; j < array.shape(1); ++j) M(i, j) = array.at(i, j);
  }
  if (!M.allFinite()) throw py::value_error(fmt::format("{}: every entry must be finite", name));
  return M;
}

Pose pose_from_parts(const Eigen::MatrixXd& L, const Eigen::VectorXd& b, const std::string& name) {
  if (L.rows() == 2 && L.cols() == 2 && b.size() == 2) {
    Affine2 A;
    A.L = L;
    A.b = b;
    return A;
  }
  if (L.rows() == 3 && L.cols() == 3 && b.size() == 3) {
    Affine3 A;
    A.L = L;
    A.b = b;
    return A;
  }
  throw py::value_error(fmt::format("{}: L must be 2x2 with b of 2 numbers, or 3x3 with b of 3 (got {}x{} and {})",
                                    name, L.rows(), L.cols(), b.size()));
}

Pose pose_from_matrix(const py::handle& value, const std::string& name) {
  const Eigen::MatrixXd M = matrix(value, name);
  const Eigen::Index n = M.cols() - 1;  // the dimension
  check_pose_shape(M.rows(), M.cols(), name);
  const bool homogeneous = M.rows() == n + 1;
  if (homogeneous) {
    Eigen::VectorXd last = Eigen::VectorXd::Zero(n + 1);
    last(n) = 1.0;
    if (M.row(n).transpose() != last) {
      throw py::value_error(fmt::format("{}: the last row of a homogeneous matrix must be [0, ..., 0, 1]", name));
    }
  }
  return pose_from_parts(M.topLeftCorner(n, n), M.block(0, n, n, 1), name);
}

// The class pita.Pose holds.
struct PoseValue {
  Pose pose;
};

py::array_t<double> linear_part(const Pose& pose) {
  return std::visit(
      [](const auto& A) {
        const py::ssize_t n = A.b.size();
        py::array_t<double> L({n, n});
        for (py::ssize_t i = 0; i < n; ++i) {
          for (py::ssize_t j = 0; j < n; ++j) L.mutable_at(i, j) = A.L(i, j);
        }
        return L;
      },
      pose);
}

py::array_t<double> translation(const Pose& pose) {
  return std::visit(
      [](const auto& A) {
        const py::ssize_t n = A.b.size();
        py::array_t<double> b(n);
        for (py::ssize_t i = 0; i < n; ++i) b.mutable_at(i) = A.b(i);
        return b;
      },
      pose);
}

py::array_t<double> homogeneous(const Pose& pose) {
  return std::visit(
      [](const auto& A) {
        const py::ssize_t n = A.b.size();
        py::array_t<double> H({n + 1, n + 1});
        double* out = H.mutable_data();
        write_pose(A, out);  // the first n rows, n + 1 wide: [L | b]
        for (py::ssize_t j = 0; j <= n; ++j) out[n * (n + 1) + j] = j == n ? 1.0 : 0.0;
        return H;
      },
      pose);
}

}  // namespace

py::object arrow_samples_type() { return py::reinterpret_borrow<py::object>(g_arrow_samples); }

py::array_t<double> new_array(const std::vector<py::ssize_t>& shape, std::initializer_list<py::ssize_t> tail) {
  std::vector<py::ssize_t> full = shape;
  full.insert(full.end(), tail.begin(), tail.end());
  return py::array_t<double>(full);
}

std::vector<std::int64_t> array_shape(const py::handle& value) {
  if (py::isinstance<py::array>(value)) {
    const auto array = py::reinterpret_borrow<py::array>(value);
    return {array.shape(), array.shape() + array.ndim()};
  }
  try {
    return py::module_::import("numpy").attr("shape")(value).cast<std::vector<std::int64_t>>();
  } catch (const py::error_already_set&) {
    return {};  // a ragged list: what reads it next refuses it in its own words
  }
}

Times read_times(const py::handle& t, const char* name, const std::function<void(std::size_t)>& check) {
  Times times;
  if (PyFloat_Check(t.ptr()) || (PyLong_Check(t.ptr()) && !PyBool_Check(t.ptr()))) {
    times.scalar = true;
    times.values.push_back(real(t, name));
    return times;
  }
  const py::array raw = py::module_::import("numpy").attr("asarray")(t);
  const char kind = raw.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    throw py::type_error(
        fmt::format("{}: expected real numbers (a float, an int or an array of them), got an array "
                    "of dtype {}",
                    name, py::str(raw.dtype()).cast<std::string>()));
  }
  // The count from the shape, before anything is converted or copied (a
  // broadcast view of 2e8 times holds one number).
  const std::vector<std::int64_t> shape(raw.shape(), raw.shape() + raw.ndim());
  check_elements(shape, name);
  if (check) check(static_cast<std::size_t>(shape_size(shape, name)));
  const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(raw);
  times.scalar = values.ndim() == 0;
  for (py::ssize_t d = 0; d < values.ndim(); ++d) times.shape.push_back(values.shape(d));
  const double* data = values.data();
  times.values.assign(data, data + values.size());
  for (std::size_t i = 0; i < times.values.size(); ++i) {
    if (!std::isfinite(times.values[i])) {
      throw py::value_error(
          fmt::format("{}: every time must be finite (item {} is {})", name, i, float_repr(times.values[i])));
    }
  }
  return times;
}

Arrow read_arrow(const py::handle& value, const char* name) {
  if (py::isinstance<Arrow>(value)) return value.cast<Arrow>();
  if (py::isinstance<py::dict>(value)) {
    const py::dict d = py::reinterpret_borrow<py::dict>(value);
    if (d.contains("p") && d.contains("q") && !d.contains("m")) {
      const Point p = point(d["p"], std::string(name) + ".p"), q = point(d["q"], std::string(name) + ".q");
      if (p == q) throw py::value_error(fmt::format("{}.q: must differ from p (an arrow has a magnitude > 0)", name));
      return zero_turn_arrow(p, q);
    }
    if (d.contains("p") && d.contains("m") && d.contains("w")) return make_arrow(d["p"], d["m"], d["w"]);
  }
  if (py::isinstance<py::tuple>(value) && py::len(value) == 3) {
    const py::tuple t = py::reinterpret_borrow<py::tuple>(value);
    return make_arrow(t[0], t[1], t[2]);
  }
  throw py::type_error(
      fmt::format("{}: expected a pita.Arrow, a dict {{\"p\", \"m\", \"w\"}} or {{\"p\", \"q\"}}, "
                  "or a tuple (p, m, w); got {}",
                  name, py::repr(value).cast<std::string>()));
}

Pose read_pose(const py::handle& value, const char* name) {
  if (py::isinstance<PoseValue>(value)) return value.cast<const PoseValue&>().pose;
  return pose_from_matrix(value, name);
}

bool is_pose(const py::handle& value) { return py::isinstance<PoseValue>(value); }

void write_pose(const Affine2& A, double* out) {
  for (int i = 0; i < 2; ++i) {
    out[3 * i] = A.L(i, 0);
    out[3 * i + 1] = A.L(i, 1);
    out[3 * i + 2] = A.b(i);
  }
}

void write_pose(const Affine3& A, double* out) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out[4 * i + j] = A.L(i, j);
    out[4 * i + 3] = A.b(i);
  }
}

py::array_t<double> pose_matrix(const Pose& pose) {
  return std::visit(
      [](const auto& A) {
        const py::ssize_t n = A.b.size();
        py::array_t<double> out({n, n + 1});
        write_pose(A, out.mutable_data());
        return out;
      },
      pose);
}

py::object arrow_object(const Arrow& arrow) { return py::cast(arrow); }
py::object pose_object(const Pose& pose) { return py::cast(PoseValue{pose}); }

void bind_values(py::module_& m) {
  py::object samples = py::module_::import("collections").attr("namedtuple")("ArrowSamples", "p m w q");
  samples.attr("__module__") = "pita";
  samples.attr("__doc__") =
      "Arrows at many times, as NumPy arrays: p and q of shape (..., 2), m and w of shape (...), "
      "where (...) is the shape of the times.";
  m.attr("ArrowSamples") = samples;
  g_arrow_samples = samples.release();

  py::class_<Arrow>(m, "Arrow", R"(An arrow A(p, m, w) (PITA paper Sec. 2.1): it starts at p, has magnitude m > 0
and winding w, a real angle in radians that is never reduced: w = 0.3 and w = 0.3 + 2 pi
are the same segment but different arrows (the second carries one more turn).

    >>> pita.Arrow((0, 0), 1.0, 0.4)
    Arrow(p=(0.0, 0.0), m=1.0, w=0.4)
)")
      .def(py::init([](const py::handle& p, const py::handle& magnitude, const py::handle& w) {
             return make_arrow(p, magnitude, w);
           }),
           py::arg("p"), py::arg("m"), py::arg("w"))
      .def_static(
          "from_points",
          [](const py::handle& p, const py::handle& q) {
            const Point from = point(p, "p"), to = point(q, "q");
            if (from == to) throw py::value_error("q: must differ from p (an arrow has a magnitude > 0)");
            return zero_turn_arrow(from, to);
          },
          py::arg("p"), py::arg("q"), "The zero-turn arrow from point p to point q (winding in (-pi, pi]).")
      .def_property_readonly(
          "p", [](const Arrow& a) { return py::make_tuple(a.p.real(), a.p.imag()); }, "The start point (x, y).")
      .def_property_readonly(
          "m", [](const Arrow& a) { return a.m; }, "The magnitude, > 0.")
      .def_property_readonly(
          "w", [](const Arrow& a) { return a.w; }, "The winding, in radians, never reduced.")
      .def_property_readonly(
          "q", [](const Arrow& a) { return py::make_tuple(a.q().real(), a.q().imag()); }, "The end point p + m e^{iw}.")
      .def_property_readonly(
          "turns", [](const Arrow& a) { return a.turns(); }, "The whole turns k of the winding: |w - 2 k pi| <= pi.")
      .def("__repr__", &arrow_repr)
      .def("__eq__",
           [](const Arrow& a, const py::object& other) -> py::object {
             if (!py::isinstance<Arrow>(other)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
             const Arrow& b = other.cast<const Arrow&>();
             return py::bool_(a.p == b.p && a.m == b.m && a.w == b.w);
           })
      .def("__hash__", [](const Arrow& a) { return py::hash(py::make_tuple(a.p.real(), a.p.imag(), a.m, a.w)); })
      .def(py::pickle([](const Arrow& a) { return py::make_tuple(a.p.real(), a.p.imag(), a.m, a.w); },
                      // A pickle is checked as the constructor checks (a damaged one,
                      // m = -1 or NaN, is refused, not loaded).
                      [](const py::tuple& t) {
                        if (t.size() != 4) throw py::value_error("Arrow: a pickled arrow is the tuple (x, y, m, w)");
                        return checked_arrow(Point{real(t[0], "x"), real(t[1], "y")}, real(t[2], "m"), real(t[3], "w"));
                      }));
  refuse_uninitialised<Arrow>();

  py::class_<PoseValue>(m, "Pose", R"(An affine pose x -> L x + b of the plane (L 2x2, b of 2) or of space (L 3x3,
b of 3): the keyframes of the SAM paper. Pose.from_matrix takes [L | b] (2x3, 3x4) or the
homogeneous matrix (3x3, 4x4); np.asarray(pose) is [L | b].

    >>> pita.Pose([[0, -1], [1, 0]], [2, 0])
    Pose(L=[[0.0, -1.0], [1.0, 0.0]], b=[2.0, 0.0])
)")
      .def(py::init([](const py::handle& L, const py::object& b) {
             const Eigen::MatrixXd linear = matrix(L, "L");
             Eigen::VectorXd translation = Eigen::VectorXd::Zero(linear.rows());
             if (!b.is_none()) {
               const Eigen::MatrixXd column =
                   matrix(py::module_::import("numpy").attr("reshape")(b, py::make_tuple(-1, 1)), "b");
               translation = column.col(0);
             }
             return PoseValue{pose_from_parts(linear, translation, "Pose")};
           }),
           py::arg("L"), py::arg("b") = py::none())
      .def_static(
          "from_matrix", [](const py::handle& M) { return PoseValue{pose_from_matrix(M, "M")}; }, py::arg("M"),
          "A pose from [L | b] (2x3, 3x4) or its homogeneous matrix (3x3, 4x4).")
      .def_property_readonly("dimension",
                             [](const PoseValue& v) {
                               return std::visit([]<class P>(const P&) { return PoseTraits<P>::dimension; }, v.pose);
                             })
      .def_property_readonly(
          "L", [](const PoseValue& v) { return linear_part(v.pose); }, "The linear part, a new array.")
      .def_property_readonly(
          "b", [](const PoseValue& v) { return translation(v.pose); }, "The translation, a new array.")
      .def_property_readonly(
          "matrix", [](const PoseValue& v) { return pose_matrix(v.pose); }, "[L | b], a new array.")
      .def_property_readonly(
          "homogeneous", [](const PoseValue& v) { return homogeneous(v.pose); },
          "The homogeneous matrix [[L, b], [0, 1]], a new array.")
      .def(
          "__array__",
          [](const PoseValue& v, const py::object& dtype, const py::object&) {
            py::array_t<double> M = pose_matrix(v.pose);
            return dtype.is_none() ? py::object(M) : py::object(M.attr("astype")(dtype));
          },
          py::arg("dtype") = py::none(), py::arg("copy") = py::none())
      .def(
          "__matmul__",
          [](const PoseValue& a, const PoseValue& b) -> PoseValue {
            if (a.pose.index() != b.pose.index())
              throw py::value_error("a pose of the plane and one of space do not compose");
            return std::visit(
                overloaded{[&](const Affine2& A) { return PoseValue{compose(A, std::get<Affine2>(b.pose))}; },
                           [&](const Affine3& A) { return PoseValue{compose(A, std::get<Affine3>(b.pose))}; }},
                a.pose);
          },
          "a @ b: first b, then a.")
      .def("inverse",
           [](const PoseValue& v) {
             return std::visit(
                 [](const auto& A) -> PoseValue {
                   if (A.L.determinant() == 0.0) throw py::value_error("the pose is singular (det L = 0): no inverse");
                   return PoseValue{inverse(A)};
                 },
                 v.pose);
           })
      .def("__repr__", [](const PoseValue& v) { return pose_repr(v.pose); })
      .def("__eq__",
           [](const PoseValue& a, const py::object& other) -> py::object {
             if (!py::isinstance<PoseValue>(other)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
             const PoseValue& b = other.cast<const PoseValue&>();
             if (a.pose.index() != b.pose.index()) return py::bool_(false);
             return py::bool_(std::visit(
                 [&](const auto& A) {
                   const auto& B = std::get<std::decay_t<decltype(A)>>(b.pose);
                   return A.L == B.L && A.b == B.b;
                 },
                 a.pose));
           })
      .def("__hash__",
           [](const PoseValue& v) {
             // of the numbers, as == compares them (-0.0 == 0.0 hash alike)
             return py::hash(py::tuple(pose_matrix(v.pose).attr("ravel")().attr("tolist")()));
           })
      .def(py::pickle([](const PoseValue& v) { return py::make_tuple(pose_matrix(v.pose)); },
                      [](const py::tuple& t) {
                        if (t.size() != 1) throw py::value_error("Pose: a pickled pose is the tuple ([L | b],)");
                        return PoseValue{pose_from_matrix(t[0], "M")};
                      }));
  refuse_uninitialised<PoseValue>();
}

}  // namespace pita::python
