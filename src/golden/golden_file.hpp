// Reading a golden file without leaving the golden folder: a golden is a plain
// file at GOLDEN/<name>/<file>, and neither <name> nor <file> may be a
// symbolic link, a FIFO or a device. A pull request that adds
// `golden/b/b.svg -> /proc/self/environ` must not put the environment of CI
// into the report (`pita check --report` copies the expected files), and a
// FIFO must not hang `check` or `update-goldens`. The folder given as
// --golden itself may be a link: the user chose it.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "golden/image_compare.hpp"

namespace pita::golden {

// A golden path that is a link or not a regular file (exit 2, with the path).
class GoldenPathError : public GoldenError {
 public:
  using GoldenError::GoldenError;
};

// The bytes of GOLDEN/<name>/<file> (`path` is that; its grandparent the
// golden folder), nullopt when it does not exist. Throws GoldenPathError for
// a link, FIFO, device or directory on the way, GoldenError when it cannot be
// read or is larger than `max_bytes`.
std::optional<std::string> read_golden_file(const std::filesystem::path& path, std::size_t max_bytes);

// Throws GoldenPathError when GOLDEN/<name> (the parent of `path`) exists and
// is not a plain directory: what update-goldens checks before writing there.
void check_golden_folder(const std::filesystem::path& path);

}  // namespace pita::golden
