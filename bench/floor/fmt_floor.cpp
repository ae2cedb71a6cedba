// The floor `pita eval` streaming is compared with (docs/explanation/
// performance.md "pita eval"): N rows of seven doubles, "{:.17g}" each, as
// `pita eval --format csv` prints them, formatted with fmt into a 64 KiB
// buffer and written to standard output, with no motion evaluated.
//   pita_fmt_floor N
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>

#include <fmt/format.h>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fputs("usage: pita_fmt_floor N\n", stderr);
    return 2;
  }
  const long count = std::atol(argv[1]);
  fmt::memory_buffer buffer;
  fmt::format_to(std::back_inserter(buffer), "t,px,py,m,w,qx,qy\n");
  for (long i = 0; i < count; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(count - 1);
    // Values with as many digits as a motion's: not round numbers.
    fmt::format_to(std::back_inserter(buffer), "{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", t,
                   6.0 * t + std::sin(3.0 * t), 1.5 * std::sin(3.14159 * t), 1.0 + 0.2 * t, 0.4 + 3.1 * t,
                   std::cos(t) + 6.0 * t, std::sin(t));
    if (buffer.size() >= (std::size_t{1} << 16)) {
      std::fwrite(buffer.data(), 1, buffer.size(), stdout);
      buffer.clear();
    }
  }
  std::fwrite(buffer.data(), 1, buffer.size(), stdout);
  return std::fflush(stdout) == 0 ? 0 : 3;
}
