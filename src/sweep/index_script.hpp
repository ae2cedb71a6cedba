// The script of a sweep's index.html (src/sweep/index_page.js): the table,
// its pages and sorting, the data files loaded with <script> elements as
// needed; text is set as text (no markup from data). Built into the binary:
// CMake writes its text into index_script.cpp (src/CMakeLists.txt), as it
// does serve's page (src/serve/page/).
#pragma once

#include <string_view>

namespace pita::sweep {

std::string_view index_script();

}  // namespace pita::sweep
