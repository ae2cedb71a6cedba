// Writing an output so that nothing half-written is ever seen: the bytes go
// to a temporary file beside the target, which is then renamed into place.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string_view>

namespace pita::render {

// An output that could not be written (exit 3): what() names the path and
// the system's reason.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws OutputError with the path and the system's reason.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace pita::render
