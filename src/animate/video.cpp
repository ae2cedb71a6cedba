#include "animate/video.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>

#include <cairo.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "animate/frame.hpp"
#include "animate/frame_runner.hpp"
#include "animate/progress.hpp"
#include "io/interrupt.hpp"
#include "io/output_file.hpp"
#include "render/backdrop.hpp"
#include "render/budget.hpp"
#include "render/panel_drawing.hpp"
#include "render/static_layers.hpp"

extern char** environ;

namespace pita::animate {

namespace fs = std::filesystem;

namespace {

using detail::ordinary_mode;
using detail::output_failed;

// A temporary beside `target` (".name.XXXXXX"), registered with the interrupt
// cleanup until released.
class TemporaryFile {
 public:
  explicit TemporaryFile(const fs::path& target) : reservation_(1), target_(target) {
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    const std::string pattern = (folder / ("." + target.filename().string() + ".XXXXXX")).string();
    slot_ = io::register_in_flight(pattern);
    if (slot_ < 0) output_failed(target, std::strerror(ENAMETOOLONG));  // a slot is reserved
    const int fd = ::mkstemp(io::slot_path(slot_));
    if (fd < 0) {
      const std::string reason = std::strerror(errno);
      io::release_in_flight(slot_);
      output_failed(target, reason);
    }
    ::close(fd);
    path_ = io::slot_path(slot_);
  }
  ~TemporaryFile() {
    if (slot_ >= 0) {
      ::unlink(path_.c_str());
      io::release_in_flight(slot_);
    }
  }
  const std::string& path() const { return path_; }
  void commit() {
    ::chmod(path_.c_str(), ordinary_mode(0666));
    if (::rename(path_.c_str(), target_.c_str()) != 0) output_failed(target_, std::strerror(errno));
    io::release_in_flight(slot_);
    slot_ = -1;
  }

 private:
  io::InFlightReservation reservation_;  // released after the slot
  fs::path target_;
  std::string path_;
  int slot_ = -1;
};

// The raw pixels of a frame for ffmpeg: cairo's ARGB32 rows (B, G, R, A in
// memory), `width` x `height`, no padding.
std::string raw_frame(const scene::Scene& scene, const render::Figure& figure, const render::FrameBackdrop& backdrop,
                      int width, int height) {
  const render::SurfacePtr surface = backdrop.paint(figure);
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) {
    throw render::RenderError(scene.path, "", "cairo could not draw a frame");
  }
  const int stride = cairo_image_surface_get_stride(surface.get());
  const unsigned char* data = cairo_image_surface_get_data(surface.get());
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y) {
    bytes.append(reinterpret_cast<const char*>(data + static_cast<std::ptrdiff_t>(y) * stride),
                 static_cast<std::size_t>(width) * 4);
  }
  return bytes;
}

// ffmpeg's arguments: raw BGRA frames on its standard input, encoded to
// `path` as H.264 in MP4, or VP9 in WebM.
std::vector<std::string> ffmpeg_arguments(const std::string& ffmpeg, int width, int height, double fps, bool webm,
                                          const std::string& path) {
  // -xerror: stop at the first error instead of finishing a broken file.
  std::vector<std::string> args = {ffmpeg, "-hide_banner", "-loglevel", "error", "-xerror", "-y", "-f", "rawvideo",
                                   "-pix_fmt", "bgra", "-s", fmt::format("{}x{}", width, height), "-framerate",
                                   fmt::format("{:.17g}", fps), "-i", "pipe:0", "-an",
                                   // yuv420p needs even sides.
                                   "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2:color=white", "-pix_fmt", "yuv420p"};
  if (webm) {
    for (const char* a :
         {"-c:v", "libvpx-vp9", "-b:v", "0", "-crf", "34", "-deadline", "realtime", "-cpu-used", "8", "-f", "webm"})
      args.emplace_back(a);
  } else {
    for (const char* a :
         {"-c:v", "libx264", "-preset", "veryfast", "-crf", "20", "-movflags", "+faststart", "-f", "mp4"})
      args.emplace_back(a);
  }
  args.push_back(path);
  return args;
}

// What a child process wrote to its standard error, kept in an anonymous
// file (memfd) to be read after it exits: ffmpeg reports some failures
// ("Error writing trailer", on a full disk or a file-size limit) only there,
// and exits 0.
class CapturedStderr {
 public:
  CapturedStderr() : fd_(::memfd_create("pita-child-stderr", MFD_CLOEXEC)) {}
  ~CapturedStderr() {
    if (fd_ >= 0) ::close(fd_);
  }
  CapturedStderr(const CapturedStderr&) = delete;
  CapturedStderr& operator=(const CapturedStderr&) = delete;
  // The child's stderr goes into it (when the memfd could not be made, the
  // child keeps pita's stderr).
  void redirect(posix_spawn_file_actions_t& actions) const {
    if (fd_ >= 0) posix_spawn_file_actions_adddup2(&actions, fd_, STDERR_FILENO);
  }
  // Its last 16 KiB.
  std::string text() const {
    std::string out;
    if (fd_ < 0) return out;
    const off_t size = ::lseek(fd_, 0, SEEK_END);
    const off_t from = std::max<off_t>(0, size - (16 << 10));
    out.resize(static_cast<std::size_t>(size - from));
    const ssize_t n = ::pread(fd_, out.data(), out.size(), from);
    out.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
    return out;
  }

 private:
  int fd_;
};

// The last non-empty line of `text`, for a message.
std::string last_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  const std::size_t at = text.find_last_of('\n');
  return at == std::string::npos ? text : text.substr(at + 1);
}

// Starts `args` with `actions` (destroyed here) in a process group of its
// own, as ffmpeg and ffprobe run: a terminal's Ctrl-C reaches pita, which
// decides. posix_spawn's result (0 when started).
int spawn_in_own_group(std::vector<std::string>& args, posix_spawn_file_actions_t& actions, pid_t& child) {
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const int spawned = ::posix_spawn(&child, args.front().c_str(), &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  return spawned;
}

// Runs `args` (stdin and stdout from /dev/null, stderr captured); its wait
// status, or -1 when it cannot be started.
int run_quietly(std::vector<std::string> args, std::string& err) {
  CapturedStderr captured;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  captured.redirect(actions);
  pid_t child = -1;
  if (spawn_in_own_group(args, actions, child) != 0) return -1;
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  err = captured.text();
  return status;
}

// The finished video, checked before it is committed: not empty, and when
// ffprobe is installed beside ffmpeg, its container readable by it (headers
// and index; with -xerror and the stderr check, what ffmpeg failed to write
// is caught before this).
void verify_video(const std::string& ffmpeg, const std::string& path, const fs::path& out) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0 || status.st_size == 0) {
    output_failed(out, "ffmpeg wrote an empty file");
  }
  const fs::path ffprobe = fs::path(ffmpeg).parent_path() / "ffprobe";
  if (ffmpeg.find('/') == std::string::npos || ::access(ffprobe.c_str(), X_OK) != 0) return;
  std::string err;
  const int probed = run_quietly({ffprobe.string(), "-v", "error", "-show_entries", "format=duration", path}, err);
  if (probed == -1) return;  // ffprobe could not start: the size check stands
  if (!WIFEXITED(probed) || WEXITSTATUS(probed) != 0 || !err.empty()) {
    output_failed(out, fmt::format("the video ffmpeg wrote is not readable ({}: {})", ffprobe.string(),
                                   err.empty() ? "failed" : last_line(err)));
  }
}

// ffmpeg running with a pipe to its standard input, in its own process group
// (a terminal's Ctrl-C reaches pita, which stops it and removes the file
// itself). While it runs, a write to a dead ffmpeg fails with EPIPE instead
// of killing pita. Its stderr is captured (CapturedStderr) and passed on to
// pita's when it ends.
class FfmpegProcess {
 public:
  FfmpegProcess(std::vector<std::string> args, const fs::path& out) {
    int pipe_fds[2];
    if (::pipe2(pipe_fds, O_CLOEXEC) != 0) output_failed(out, std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[0], STDIN_FILENO);
    stderr_.redirect(actions);
    const int spawned = spawn_in_own_group(args, actions, child_);
    ::close(pipe_fds[0]);
    if (spawned != 0) {
      ::close(pipe_fds[1]);
      throw AnimationError(fmt::format("-o {}: cannot run {}: {}", out.string(), args.front(), std::strerror(spawned)));
    }
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    ::sigaction(SIGPIPE, &ignore, &previous_);
    pipe_ = pipe_fds[1];
  }
  FfmpegProcess(const FfmpegProcess&) = delete;
  FfmpegProcess& operator=(const FfmpegProcess&) = delete;
  ~FfmpegProcess() {
    if (child_ > 0) stop(true);
  }

  // Writes all of `bytes`; false when ffmpeg stopped reading. Throws
  // Interrupted when a signal is pending.
  bool write(const std::string& bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::write(pipe_, bytes.data() + done, bytes.size() - done);
      if (n < 0 && errno == EINTR) {
        if (const int sig = io::pending_interrupt()) throw Interrupted{sig};
        continue;
      }
      if (n <= 0) return false;
      done += static_cast<std::size_t>(n);
    }
    return true;
  }

  // Closes the pipe (ffmpeg finishes the file), or kills ffmpeg; waits for it.
  // Returns its wait status.
  int stop(bool kill_it) {
    if (pipe_ >= 0) ::close(pipe_);
    pipe_ = -1;
    if (kill_it) ::kill(child_, SIGKILL);
    int status = 0;
    while (::waitpid(child_, &status, 0) < 0 && errno == EINTR) {
    }
    child_ = -1;
    ::sigaction(SIGPIPE, &previous_, nullptr);
    errors_ = stderr_.text();
    if (!errors_.empty()) std::fputs(errors_.c_str(), stderr);  // what ffmpeg said, as it said it
    return status;
  }

  // What ffmpeg wrote to its stderr (at -loglevel error: only errors).
  const std::string& errors() const { return errors_; }

 private:
  CapturedStderr stderr_;
  std::string errors_;
  pid_t child_ = -1;
  int pipe_ = -1;
  struct sigaction previous_ {};
};

}  // namespace

fs::path write_video(const scene::Scene& scene, const Timeline& timeline, const Request& request,
                     const motion::Stage* stage, render::StaticLayers* layers,
                     const std::vector<render::PanelPlacement>& placements) {
  const std::string& ffmpeg = request.ffmpeg;
  if (ffmpeg.empty()) {
    throw AnimationError(
        fmt::format("-o {}: writing video needs ffmpeg, which is not installed (install the Debian "
                    "package: apt-get install ffmpeg), or write an animated .svg or a directory "
                    "of frames instead",
                    request.out.string()));
  }
  const int width = static_cast<int>(std::round(scene.canvas.width * request.scale));
  const int height = static_cast<int>(std::round(scene.canvas.height * request.scale));
  render::check_pixel_budget(scene, request.scale, request.budget);
  TemporaryFile temporary(request.out);
  FfmpegProcess process(
      ffmpeg_arguments(ffmpeg, width, height, timeline.fps, request.kind == AnimationOutput::webm, temporary.path()),
      request.out);
  // Every frame is painted over the layers they share, painted once.
  const render::FrameBackdrop backdrop(
      scene, frame_figure(scene, timeline, timeline.time(0), placements, stage, layers), width, height, request.scale);
  Progress progress("video", timeline.frames, request.progress);
  try {
    run_frames(
        timeline.frames, request.threads,
        [&](int k) {
          const render::Figure figure = frame_figure(scene, timeline, timeline.time(k), placements, stage, layers);
          return raw_frame(scene, figure, backdrop, width, height);
        },
        [&](int k, std::string&& bytes) {
          if (!process.write(bytes)) {
            throw io::OutputError(
                fmt::format("{}: cannot write: ffmpeg stopped reading (see its message above)", request.out.string()));
          }
          progress.update(k + 1);
        },
        request.cancelled);
  } catch (const Interrupted& interrupted) {
    process.stop(true);
    ::unlink(temporary.path().c_str());
    stop_interrupted(interrupted.signal);
  } catch (...) {
    process.stop(true);
    throw;
  }
  const int status = process.stop(false);
  if (const int sig = pending_stop(request.cancelled)) {
    ::unlink(temporary.path().c_str());
    stop_interrupted(sig);
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    output_failed(request.out, fmt::format("ffmpeg failed ({})",
                                           WIFEXITED(status) ? fmt::format("exit status {}", WEXITSTATUS(status))
                                                             : fmt::format("signal {}", WTERMSIG(status))));
  }
  // Exit 0 is not enough: an error while finishing the file (its trailer)
  // is only said on stderr.
  if (!process.errors().empty()) {
    output_failed(request.out, fmt::format("ffmpeg reported an error: {}", last_line(process.errors())));
  }
  verify_video(ffmpeg, temporary.path(), request.out);
  if (const int sig = pending_stop(request.cancelled)) {  // a signal during the check
    ::unlink(temporary.path().c_str());
    stop_interrupted(sig);
  }
  temporary.commit();
  return request.out;
}

std::string find_ffmpeg(std::optional<std::string_view> given, std::optional<std::string_view> search_path) {
  if (given) return ::access(std::string(*given).c_str(), X_OK) == 0 ? std::string(*given) : "";
  const std::string dirs(search_path.value_or("/usr/bin:/bin"));
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = dirs.find(':', start);
    const std::string dir = dirs.substr(start, end == std::string::npos ? std::string::npos : end - start);
    const std::string candidate = (dir.empty() ? std::string(".") : dir) + "/ffmpeg";
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return "";
}

}  // namespace pita::animate
