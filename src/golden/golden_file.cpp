#include "golden/golden_file.hpp"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

namespace pita::golden {

namespace {

namespace fs = std::filesystem;

// Closes on every path out.
struct Descriptor {
  int fd = -1;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

std::string kind_of(mode_t mode) {
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISDIR(mode)) return "a directory";
  return "not a regular file";
}

[[noreturn]] void refuse(const fs::path& path, const std::string& what) {
  throw GoldenPathError(
      fmt::format("{}: {}; a golden must be a plain file inside the golden folder "
                  "(docs/guide/goldens.md)",
                  path.string(), what));
}

// GOLDEN/<name>, opened without following a link: -1 when it does not exist.
int open_name_folder(const fs::path& path) {
  const fs::path folder = path.parent_path();
  const fs::path root = folder.parent_path().empty() ? fs::path(".") : folder.parent_path();
  Descriptor root_fd{::open(root.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)};
  if (root_fd.fd < 0) {
    if (errno == ENOENT) return -1;
    throw GoldenError(fmt::format("{}: cannot open the golden folder ({})", root.string(), std::strerror(errno)));
  }
  const int fd = ::openat(root_fd.fd, folder.filename().c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd >= 0) return fd;
  if (errno == ENOENT) return -1;
  if (errno == ELOOP) refuse(folder, "it is a symbolic link");
  if (errno == ENOTDIR) {
    struct stat status {};
    if (::fstatat(root_fd.fd, folder.filename().c_str(), &status, AT_SYMLINK_NOFOLLOW) == 0 &&
        S_ISLNK(status.st_mode)) {
      refuse(folder, "it is a symbolic link");
    }
    refuse(folder, "it is not a directory");
  }
  throw GoldenError(fmt::format("{}: cannot open ({})", folder.string(), std::strerror(errno)));
}

}  // namespace

void check_golden_folder(const fs::path& path) { const Descriptor folder{open_name_folder(path)}; }

std::optional<std::string> read_golden_file(const fs::path& path, std::size_t max_bytes) {
  const Descriptor folder{open_name_folder(path)};
  if (folder.fd < 0) return std::nullopt;
  // O_NONBLOCK: opening a FIFO does not wait for a writer; it is refused below.
  Descriptor file{::openat(folder.fd, path.filename().c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) {
    if (errno == ENOENT) return std::nullopt;
    if (errno == ELOOP) refuse(path, "it is a symbolic link");
    throw GoldenError(fmt::format("{}: cannot open the golden file ({})", path.string(), std::strerror(errno)));
  }
  struct stat status {};
  if (::fstat(file.fd, &status) != 0) {
    throw GoldenError(fmt::format("{}: cannot read the golden file ({})", path.string(), std::strerror(errno)));
  }
  if (!S_ISREG(status.st_mode)) refuse(path, "it is " + kind_of(status.st_mode));
  if (static_cast<std::size_t>(status.st_size) > max_bytes) {
    throw GoldenError(fmt::format("{}: the golden file is larger than the limit of {} MiB", path.string(),
                                  max_bytes / (1024 * 1024)));
  }
  std::string bytes;
  char chunk[1 << 16];
  while (bytes.size() <= max_bytes) {
    const ssize_t n = ::read(file.fd, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      throw GoldenError(fmt::format("{}: cannot read the golden file ({})", path.string(), std::strerror(errno)));
    }
    if (n == 0) break;
    bytes.append(chunk, static_cast<std::size_t>(n));
  }
  if (bytes.size() > max_bytes) {  // grew while read
    throw GoldenError(fmt::format("{}: the golden file is larger than the limit of {} MiB", path.string(),
                                  max_bytes / (1024 * 1024)));
  }
  return bytes;
}

}  // namespace pita::golden
