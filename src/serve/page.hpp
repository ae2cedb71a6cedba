// The page of `pita serve` (src/serve/page/), built into the binary:
// CMake writes its text into serve_page.cpp in the build folder
// (src/CMakeLists.txt), so that nothing is fetched or installed beside pita
// to show it.
#pragma once

#include <string_view>

namespace pita::serve {

std::string_view page_html();

}  // namespace pita::serve
