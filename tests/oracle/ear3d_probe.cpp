// A test-only window on EAR in 3D (core/affine_power_of_space.hpp) for the
// independent oracle tests/oracle/sam3d_oracle.py (ctest oracle.sam3d_compare):
// 3D scenes do not exist in the CLI yet, so the oracle asks this instead of
// `pita eval`.
//
// Each line of stdin: t and the 3x4 matrix [L | b] by rows,
//   t a b c tx d e f ty g h i tz
// Each line of stdout: A^t as 12 numbers (%.17g), or "nosam <what()>" when
// A has no real power (NoRealLogarithm).
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

#include "core/affine_power_of_space.hpp"

int main() {
  std::string line;
  while (std::getline(std::cin, line)) {
    if (line.empty()) continue;
    std::istringstream in(line);
    double t = 0.0;
    pita::Affine3 A;
    in >> t;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) in >> A.L(r, c);
      in >> A.b(r);
    }
    if (!in) {
      std::cerr << "ear3d_probe: expected 13 numbers: " << line << "\n";
      return 2;
    }
    try {
      const pita::Affine3 P = pita::affine_power(A, t);
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) std::printf("%.17g ", P.L(r, c));
        std::printf(r == 2 ? "%.17g\n" : "%.17g ", P.b(r));
      }
    } catch (const pita::NoRealLogarithm& error) {
      std::printf("nosam %s\n", error.what());
    }
  }
  return 0;
}
