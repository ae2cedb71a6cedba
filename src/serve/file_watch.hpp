// Saves of a set of files, as `pita watch` and `pita serve` wait for them
// (inotify). Editors save in place or write a new file and rename it over the
// old one, so the folders of the files are watched, and a file counts as
// saved when a writer closes it, a file is renamed to its name, or it is
// deleted (the next read says so). A file reached through a symbolic link is
// watched in the folder of its target too (an editor may write the target).
// A watched folder that is removed or moved away is watched through its
// nearest existing ancestor until it is made again; then it is watched again,
// and its files found there count as saved.
#pragma once

#include <chrono>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace pita::serve {

class FileWatcher {
 public:
  // Throws std::system_error when inotify is not available.
  FileWatcher();
  ~FileWatcher();
  FileWatcher(const FileWatcher&) = delete;
  FileWatcher& operator=(const FileWatcher&) = delete;

  // Watches these files (replacing the set watched before; folders watched
  // before and now keep their watch, and the events queued on it). A folder
  // that cannot be watched throws std::system_error naming it, unless it was
  // watched before (removed since: it is waited for in its ancestor).
  void watch(const std::vector<std::filesystem::path>& files);

  // The watched files saved since the last call, waiting up to `timeout` for
  // the first one; empty when none was. A burst of events (an editor's
  // write, rename and attribute change) is gathered into one answer: after
  // the first event it waits until `quiet` passes without another.
  std::set<std::filesystem::path> wait(std::chrono::milliseconds timeout,
                                       std::chrono::milliseconds quiet = std::chrono::milliseconds(40));

 private:
  // Reads the pending events; adds the watched files they concern to `saved`.
  void drain(std::set<std::filesystem::path>& saved);
  // Watches the folders of given_, each folder that is gone through its
  // nearest existing ancestor; adds to `saved` the files of a folder watched
  // again that exist. With `strict_unless`, a folder not in it that cannot be
  // watched throws.
  void rewatch(std::set<std::filesystem::path>& saved, const std::set<std::filesystem::path>* strict_unless);

  int fd_ = -1;
  std::vector<std::filesystem::path> given_;  // the files, absolute and lexically normal
  // watch descriptor -> the folders it watches (itself, or the ancestor of a folder that is gone)
  std::map<int, std::set<std::filesystem::path>> folders_;
  // Where an event may name a watched file (absolute, lexically normal: the
  // file, and the target of its links) -> the file as watch() was given it.
  std::map<std::filesystem::path, std::filesystem::path> files_;
};

}  // namespace pita::serve
