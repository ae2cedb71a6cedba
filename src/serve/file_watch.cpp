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

// A save of a file in a watched folder, or a folder made (or moved) where a
// watched folder belongs; and the watched folder's own removal or move.
constexpr std::uint32_t kEvents =
    IN_CLOSE_WRITE | IN_MOVED_TO | IN_DELETE | IN_CREATE | IN_DELETE_SELF | IN_MOVE_SELF | IN_ONLYDIR;

// Passes of a re-watch at most (a folder made again between a failed watch
// and the watch of its parent).
constexpr int kMaxPasses = 8;

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

// Whether `inner` is `outer` or lies under it (both absolute and normal).
bool within(const fs::path& inner, const fs::path& outer) {
  auto i = inner.begin();
  for (auto o = outer.begin(); o != outer.end(); ++o, ++i) {
    if (o->empty()) continue;  // a trailing separator
    if (i == inner.end() || *i != *o) return false;
  }
  return true;
}

// The child of `ancestor` on the way to `folder` (ancestor lies above it).
fs::path next_toward(const fs::path& ancestor, const fs::path& folder) {
  fs::path next = ancestor;
  auto f = folder.begin();
  for (auto a = ancestor.begin(); a != ancestor.end() && f != folder.end(); ++a, ++f) {
  }
  if (f != folder.end()) next /= *f;
  return next;
}

}  // namespace

FileWatcher::FileWatcher() : fd_(::inotify_init1(IN_CLOEXEC | IN_NONBLOCK)) {
  if (fd_ < 0) throw std::system_error(errno, std::generic_category(), "inotify_init1");
}

FileWatcher::~FileWatcher() { ::close(fd_); }

void FileWatcher::watch(const std::vector<fs::path>& files) {
  // A folder given now for the first time must exist; one watched before
  // that is gone now is watched through its nearest ancestor until it is
  // made again.
  std::set<fs::path> before;
  for (const auto& [where, file] : files_) before.insert(where.parent_path());
  given_.clear();
  for (const fs::path& file : files) given_.push_back(normal(file));
  std::set<fs::path> ignored;
  rewatch(ignored, &before);
}

void FileWatcher::rewatch(std::set<fs::path>& saved, const std::set<fs::path>* strict_unless) {
  std::map<fs::path, fs::path> named;
  std::set<fs::path> folders;
  for (const fs::path& given : given_) {
    named[given] = given;
    folders.insert(given.parent_path());
    std::error_code error;
    const fs::path target = fs::weakly_canonical(given, error);
    if (!error && target != given) {
      named[target] = given;
      folders.insert(target.parent_path());
    }
  }
  std::set<fs::path> had_own;  // the folders watched as themselves before
  for (const auto& [descriptor, paths] : folders_) {
    for (const fs::path& path : paths) {
      if (folders.count(path) != 0) had_own.insert(path);
    }
  }
  // New watches first: a folder watched already keeps its descriptor, and
  // the events queued on it.
  std::map<int, std::set<fs::path>> watched;
  std::set<fs::path> own;
  for (const fs::path& folder : folders) {
    for (int pass = 0; pass < kMaxPasses; ++pass) {
      fs::path at = folder;
      int descriptor = -1;
      while (true) {
        descriptor = ::inotify_add_watch(fd_, at.c_str(), kEvents);
        if (descriptor >= 0) break;
        const int error = errno;
        if (strict_unless != nullptr && at == folder && strict_unless->count(folder) == 0) {
          throw std::system_error(error, std::generic_category(), "cannot watch the folder " + folder.string());
        }
        if (at == at.root_path() || !at.has_parent_path() || at.parent_path() == at) break;
        at = at.parent_path();  // gone (or not to be watched): wait for it in its parent
      }
      if (descriptor < 0) break;  // not even the root: nothing to watch it by
      watched[descriptor].insert(at);
      if (at == folder) {
        own.insert(folder);
        break;
      }
      // Made between the failed watch and this one: its creation was not seen.
      std::error_code error;
      if (!fs::is_directory(next_toward(at, folder), error)) break;
    }
  }
  for (const auto& [descriptor, paths] : folders_) {
    if (watched.count(descriptor) == 0) ::inotify_rm_watch(fd_, descriptor);
  }
  folders_ = std::move(watched);
  files_ = std::move(named);
  // A folder watched again: its files there now were saved (made with it, or
  // since it was made).
  for (const auto& [where, file] : files_) {
    const fs::path folder = where.parent_path();
    std::error_code error;
    if (own.count(folder) != 0 && had_own.count(folder) == 0 && strict_unless == nullptr && fs::exists(where, error)) {
      saved.insert(file);
    }
  }
}

void FileWatcher::drain(std::set<fs::path>& saved) {
  alignas(inotify_event) std::array<char, 16384> buffer{};
  bool moved = false;  // a watched folder or one of its ancestors was removed, moved or made
  while (true) {
    const ssize_t got = ::read(fd_, buffer.data(), buffer.size());
    if (got < 0) {
      if (errno == EINTR) continue;
      if (errno == EAGAIN) break;
      throw std::system_error(errno, std::generic_category(), "read from inotify");
    }
    if (got == 0) break;
    for (ssize_t at = 0; at < got;) {
      const auto* event = reinterpret_cast<const inotify_event*>(buffer.data() + at);
      at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
      if ((event->mask & IN_Q_OVERFLOW) != 0) {  // events were lost: every file may have changed
        for (const auto& [where, file] : files_) saved.insert(file);
        moved = true;
        continue;
      }
      const auto folder = folders_.find(event->wd);
      if (folder == folders_.end()) continue;
      if ((event->mask & (IN_DELETE_SELF | IN_MOVE_SELF | IN_IGNORED)) != 0) {
        moved = true;
        continue;
      }
      if (event->len == 0) continue;
      for (const fs::path& path : folder->second) {
        const fs::path named = path / event->name;
        const auto file = files_.find(named);
        if (file != files_.end()) saved.insert(file->second);
        // A folder made, moved in or removed on the way to a watched one.
        for (const auto& [where, watched] : files_) {
          if (within(where.parent_path(), named)) moved = true;
        }
      }
    }
  }
  if (moved) rewatch(saved, nullptr);
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
