// The output folder of a sweep (docs/reference/sweep.md "pita sweep"): pita
// writes only into a folder that is new, empty or a sweep's own (it carries
// the marker file .pita-sweep); one run at a time writes each manifest (an
// advisory lock, flock(2), on a hidden file beside it); and a resumed run
// removes the hidden temporaries a killed run of the same shard left.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "io/output_file.hpp"
#include "sweep/grid.hpp"

namespace pita::sweep {

// The marker of a folder that a sweep made.
inline constexpr std::string_view kFolderMarker = ".pita-sweep";

// An output refused for the folder a sweep was given (exit 3), about its input.
using SweepOutputError = AboutInput<io::OutputError>;

// Creates DIR when missing and marks it as a sweep's. Throws
// SweepOutputError (exit 3) when DIR holds files and is not a sweep's
// folder, or when its sweep.json is the base scene itself; SweepUsageError
// when DIR cannot be created. `given`: DIR as the user gave it (the output).
void claim_folder(const std::filesystem::path& dir, const std::string& given, const std::filesystem::path& base_scene);

// A folder a sweep writes and removes files in, inside DIR (index/): absent,
// or a folder of its own, never a symbolic link (files of the folder it leads
// to would be removed) or a file. Throws io::OutputError (exit 3) naming it.
void check_own_subfolder(const std::filesystem::path& folder);

// Holds the lock of DIR/<manifest> while it lives. Another holder: throws
// SweepUsageError (exit 2) naming its PID, about `about` with the remedy
// wait, or with `wait` waits for it.
class FolderLock {
 public:
  FolderLock(const std::filesystem::path& dir, const std::string& manifest, About about, bool wait);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
};

// Removes DIR's hidden temporaries (".<target>.XXXXXX", output_file.hpp) whose
// target `mine` accepts; returns how many. Call it holding the lock.
std::int64_t remove_stale_temporaries(const std::filesystem::path& dir,
                                      const std::function<bool(const std::string& target)>& mine);

}  // namespace pita::sweep
