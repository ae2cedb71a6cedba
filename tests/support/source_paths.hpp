// Folders of the source tree that tests read: every test executable is
// compiled with PITA_SOURCE_DIR (tests/CMakeLists.txt).
#pragma once

#include <filesystem>

namespace pita::test {

inline const std::filesystem::path kScenes = std::filesystem::path(PITA_SOURCE_DIR) / "scenes";

}  // namespace pita::test
