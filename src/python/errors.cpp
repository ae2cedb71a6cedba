// The exceptions of the module. Every error of pita is a pita.Error; a bad
// scene or argument is also a ValueError, an output that cannot be written an
// OSError. Those about a scene carry where: .file, .pointer (JSON Pointer,
// "" for the whole document), .reason, and .line and .column for malformed
// JSON (0 otherwise). A C++ exception never escapes as a crash: what is not
// one of these becomes RuntimeError (pybind11's translation).
#include <array>
#include <exception>
#include <optional>
#include <string>

#include <pybind11/eval.h>

#include "animate/timeline.hpp"
#include "core/affine_power.hpp"
#include "golden/image_compare.hpp"
#include "io/output_file.hpp"
#include "python/bindings.hpp"
#include "render/image_cache.hpp"
#include "scene/located_error.hpp"

namespace pita::python {

namespace {

// The classes, written in Python so that they behave as Python users expect
// (constructible, with keyword attributes, picklable).
constexpr const char* kErrorClasses = R"(
class Error(Exception):
    """Every error pita raises."""

class SceneError(Error, ValueError):
    """A scene (a file, a dict, or the arguments of pita.motion) that pita refuses.

    .file names the scene ("<dict>" or "<pita.motion>" for scenes made in
    Python), .pointer is the JSON Pointer of the bad value ("/keyframes/1/m";
    "" for the whole document), .reason says what is wrong; .line and .column
    locate malformed JSON (0 otherwise). str() is "FILE: POINTER: reason".
    """
    def __init__(self, message, file="", pointer="", reason="", line=0, column=0):
        super().__init__(message)
        self.file, self.pointer, self.reason = file, pointer, reason
        self.line, self.column = line, column

    def __reduce__(self):
        return (type(self), (str(self), self.file, self.pointer, self.reason, self.line, self.column))

class NoMotionError(SceneError):
    """No motion exists through these keyframes or poses (or it is not finite at a time asked for)."""

class RenderError(SceneError):
    """A figure that cannot be drawn (its motion does not exist, a frame is not finite, an image is corrupt)."""

class AnimationError(Error, ValueError):
    """An animation pita cannot make (a bad fps, duration, frame count or output kind)."""

class GoldenError(Error):
    """A golden file that cannot be read or decoded."""

class OutputError(Error, OSError):
    """An output that could not be written (nothing was left half-written)."""

class NoSamError(Error, ValueError):
    """No real power, hence no SAM, exists: the linear part has no real logarithm
    (two negative eigenvalues, SAM paper appendix A.5 case G3) or reverses orientation.

    .reason says why, with the eigenvalues; .index is the index of the first
    matrix without one in an array (None for a single matrix).
    """
    def __init__(self, message, reason="", index=None):
        super().__init__(message)
        self.reason, self.index = reason, index

    def __reduce__(self):
        return (type(self), (str(self), self.reason, self.index))
)";

// The classes, kept for the process's life (the module is never unloaded);
// those of the located errors by kind, from scene::kLocatedAnswers.
struct ErrorTypes {
  std::array<py::handle, scene::kLocatedAnswers.size()> located;
  py::handle animation, golden, output, no_sam;

  py::handle of(scene::LocatedKind kind) const {
    return located[static_cast<std::size_t>(&scene::answer(kind) - scene::kLocatedAnswers.data())];
  }
};
ErrorTypes& types() {
  static ErrorTypes all;
  return all;
}

void raise(py::handle type, const py::object& instance) { PyErr_SetObject(type.ptr(), instance.ptr()); }

void raise_located(py::handle type, const char* what, const std::string& file, const std::string& pointer,
                   const std::string& reason, int line = 0, int column = 0) {
  raise(type, py::reinterpret_borrow<py::object>(type)(what, file, pointer, reason, line, column));
}

}  // namespace

void raise_no_sam(const std::string& reason, std::optional<std::size_t> index) {
  const std::string message = index ? "matrix " + std::to_string(*index) + ": " + reason : reason;
  py::object error = py::reinterpret_borrow<py::object>(types().no_sam)(message, reason);
  if (index) error.attr("index") = *index;
  raise(types().no_sam, error);
  throw py::error_already_set();
}

void bind_errors(py::module_& m) {
  py::dict scope;
  scope["__name__"] = "pita";
  py::exec(kErrorClasses, scope);
  for (const char* name : {"Error", "SceneError", "NoMotionError", "RenderError", "AnimationError", "GoldenError",
                           "OutputError", "NoSamError"}) {
    m.attr(name) = scope[name];
  }
  ErrorTypes& all = types();
  const auto kept = [&](const char* name) { return py::object(scope[name]).release(); };  // never freed
  for (std::size_t k = 0; k < scene::kLocatedAnswers.size(); ++k) {
    all.located[k] = kept(std::string(scene::kLocatedAnswers[k].python_class).c_str());
  }
  all.animation = kept("AnimationError");
  all.golden = kept("GoldenError");
  all.output = kept("OutputError");
  all.no_sam = kept("NoSamError");

  py::register_exception_translator([](std::exception_ptr thrown) {
    if (!thrown) return;
    const ErrorTypes& t = types();
    try {
      std::rethrow_exception(thrown);
    } catch (const scene::LocatedError& e) {  // SceneError, NoMotion, RenderError
      raise_located(t.of(e.kind()), e.what(), e.file(), e.pointer(), e.reason(), e.line(), e.column());
    } catch (const render::ImageError& e) {
      raise_located(t.of(scene::LocatedKind::render), e.what(), "", "", e.what());
    } catch (const animate::AnimationError& e) {
      raise(t.animation, py::reinterpret_borrow<py::object>(t.animation)(e.what()));
    } catch (const golden::GoldenError& e) {
      raise(t.golden, py::reinterpret_borrow<py::object>(t.golden)(e.what()));
    } catch (const io::OutputError& e) {
      raise(t.output, py::reinterpret_borrow<py::object>(t.output)(e.what()));
    } catch (const NoRealLogarithm& e) {
      raise(t.no_sam, py::reinterpret_borrow<py::object>(t.no_sam)(e.what(), e.what()));
    } catch (const MotionDomainError& e) {
      raise_located(t.of(scene::LocatedKind::no_motion), e.what(), "", "", e.what());
    }
  });
}

}  // namespace pita::python
