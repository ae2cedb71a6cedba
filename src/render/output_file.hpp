// Writing an output so that nothing half-written is ever seen: the bytes go
// to a temporary file beside the target, which is then renamed into place.
#pragma once

#include <filesystem>
#include <string_view>

namespace pita::render {

// Throws std::runtime_error with the path and the system's reason.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace pita::render
