// An LD_PRELOAD shim for the CLI tests of interruption and of all-or-none
// writes (tests/cli/test_interrupt.cpp, test_render_outputs.cpp). It takes over
// rename(2), the commit step of every output (src/io/output_file.cpp), so
// that a test can catch pita with its temporaries written but not yet renamed,
// however fast the write, or make one rename fail, as a full or read-only file
// system could. Without its variables it is the system's rename.
//
//   PITA_TEST_PAUSE_BEFORE_RENAME=FILE  at the first rename, create FILE (the
//       test waits for it) and wait for signals, forever.
//   PITA_TEST_PAUSE_AT=NAME             with the above: pause at the first
//       rename onto a file named NAME instead.
//   PITA_TEST_FAIL_RENAME_TO=NAME       a rename onto a file named NAME fails
//       with EIO.
//
// Not <cstdio>: it declares rename, with another exception specification.
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include <dlfcn.h>
#include <fcntl.h>
#include <unistd.h>

namespace {

bool is_named(const char* path, const char* name) {
  const char* slash = std::strrchr(path, '/');
  return std::strcmp(slash != nullptr ? slash + 1 : path, name) == 0;
}

}  // namespace

extern "C" int rename(const char* from, const char* to) {
  using Rename = int (*)(const char*, const char*);
  static const Rename next = reinterpret_cast<Rename>(::dlsym(RTLD_NEXT, "rename"));
  if (const char* marker = std::getenv("PITA_TEST_PAUSE_BEFORE_RENAME")) {
    const char* at = std::getenv("PITA_TEST_PAUSE_AT");
    if (at == nullptr || is_named(to, at)) {
      const int fd = ::open(marker, O_WRONLY | O_CREAT, 0644);
      if (fd >= 0) ::close(fd);
      for (;;) ::pause();  // a handler that returns would come back here
    }
  }
  if (const char* name = std::getenv("PITA_TEST_FAIL_RENAME_TO"); name != nullptr && is_named(to, name)) {
    errno = EIO;
    return -1;
  }
  return next(from, to);
}
