#include "io/output_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/input_file.hpp"
#include "io/interrupt.hpp"

namespace pita::io {

namespace {

namespace fs = std::filesystem;

OutputError error(const fs::path& path, const std::string& what, int errnum) {
  return OutputError(path.string() + ": " + what + " (" + std::strerror(errnum) + ")");
}

}  // namespace

// Named, not anonymous: StreamingOutput::Impl, declared in the header, holds one.
namespace atomic_output {

// The hidden temporary of one target. Its name is registered with the
// interrupt cleanup before mkstemp creates it (mkstemp fills in the XXXXXX in
// the registered slot itself), and released only once the file is renamed
// into place or removed: a signal at any moment leaves no temporary behind.
class Temporary {
 public:
  explicit Temporary(const fs::path& target) : target_(target) {
    const fs::path dir = target.has_parent_path() ? target.parent_path() : ".";
    std::string name = target.filename().string();
    name.insert(0, 1, '.');
    name.append(".XXXXXX");
    const std::string pattern = (dir / name).string();
    const std::string cannot = "cannot create a temporary file in " + dir.string();
    slot_ = register_in_flight(pattern);
    // The caller holds a reservation (InFlightReservation): a slot is free
    // unless the path is too long for one.
    if (slot_ < 0) throw error(target, cannot, ENAMETOOLONG);
    fd_ = ::mkstemp(slot_path(slot_));
    if (fd_ < 0) {
      const int saved = errno;
      release_in_flight(slot_);
      throw error(target, cannot, saved);
    }
    temp_ = slot_path(slot_);
  }
  Temporary(const Temporary&) = delete;
  Temporary& operator=(const Temporary&) = delete;
  ~Temporary() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_) ::unlink(temp_.c_str());
    release_in_flight(slot_);
  }

  // Every byte, then the ordinary permissions (mkstemp creates 0600; outputs
  // are 0666 less the umask), then close, whose error may be the first news
  // of a full disk on some file systems.
  void write(std::string_view bytes, mode_t mode) {
    append(bytes);
    finish(mode);
  }

  void append(std::string_view bytes) {
    std::size_t written = 0;
    while (written < bytes.size()) {
      const ssize_t n = ::write(fd_, bytes.data() + written, bytes.size() - written);
      if (n < 0) {
        if (errno == EINTR) continue;
        throw error(target_, "cannot write", errno);
      }
      written += static_cast<std::size_t>(n);
    }
  }

  void finish(mode_t mode) {
    ::fchmod(fd_, mode);
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) throw error(target_, "cannot write", errno);
  }

  // The rename fails on a directory in the way (EISDIR): found before any
  // file of the set is renamed, so that the old files stay as they were.
  void check_target() const {
    struct stat status {};
    if (::lstat(target_.c_str(), &status) == 0 && S_ISDIR(status.st_mode)) {
      throw error(target_, "cannot rename the finished file into place", EISDIR);
    }
  }

  void commit() {
    if (std::rename(temp_.c_str(), target_.c_str()) != 0) {
      throw error(target_, "cannot rename the finished file into place", errno);
    }
    committed_ = true;
  }

  const fs::path& target() const { return target_; }

 private:
  fs::path target_;
  std::string temp_;
  int slot_ = -1;
  int fd_ = -1;
  bool committed_ = false;
};

}  // namespace atomic_output

namespace {

using atomic_output::Temporary;

struct View {
  const fs::path& path;
  std::string_view bytes;
};

// 0666 less the umask. umask(2) can only be read by setting it: done once (a
// thread-safe static), never while other threads write (a sweep's pool, an
// animation's frames), which would see the 0 set in between and create files
// of mode 666.
mode_t output_mode() {
  static const mode_t mask = [] {
    const mode_t m = ::umask(0);
    ::umask(m);
    return m;
  }();
  return 0666 & ~mask;
}

void write_all_or_none(const std::vector<View>& files) {
  const mode_t mode = output_mode();
  // Declared first, released last: after every temporary is gone.
  const InFlightReservation reservation(files.size());
  std::vector<std::unique_ptr<Temporary>> temporaries;
  // The destructors remove every temporary not renamed, whatever throws.
  for (const View& file : files) temporaries.push_back(std::make_unique<Temporary>(file.path));
  for (std::size_t i = 0; i < files.size(); ++i) temporaries[i]->write(files[i].bytes, mode);
  for (const auto& temporary : temporaries) temporary->check_target();
  for (std::size_t i = 0; i < temporaries.size(); ++i) {
    try {
      temporaries[i]->commit();
    } catch (const std::runtime_error& failure) {
      // The old versions of the files already renamed are gone: remove the new
      // ones too, so that the set is none rather than a mix.
      std::string message = failure.what();
      for (std::size_t k = 0; k < i; ++k) {
        ::unlink(temporaries[k]->target().c_str());
        message += (k == 0 ? "; removed " : ", ") + temporaries[k]->target().string();
      }
      if (i > 0) message += ", written with it";
      throw OutputError(message);
    }
  }
}

}  // namespace

struct StreamingOutput::Impl {
  explicit Impl(const fs::path& path) : reservation(1), temporary(path) {}
  InFlightReservation reservation;  // released after the temporary
  atomic_output::Temporary temporary;
  std::string buffer;
};

StreamingOutput::StreamingOutput(const fs::path& path, std::size_t buffer_bytes)
    : buffer_bytes_(buffer_bytes), impl_(std::make_unique<Impl>(path)) {}
StreamingOutput::~StreamingOutput() = default;

void StreamingOutput::write(std::string_view bytes) {
  // The buffer never grows past buffer_bytes_ (a string left to double would
  // reach twice that, and copy itself on the way).
  if (impl_->buffer.size() + bytes.size() > buffer_bytes_ && !impl_->buffer.empty()) {
    impl_->temporary.append(impl_->buffer);
    impl_->buffer.clear();
  }
  if (bytes.size() >= buffer_bytes_) {
    impl_->temporary.append(bytes);
    return;
  }
  if (impl_->buffer.capacity() < buffer_bytes_) impl_->buffer.reserve(buffer_bytes_);
  impl_->buffer.append(bytes);
}

void StreamingOutput::commit() {
  impl_->temporary.append(impl_->buffer);
  impl_->buffer.clear();
  impl_->temporary.finish(output_mode());
  impl_->temporary.check_target();
  impl_->temporary.commit();
}

void write_file_atomically(const fs::path& path, std::string_view bytes) { write_all_or_none({View{path, bytes}}); }

bool replace_file_if_unchanged(const fs::path& path, std::string_view expected, std::string_view bytes) {
  StreamingOutput out(path);
  out.write(bytes);
  std::string now;
  try {
    now = read_regular_file(path, expected.size() + 1);  // one byte more tells a longer file
  } catch (const InputError&) {
    return false;  // gone, grown past it, or no longer a file: changed
  }
  if (now != expected) return false;  // the temporary goes with `out`
  out.commit();
  return true;
}

void write_files_atomically(std::span<const std::pair<fs::path, std::string>> files) {
  std::vector<View> views;
  views.reserve(files.size());
  for (const auto& [path, bytes] : files) views.push_back(View{path, bytes});
  write_all_or_none(views);
}

}  // namespace pita::io
