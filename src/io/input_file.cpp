#include "io/input_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace pita::io {

namespace {

std::string system_reason(int error) { return std::strerror(error); }

// What a file that is not regular is, in words.
std::string what_it_is(mode_t mode) {
  if (S_ISDIR(mode)) return "it is a directory";
  if (S_ISFIFO(mode)) return "it is a named pipe (FIFO), not a regular file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "it is a device, not a regular file";
  if (S_ISSOCK(mode)) return "it is a socket, not a regular file";
  return "it is not a regular file";
}

// "32 MiB", "512 bytes".
std::string size_text(std::size_t bytes) {
  constexpr std::size_t kMiB = 1024 * 1024;
  return bytes >= kMiB && bytes % kMiB == 0 ? std::to_string(bytes / kMiB) + " MiB" : std::to_string(bytes) + " bytes";
}

using Kind = InputError::Kind;

}  // namespace

std::string InputError::sentence(const std::string& what) const {
  switch (kind_) {
    case Kind::cannot_open:
      return "cannot open the " + what + " (" + this->what() + ")";
    case Kind::not_regular:
      return "cannot read the " + what + ": " + this->what();
    case Kind::too_large:
      return "the " + what + " is larger than the limit of " + this->what();
    case Kind::cannot_read:
      break;
  }
  return "cannot read the " + what + " (" + this->what() + ")";
}

InputFile::InputFile(const std::filesystem::path& path) {
  const std::string& name = path.native();
  if (name.find('\0') != std::string::npos) throw InputError(Kind::not_regular, "its name holds a NUL byte");
  // O_NONBLOCK: opening a FIFO without a writer returns at once instead of
  // waiting for one; fstat then says what was opened.
  fd_ = ::open(name.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd_ < 0) {
    const int error = errno;
    struct stat st {};
    if (error == ENXIO || (::stat(name.c_str(), &st) == 0 && !S_ISREG(st.st_mode))) {
      throw InputError(Kind::not_regular,
                       ::stat(name.c_str(), &st) == 0 ? what_it_is(st.st_mode) : "it is not a regular file");
    }
    throw InputError(Kind::cannot_open, system_reason(error));
  }
  struct stat st {};
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    const std::string reason = ::fstat(fd_, &st) == 0 ? what_it_is(st.st_mode) : "cannot read what it is";
    ::close(fd_);
    fd_ = -1;
    throw InputError(Kind::not_regular, reason);
  }
  // A regular file: blocking reads from here on.
  const int flags = ::fcntl(fd_, F_GETFL);
  if (flags >= 0) ::fcntl(fd_, F_SETFL, flags & ~O_NONBLOCK);
}

InputFile::~InputFile() {
  if (fd_ >= 0) ::close(fd_);
}

InputFile::InputFile(InputFile&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }

std::size_t InputFile::read(char* buffer, std::size_t n) {
  while (true) {
    const ssize_t got = ::read(fd_, buffer, n);
    if (got >= 0) return static_cast<std::size_t>(got);
    if (errno == EINTR) continue;
    throw InputError(Kind::cannot_read, system_reason(errno));
  }
}

std::optional<std::string> neither_file_nor_pipe(const std::filesystem::path& path) {
  struct stat st {};
  if (path.native().find('\0') != std::string::npos) return "its name holds a NUL byte";
  if (::stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode) || S_ISFIFO(st.st_mode)) return std::nullopt;
  return what_it_is(st.st_mode);
}

std::string read_regular_file(const std::filesystem::path& path, std::size_t max_bytes) {
  InputFile file(path);
  std::string text;
  char chunk[1 << 16];
  while (text.size() <= max_bytes) {
    const std::size_t got = file.read(chunk, std::min(sizeof chunk, max_bytes + 1 - text.size()));
    if (got == 0) return text;
    text.append(chunk, got);
  }
  throw InputError(Kind::too_large, size_text(max_bytes));
}

bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code error;
  if (std::filesystem::exists(a, error) && std::filesystem::exists(b, error)) {
    return std::filesystem::equivalent(a, b, error) && !error;
  }
  return std::filesystem::weakly_canonical(a, error) == std::filesystem::weakly_canonical(b, error) && !error;
}

bool within_folder(const std::filesystem::path& path, const std::filesystem::path& folder) {
  std::error_code error;
  const std::filesystem::path p = std::filesystem::weakly_canonical(path, error);
  if (error) return false;
  const std::filesystem::path f = std::filesystem::weakly_canonical(folder, error);
  if (error) return false;
  auto it = p.begin();
  for (const std::filesystem::path& part : f) {
    if (part.empty()) continue;  // the trailing "" of "dir/"
    if (it == p.end() || *it != part) return false;
    ++it;
  }
  return true;
}

}  // namespace pita::io
