#include "serve/file_watch.hpp"

#include <array>
#include <cerrno>
#include <cstring>
#include <system_error>

#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

namespace pita::serve {

namespace fs = std::filesystem;

namespace {

constexpr std::uint32_t kSaveEvents = IN_CLOSE_WRITE | IN_MOVED_TO | IN_DELETE | IN_CREATE;

fs::path normal(const fs::path& file) { return fs::absolute(file).lexically_normal(); }

// Whether an event arrives within `wait` on `fd`.
bool readable(int fd, std::chrono::milliseconds wait) {
  pollfd one{fd, POLLIN, 0};
  while (true) {
    const int ready = ::poll(&one, 1, static_cast<int>(wait.count()));
    if (ready >= 0) return ready > 0;
    if (errno != EINTR) throw std::system_error(errno, std::generic_category(), "poll on inotify");
  }
}

}  // namespace

FileWatcher::FileWatcher() : fd_(::inotify_init1(IN_CLOEXEC | IN_NONBLOCK)) {
  if (fd_ < 0) throw std::system_error(errno, std::generic_category(), "inotify_init1");
}

FileWatcher::~FileWatcher() { ::close(fd_); }

void FileWatcher::watch(const std::vector<fs::path>& files) {
  std::map<fs::path, fs::path> named;
  std::set<fs::path> folders;
  for (const fs::path& file : files) {
    const fs::path given = normal(file);
    named[given] = given;
    folders.insert(given.parent_path());
    std::error_code error;
    const fs::path target = fs::weakly_canonical(given, error);
    if (!error && target != given) {
      named[target] = given;
      folders.insert(target.parent_path());
    }
  }
  // New watches first: a folder watched already keeps its descriptor, and
  // the events queued on it.
  std::map<int, fs::path> watched;
  for (const fs::path& folder : folders) {
    const int descriptor = ::inotify_add_watch(fd_, folder.c_str(), kSaveEvents);
    if (descriptor < 0) {
      throw std::system_error(errno, std::generic_category(), "cannot watch the folder " + folder.string());
    }
    watched[descriptor] = folder;
  }
  for (const auto& [descriptor, folder] : folders_) {
    if (watched.count(descriptor) == 0) ::inotify_rm_watch(fd_, descriptor);
  }
  folders_ = std::move(watched);
  files_ = std::move(named);
}

void FileWatcher::drain(std::set<fs::path>& saved) {
  alignas(inotify_event) std::array<char, 16384> buffer{};
  while (true) {
    const ssize_t got = ::read(fd_, buffer.data(), buffer.size());
    if (got < 0) {
      if (errno == EINTR) continue;
      if (errno == EAGAIN) return;
      throw std::system_error(errno, std::generic_category(), "read from inotify");
    }
    if (got == 0) return;
    for (ssize_t at = 0; at < got;) {
      const auto* event = reinterpret_cast<const inotify_event*>(buffer.data() + at);
      at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
      if ((event->mask & IN_Q_OVERFLOW) != 0) {  // events were lost: every file may have changed
        for (const auto& [where, file] : files_) saved.insert(file);
        continue;
      }
      const auto folder = folders_.find(event->wd);
      if (folder == folders_.end() || event->len == 0) continue;
      const auto file = files_.find(folder->second / event->name);
      if (file != files_.end()) saved.insert(file->second);
    }
  }
}

std::set<fs::path> FileWatcher::wait(std::chrono::milliseconds timeout, std::chrono::milliseconds quiet) {
  std::set<fs::path> saved;
  if (!readable(fd_, timeout)) return saved;
  drain(saved);
  // A burst: wait for a quiet moment (at most half a second), so that a
  // save in several steps is one answer. Events of other files are dropped
  // (they end the wait for quiet as well).
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::milliseconds(500);
  while (std::chrono::steady_clock::now() < give_up && readable(fd_, quiet)) drain(saved);
  return saved;
}

}  // namespace pita::serve
