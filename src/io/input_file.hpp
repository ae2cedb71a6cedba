// Files read as inputs (scenes, images, a sweep's manifests and parts): opened
// as regular files only. A FIFO, a device, a socket or a directory is refused
// at once with what it is, without ever blocking in open() or reading an
// endless stream, and a name that holds a NUL byte (which the system would cut
// short, "secret.txt\0.json") is refused before anything is opened.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

namespace pita::io {

// Why an input cannot be read, without the file's name, which the caller
// places: what() is the detail ("it is a named pipe (FIFO), not a regular
// file", "No such file or directory", "32 MiB"); sentence() words it.
class InputError : public std::runtime_error {
 public:
  enum class Kind { cannot_open, not_regular, too_large, cannot_read };
  InputError(Kind kind, const std::string& detail) : std::runtime_error(detail), kind_(kind) {}
  Kind kind() const { return kind_; }
  // The sentence for an input named by `what` ("scene file"): "cannot open
  // the scene file (No such file or directory)", "cannot read the scene file:
  // it is a directory", "the scene file is larger than the limit of 32 MiB".
  std::string sentence(const std::string& what) const;

 private:
  Kind kind_;
};

// A regular file open for reading.
class InputFile {
 public:
  // Throws InputError.
  explicit InputFile(const std::filesystem::path& path);
  ~InputFile();
  InputFile(InputFile&& other) noexcept;
  InputFile& operator=(InputFile&&) = delete;
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  // Up to `n` bytes into `buffer`; 0 at its end. Throws InputError.
  std::size_t read(char* buffer, std::size_t n);

 private:
  int fd_ = -1;
};

// For an input that may be a pipe (pita eval --batch FILE, where <(...) is a
// FIFO): what it is when it is neither a regular file nor a FIFO ("it is a
// device, not a regular file"), else nullopt (also when it does not exist:
// opening it says so).
std::optional<std::string> neither_file_nor_pipe(const std::filesystem::path& path);

// The whole regular file, at most `max_bytes` (InputError beyond, read no
// further than one byte past the limit).
std::string read_regular_file(const std::filesystem::path& path, std::size_t max_bytes);

// Whether two paths name one file: the same file when both exist (links
// followed, hard links included), else the same canonical path. How an output
// is refused when it would replace an input of the same run.
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

// Whether `path` is `folder` or lies inside it, links followed as far as
// they exist (weakly_canonical).
bool within_folder(const std::filesystem::path& path, const std::filesystem::path& folder);

}  // namespace pita::io
