// The Python module `pita` (pybind11): a thin layer over the C++ layers, as
// cli/ is for the command line. Each part binds one concern:
//   errors.cpp   the exceptions (pita.Error, SceneError with .file and .pointer, ...)
//   values.cpp   pita.Arrow and pita.Pose, plain value types
//   affine.cpp   pita.sma, ear_power, sam, has_sam (core, vectorised over NumPy)
//   motion.cpp   pita.methods(), pita.motion(...) and the Motion it returns
//   scene.cpp    pita.load_scene(...) and Scene: eval, render, animate, measure, check
//   examples.cpp pita.scenes_dir() and pita.example(name): pita's own scenes from any folder
// No math is done here: every number comes from the same C++ the CLI calls.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>  // every file: one type_caster of std::vector and std::optional

#include "core/affine2.hpp"
#include "core/affine3.hpp"
#include "core/arrow.hpp"

namespace pita::python {

namespace py = pybind11;

void bind_errors(py::module_& m);
void bind_values(py::module_& m);
void bind_affine(py::module_& m);
void bind_motion(py::module_& m);
void bind_scene(py::module_& m);
void bind_examples(py::module_& m);

// A pose of the plane or of space: pita.Pose holds one.
using Pose = std::variant<Affine2, Affine3>;

// ------------------------------------------------------------- conversions

// Times as NumPy gives them: a Python number (scalar) or an array-like of
// real numbers of any shape (integers are converted; complex, strings and
// objects are refused with TypeError, NaN and infinities with ValueError).
struct Times {
  std::vector<double> values;      // flattened, C order
  std::vector<py::ssize_t> shape;  // empty for a scalar
  bool scalar = false;
};
// The count of the times is checked from their shape before they are
// converted or copied: at most kMaxElements (python/checks.hpp), then by
// `check` (given the count) when given. ValueError names `name`.
Times read_times(const py::handle& t, const char* name, const std::function<void(std::size_t)>& check = {});

// The shape of an array-like, as np.shape gives it (an array's own, without a
// copy); empty when NumPy cannot say (a ragged list).
std::vector<std::int64_t> array_shape(const py::handle& value);

// A float64 array of shape `shape` + `tail`, C-contiguous, uninitialised.
py::array_t<double> new_array(const std::vector<py::ssize_t>& shape, std::initializer_list<py::ssize_t> tail);

// An arrow from a pita.Arrow, or a mapping {"p", "m", "w"} / {"p", "q"}.
Arrow read_arrow(const py::handle& value, const char* name);

// A pose from a pita.Pose, or a matrix: 2x3 [L | b] or 3x3 homogeneous
// (plane), 3x4 or 4x4 homogeneous (space). Throws ValueError (py::value_error)
// for another shape or a homogeneous last row other than [0, ..., 0, 1].
Pose read_pose(const py::handle& value, const char* name);

// Whether the value is a pita.Pose.
bool is_pose(const py::handle& value);

// A pose as NumPy: [L | b], 2x3 or 3x4.
py::array_t<double> pose_matrix(const Pose& pose);
void write_pose(const Affine2& A, double* out);  // 6 numbers, row-major [L | b]
void write_pose(const Affine3& A, double* out);  // 12 numbers

// Raises pita.NoSamError (throws py::error_already_set) with the reason;
// `index`: the first matrix of an array that has no real power.
[[noreturn]] void raise_no_sam(const std::string& reason, std::optional<std::size_t> index);

// The arrow as Python sees it (a pita.Arrow).
py::object arrow_object(const Arrow& arrow);
py::object pose_object(const Pose& pose);

// An object made by T.__new__ without __init__ (pita.Arrow.__new__(pita.Arrow))
// holds no value: pybind11 would give its methods fresh uninitialised memory
// (type_caster_generic::load_value allocates it lazily with the type's
// operator_new). Called once after T's py::class_, this makes that
// allocation raise TypeError instead, so that every method and attribute of
// such an object refuses it; objects made by a constructor, a function or
// a pickle are untouched (they hold a value before any method runs).
template <class T>
void* refuse_new_value(std::size_t) {
  const py::detail::type_info* info = py::detail::get_type_info(typeid(T));
  const std::string name = info != nullptr ? info->type->tp_name : "pita object";
  throw py::type_error(name +
                       ": this object was made by __new__ without __init__ and holds no value; make one with its "
                       "constructor, or the function that returns it");
}
template <class T>
void refuse_uninitialised() {
  py::detail::get_type_info(typeid(T))->operator_new = &refuse_new_value<T>;
}

// Named tuples of the module (made once by bind_values): ArrowSamples(p, m, w, q).
py::object arrow_samples_type();

}  // namespace pita::python
