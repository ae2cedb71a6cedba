#include "sweep/folder.hpp"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string_view>
#include <system_error>

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/output_file.hpp"
#include "sweep/definition.hpp"
#include "sweep/grid.hpp"

namespace pita::sweep {

namespace {

namespace fs = std::filesystem;

// ".<target>.XXXXXX" -> "<target>", or "" when `name` is not a temporary.
std::string temporary_target(std::string_view name) {
  constexpr std::size_t kSuffix = 7;  // ".XXXXXX" (mkstemp)
  if (name.size() < 1 + 1 + kSuffix || name.front() != '.' || name[name.size() - kSuffix] != '.') return {};
  for (std::size_t i = name.size() - kSuffix + 1; i < name.size(); ++i) {
    if (std::isalnum(static_cast<unsigned char>(name[i])) == 0) return {};
  }
  return std::string(name.substr(1, name.size() - 1 - kSuffix));
}

// A folder a sweep made: the marker, or (made before the marker existed) a
// sweep.json that is a sweep definition.
bool is_sweep_folder(const fs::path& dir) {
  std::error_code error;
  if (fs::is_regular_file(fs::symlink_status(dir / kFolderMarker, error))) return true;
  if (!fs::is_regular_file(fs::symlink_status(dir / kSweepFile, error))) return false;
  try {
    (void)read_definition(dir);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

// pita's own hidden files in a sweep's folder: locks and journals of
// manifests (.manifest.csv.lock, .manifest.0-of-2.csv.journal).
bool is_own_hidden_file(const std::string& name) {
  return name.starts_with(".manifest.") && (name.ends_with(".lock") || name.ends_with(".journal"));
}

// The folder of per-task logs that the Slurm recipe creates before any task
// runs (scripts/slurm-sweep.sbatch --logs, default OUT/logs).
constexpr std::string_view kLogsFolder = "logs";

// The first entry that is neither the marker, nor its temporary, nor a
// manifest's lock or journal, nor the logs folder, to name in the refusal; "" when there is none
// or when the marker itself is listed (a concurrent shard wrote it after
// is_sweep_folder looked: it comes first, before any of that shard's files).
std::string first_foreign_entry(const fs::path& dir) {
  std::error_code error;
  std::string foreign;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, error)) {
    const std::string name = entry.path().filename().string();
    if (name == kFolderMarker) return {};
    if (temporary_target(name) == kFolderMarker || is_own_hidden_file(name)) continue;
    if (name == kLogsFolder && entry.is_directory(error)) continue;
    if (foreign.empty()) foreign = name;
  }
  return foreign;
}

}  // namespace

void claim_folder(const fs::path& dir, const std::string& given, const fs::path& base_scene) {
  const About about{Input::output, given};
  std::error_code error;
  const fs::file_status status = fs::symlink_status(dir, error);
  if (fs::exists(status) && !fs::is_directory(fs::status(dir, error))) {
    throw SweepUsageError(about, "cannot create the output folder (a file of that name exists)");
  }
  fs::create_directories(dir, error);
  if (error || !fs::is_directory(dir)) {
    throw SweepUsageError(about, fmt::format("cannot create the output folder ({})",
                                             error ? error.message() : "a file of that name exists"));
  }
  if (fs::equivalent(dir / kSweepFile, base_scene, error)) {
    throw SweepOutputError(about, fmt::format("cannot write: the sweep's definition {} would replace the base scene "
                                              "{}; give another output folder",
                                              (dir / kSweepFile).string(), base_scene.string()));
  }
  try {
    check_own_subfolder(dir / "index");
  } catch (const io::OutputError& subfolder) {
    throw SweepOutputError(about, subfolder.what());
  }
  if (!is_sweep_folder(dir)) {
    if (const std::string other = first_foreign_entry(dir); !other.empty()) {
      throw SweepOutputError(
          about, fmt::format("cannot write: the folder holds files that a sweep did not write ({} among them; a "
                             "sweep's folder has a {} file); give a new or empty folder, so that nothing of yours "
                             "is replaced",
                             other, kFolderMarker));
    }
    io::write_file_atomically(dir / kFolderMarker, "This folder is the output of pita sweep.\n");
  }
}

void check_own_subfolder(const fs::path& folder) {
  std::error_code error;
  const fs::file_status status = fs::symlink_status(folder, error);
  if (fs::is_symlink(status) || (fs::exists(status) && !fs::is_directory(status))) {
    throw io::OutputError(fmt::format("{}: cannot write: it is {}, not the sweep's own folder; remove it",
                                      folder.string(), fs::is_symlink(status) ? "a symbolic link" : "a file"));
  }
}

FolderLock::FolderLock(const fs::path& dir, const std::string& manifest, About about, bool wait) {
  const fs::path path = dir / ("." + manifest + ".lock");
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd_ < 0) {
    throw io::OutputError(fmt::format("{}: cannot create the lock file ({})", path.string(), std::strerror(errno)));
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    if (errno == ENOSYS || errno == EOPNOTSUPP || errno == ENOLCK) {
      // A file system without locks (Lustre mounted noflock, some NFS): run
      // unguarded, as before locks existed, and say so.
      std::fprintf(stderr, "pita: %s: cannot lock (%s): run one sweep at a time into this folder\n", path.c_str(),
                   std::strerror(errno));
      ::close(fd_);
      fd_ = -1;
      return;
    }
    if (errno != EWOULDBLOCK) {
      const int saved = errno;
      ::close(fd_);
      throw io::OutputError(fmt::format("{}: cannot lock ({})", path.string(), std::strerror(saved)));
    }
    if (!wait) {
      char text[32] = {};
      const ssize_t n = ::pread(fd_, text, sizeof text - 1, 0);
      std::string pid(text, n > 0 ? static_cast<std::size_t>(n) : 0);
      while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
      ::close(fd_);
      fd_ = -1;
      about.remedy = Input::wait;
      throw SweepUsageError(std::move(about),
                            fmt::format("another pita sweep ({}) is writing {} there; wait for it to finish",
                                        pid.empty() ? std::string("its PID unknown") : "PID " + pid, manifest));
    }
    while (::flock(fd_, LOCK_EX) != 0) {
      if (errno != EINTR) {
        const int saved = errno;
        ::close(fd_);
        throw io::OutputError(fmt::format("{}: cannot lock ({})", path.string(), std::strerror(saved)));
      }
    }
  }
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
    // The lock holds without the PID; only the message of a refused run loses it.
  }
}

FolderLock::~FolderLock() {
  // The file stays: removing it would let a waiting run lock a file no
  // longer in the folder while a third run creates a new one.
  if (fd_ >= 0) ::close(fd_);
}

std::int64_t remove_stale_temporaries(const fs::path& dir, const std::function<bool(const std::string&)>& mine) {
  std::int64_t removed = 0;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, error)) {
    const std::string target = temporary_target(entry.path().filename().string());
    if (target.empty() || !mine(target)) continue;
    if (!fs::is_regular_file(entry.symlink_status(error))) continue;
    if (fs::remove(entry.path(), error)) ++removed;
  }
  return removed;
}

}  // namespace pita::sweep
