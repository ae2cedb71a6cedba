// What the fuzz targets share: the input as text, a check that ends the
// process like a crash in every build (assert() is compiled out by NDEBUG in
// the Release build whose ctest replays tests/data/fuzz/), and a scratch path
// of the process removed at exit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

#include <unistd.h>

#define PITA_FUZZ_CHECK(condition)                                                            \
  do {                                                                                        \
    if (!(condition)) {                                                                       \
      std::fprintf(stderr, "%s:%d: fuzz check failed: %s\n", __FILE__, __LINE__, #condition); \
      std::abort();                                                                           \
    }                                                                                         \
  } while (false)

namespace pita::fuzz {

inline std::string_view text_of(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// FNV-1a: a choice that follows the input (the same input always makes it).
inline std::uint64_t hash_of(std::string_view text) {
  std::uint64_t h = 14695981039346656037ull;
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  return h;
}

// PREFIX<pid>SUFFIX under the temporary directory, the same on every call of
// the process, removed (with what it holds) at exit. The path is allocated
// once and never destroyed: a static object made in the first call would be
// destroyed before the exit handler registered during its making runs.
inline const std::filesystem::path& scratch_path(std::string_view prefix = "", std::string_view suffix = "") {
  static const std::filesystem::path* const path = [&] {
    const auto* p = new std::filesystem::path(std::filesystem::temp_directory_path() /
                                              (std::string(prefix) + std::to_string(::getpid()) + std::string(suffix)));
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(scratch_path(), ignored);
    });
    return p;
  }();
  return *path;
}

}  // namespace pita::fuzz
