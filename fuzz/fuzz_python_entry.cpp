// Bytes -> the checks the Python module makes of what a user passes
// (src/python/checks.hpp), which run before any array is copied or any value
// is built: the count of an array from its shape against the work limit,
// NumPy's broadcast of two shapes, the shape of a pose's matrix, and the
// arrow a constructor or a pickle gives (Atheris is not in Debian: this
// harness drives the same C++ without the interpreter). The first byte
// chooses the check:
//   0  two shapes (a byte of rank each, at most 8, then 8-byte extents, any
//      sign): broadcast_shape and check_elements;
//   1  an arrow: four raw doubles (x, y, m, w) to checked_arrow;
//   2  a matrix shape: two 8-byte extents to check_pose_shape (the second
//      byte: a linear part L or a whole pose);
//   3  a raw double to python_repr.
//
// Must hold for any input: no crash and no UB; a refusal is
// std::invalid_argument with a message that names the argument; what is
// accepted is what the module may then allocate and compute with: a
// broadcast NumPy would make, of at most kMaxElements elements; a finite
// arrow with m > 0 and |w| <= kMaxWinding whose turns are exact; a 2x3, 3x3,
// 3x4 or 4x4 matrix (2x2 or 3x3 for L); the shortest text that reads back
// as the same double.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz_support.hpp"
#include "python/checks.hpp"

namespace {

using namespace pita;

class Reader {
 public:
  Reader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  // Eight bytes, little-endian, as a double or an int64.
  template <class T>
  T raw() {
    static_assert(sizeof(T) == sizeof(std::uint64_t));
    std::uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits |= std::uint64_t{byte()} << (8 * i);
    return std::bit_cast<T>(bits);
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

// A refusal names what was passed: "t: ...", "M and t: ...".
void check_refusal(const std::invalid_argument& error, const std::string& name) {
  const std::string message = error.what();
  PITA_FUZZ_CHECK(message.starts_with(name + ": "));
  PITA_FUZZ_CHECK(message.size() > name.size() + 2);
}

std::vector<std::int64_t> shape(Reader& in) {
  std::vector<std::int64_t> extents(in.byte() % 9);
  for (std::int64_t& extent : extents) extent = in.raw<std::int64_t>();
  return extents;
}

void shapes(Reader& in) {
  const std::vector<std::int64_t> a = shape(in), b = shape(in);
  const bool negative = std::any_of(a.begin(), a.end(), [](std::int64_t x) { return x < 0; }) ||
                        std::any_of(b.begin(), b.end(), [](std::int64_t x) { return x < 0; });
  std::vector<std::int64_t> out;
  try {
    out = python::broadcast_shape(a, b, "M and t");
  } catch (const std::invalid_argument& error) {
    check_refusal(error, "M and t");
    return;
  }
  PITA_FUZZ_CHECK(!negative);
  PITA_FUZZ_CHECK(out.size() == std::max(a.size(), b.size()));
  for (std::size_t i = 0; i < out.size(); ++i) {  // NumPy's rule, from the right
    const std::size_t from_end = out.size() - i;
    const std::int64_t x = from_end <= a.size() ? a[a.size() - from_end] : 1;
    const std::int64_t y = from_end <= b.size() ? b[b.size() - from_end] : 1;
    PITA_FUZZ_CHECK(x == y || x == 1 || y == 1);
    PITA_FUZZ_CHECK(out[i] == (x == 1 ? y : x));
  }
  try {
    python::check_elements(out, "M and t");
  } catch (const std::invalid_argument& error) {
    check_refusal(error, "M and t");
    PITA_FUZZ_CHECK(python::shape_size(out, "M and t") > python::kMaxElements);
    return;
  }
  // Accepted: within the limit, so the count fits a size_t and its arrays are bounded.
  double size = 1.0;
  for (const std::int64_t extent : out) size *= static_cast<double>(extent);
  PITA_FUZZ_CHECK(size <= python::kMaxElements);
}

void arrow(Reader& in) {
  const double x = in.raw<double>(), y = in.raw<double>(), m = in.raw<double>(), w = in.raw<double>();
  Arrow a;
  try {
    a = python::checked_arrow(Point{x, y}, m, w);
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    PITA_FUZZ_CHECK(message.starts_with("p: ") || message.starts_with("m: ") || message.starts_with("w: "));
    PITA_FUZZ_CHECK(!(std::isfinite(x) && std::isfinite(y) && std::isfinite(m) && m > 0.0 && std::isfinite(w) &&
                      std::abs(w) <= scene::kMaxWinding));
    return;
  }
  PITA_FUZZ_CHECK(std::isfinite(a.p.real()) && std::isfinite(a.p.imag()));
  PITA_FUZZ_CHECK(std::isfinite(a.m) && a.m > 0.0);
  PITA_FUZZ_CHECK(std::isfinite(a.w) && std::abs(a.w) <= scene::kMaxWinding);
  // Its turns are exact: w - 2 pi k is within a half turn (and a rounding).
  const double k = static_cast<double>(a.turns());
  PITA_FUZZ_CHECK(std::abs(k) <= scene::kMaxWinding / (2.0 * std::numbers::pi) + 1.0);
  PITA_FUZZ_CHECK(std::abs(a.w - 2.0 * std::numbers::pi * k) <= std::numbers::pi * (1.0 + 1e-9));
}

void pose_shape(Reader& in) {
  const bool linear = (in.byte() & 1) != 0;
  const auto rows = in.raw<std::int64_t>(), cols = in.raw<std::int64_t>();
  const std::string name = linear ? "L" : "M";
  try {
    python::check_pose_shape(rows, cols, name, linear);
  } catch (const std::invalid_argument& error) {
    check_refusal(error, name);
    return;
  }
  if (linear) {
    PITA_FUZZ_CHECK(rows == cols && (rows == 2 || rows == 3));
  } else {
    PITA_FUZZ_CHECK((rows == 2 && cols == 3) || (rows == 3 && cols == 3) || (rows == 3 && cols == 4) ||
                    (rows == 4 && cols == 4));
  }
}

void repr(Reader& in) {
  const double x = in.raw<double>();
  const std::string text = python::python_repr(x);
  PITA_FUZZ_CHECK(!text.empty());
  const double back = std::strtod(text.c_str(), nullptr);
  PITA_FUZZ_CHECK(std::isnan(x) ? std::isnan(back) : back == x && std::signbit(back) == std::signbit(x));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Reader in(data, size);
  switch (in.byte() % 4) {
    case 0:
      shapes(in);
      break;
    case 1:
      arrow(in);
      break;
    case 2:
      pose_shape(in);
      break;
    default:
      repr(in);
      break;
  }
  return 0;
}
