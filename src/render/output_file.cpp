#include "render/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

namespace pita::render {

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : ".";
  std::string name = path.filename().string();
  name.insert(0, 1, '.');
  name.append(".XXXXXX");
  std::string temp = (dir / name).string();
  const int fd = mkstemp(temp.data());
  if (fd < 0) {
    throw OutputError(path.string() + ": cannot create a temporary file in " + dir.string() +
                             " (" + std::strerror(errno) + ")");
  }
  const auto fail = [&](const char* what) {
    const int saved = errno;
    close(fd);
    std::remove(temp.c_str());
    throw OutputError(path.string() + ": " + what + " (" + std::strerror(saved) + ")");
  };
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("cannot write");
    }
    written += static_cast<std::size_t>(n);
  }
  // mkstemp creates 0600; outputs are ordinary files (0644 less the umask).
  const mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, 0666 & ~mask);
  if (close(fd) != 0) {
    std::remove(temp.c_str());
    throw OutputError(path.string() + ": cannot write (" + std::strerror(errno) + ")");
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    const int saved = errno;
    std::remove(temp.c_str());
    throw OutputError(path.string() + ": cannot rename the finished file into place (" +
                             std::strerror(saved) + ")");
  }
}

}  // namespace pita::render
