// The module's entry: `import pita` (docs/guide/python.md).
#include "python/bindings.hpp"
#include "python/chunks.hpp"

#ifndef PITA_VERSION
#error "PITA_VERSION is defined by src/python/CMakeLists.txt"
#endif

PYBIND11_MODULE(pita, m) {
  m.doc() = R"(pita: the interpolating motions of Rossignac and Vinacua from Python.

The PITAs (planar interpolation of three arrows, P1-P10) and the steady morph of two arrows
(SMA), the Steady Affine Morphs (SAM) of poses of the plane and of space and their real
powers (EAR), and the figures of scene files: the same C++ as the pita command line,
vectorised over NumPy arrays.

    import pita, numpy as np
    arrows = [pita.Arrow((0, 0), 1, 0.4), pita.Arrow((3, 1.5), 0.6, 2.0), pita.Arrow((6, 0), 1.2, 3.5)]
    motion = pita.motion("P6", arrows, [0, 0.5, 1])
    p, m, w, q = motion(np.linspace(0, 1, 9))
    pita.ear_power([[0, -1, 2], [1, 0, 0]], 0.5)     # the square root of a quarter turn
    pita.load_scene(pita.example("fig01-eight-pitas"))  # shows its figure in Jupyter
)";
  m.attr("__version__") = PITA_VERSION;
  pita::python::bind_errors(m);
  pita::python::bind_values(m);
  pita::python::bind_affine(m);
  pita::python::bind_motion(m);
  pita::python::bind_scene(m);
  pita::python::bind_examples(m);
  // A figure dropped by Ctrl-C (run_interruptible) ends before the process does.
  pybind11::module_::import("atexit").attr("register")(
      pybind11::cpp_function([] { pita::python::wait_for_background_work(); }));
}
