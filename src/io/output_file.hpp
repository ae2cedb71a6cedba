// Writing outputs so that nothing half-written is ever seen: the bytes go to a
// hidden temporary file beside the target (.name.ext.XXXXXX, in the same
// directory so that the rename is atomic), which is then renamed into place.
// The temporaries are registered with the interrupt cleanup (interrupt.hpp):
// SIGINT, SIGTERM or SIGHUP removes them.
#pragma once

#include <filesystem>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace pita::io {

// An output that could not be written (exit 3): what() names the path and
// the system's reason.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws OutputError with the path and the system's reason.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

// `bytes` in place of the file at `path` (written atomically, as above) if
// the file still holds `expected`, compared just before the rename; false,
// and the file left as it is, when it changed (another program saved it).
// Throws OutputError.
bool replace_file_if_unchanged(const std::filesystem::path& path, std::string_view expected, std::string_view bytes);

// The files of a set (a scene's formats) are written all or none: every
// temporary is created and written first, and only then are they renamed into
// place, the commit step. A failure before the commit (no space, a directory
// in the way of a target) removes every temporary and leaves the old files
// untouched. Should a rename still fail during the commit, the files of the
// set already renamed are removed too, so that no partial set remains.
// Throws OutputError naming the file that failed and the reason.
void write_files_atomically(std::span<const std::pair<std::filesystem::path, std::string>> files);

// One file written piece by piece (a manifest of millions of rows) without
// holding it in memory, atomically like the others: into a registered hidden
// temporary, renamed into place by commit(). Destroyed without commit(), it
// leaves no file and the old one untouched. Throws OutputError.
class StreamingOutput {
 public:
  // `buffer_bytes`: written through once this much is held (smaller for
  // many files open at once).
  explicit StreamingOutput(const std::filesystem::path& path, std::size_t buffer_bytes = kBufferBytes);
  ~StreamingOutput();
  StreamingOutput(const StreamingOutput&) = delete;
  StreamingOutput& operator=(const StreamingOutput&) = delete;
  void write(std::string_view bytes);  // buffered (kBufferBytes)
  void commit();

  static constexpr std::size_t kBufferBytes = std::size_t{1} << 20;

 private:
  std::size_t buffer_bytes_;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pita::io
