// How the core's messages print a number: six significant digits, as printf's
// "%.6g" ("0.333333", "1e+300"). The core has no fmt; the layers above use it.
#pragma once

#include <cstdio>
#include <string>

namespace pita::number_text {

inline std::string g6(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

}  // namespace pita::number_text
