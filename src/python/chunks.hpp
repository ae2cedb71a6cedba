// Long loops of the module run without the GIL, in chunks: between two, the
// GIL is taken back for a moment to see whether Ctrl-C was pressed
// (KeyboardInterrupt is then raised, and nothing is returned).
#pragma once

#include <algorithm>
#include <cstddef>

#include <pybind11/pybind11.h>

namespace pita::python {

inline constexpr std::size_t kChunk = std::size_t{1} << 16;

// Calls step(begin, end) over [0, n) in chunks of kChunk, without the GIL;
// stops early when step returns false. Throws py::error_already_set on a
// pending signal (KeyboardInterrupt); exceptions of step pass through.
template <class Step>
void for_each_chunk(std::size_t n, Step&& step) {
  for (std::size_t begin = 0; begin < n; begin += kChunk) {
    const std::size_t end = std::min(n, begin + kChunk);
    bool go_on = true;
    {
      pybind11::gil_scoped_release unlocked;
      go_on = step(begin, end);
    }
    if (!go_on) return;
    if (PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
  }
}

}  // namespace pita::python
