#include "render/image_cache.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <iterator>
#include <list>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <utility>

#include <fmt/format.h>
#include <sys/stat.h>

#include "io/input_file.hpp"
#include "render/cairo_handles.hpp"
#include "scene/limits.hpp"

namespace pita::render {

namespace {

// Decoded bytes held by the caches of every thread together.
std::atomic<std::size_t> cached_bytes{0};

std::size_t bytes_of(cairo_surface_t* surface) {
  return static_cast<std::size_t>(cairo_image_surface_get_stride(surface)) *
         static_cast<std::size_t>(cairo_image_surface_get_height(surface));
}

// What tells one version of a file from the next without reading it: its
// inode, size, modification and status change times ("" when it cannot be read: decoding then says
// why). A long-lived process (pita watch, the Python module) sees an image
// saved again as a new one.
std::string file_stamp(const std::string& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) return {};
  // The inode and the status change time too: a copy that keeps the
  // modification time (cp -p) or a rewrite of the same size in the same
  // tick is still another version.
  return fmt::format("{}:{}:{}.{}:{}.{}", status.st_ino, status.st_size, status.st_mtim.tv_sec, status.st_mtim.tv_nsec,
                     status.st_ctim.tv_sec, status.st_ctim.tv_nsec);
}

// One thread's images, the most recently used first.
class ThreadCache {
 public:
  ~ThreadCache() {
    while (!entries_.empty()) drop_last();
  }
  // The image decoded from `path` as it was at `stamp`; an older version of
  // it is dropped.
  cairo_surface_t* find(const std::string& path, const std::string& stamp) {
    for (auto it = entries_.begin(); it != entries_.end(); ++it) {
      if (it->path != path) continue;
      if (it->stamp != stamp || stamp.empty()) {
        drop(it);
        return nullptr;
      }
      entries_.splice(entries_.begin(), entries_, it);  // now the most recent
      return entries_.front().surface.get();
    }
    return nullptr;
  }
  // Keeps `surface`, first evicting this thread's least recently used images
  // while the caches of all threads would hold more than kImageCacheBytes.
  cairo_surface_t* insert(const std::string& path, const std::string& stamp, SurfacePtr surface) {
    const std::size_t bytes = bytes_of(surface.get());
    while (!entries_.empty() && cached_bytes.load() + bytes > kImageCacheBytes) drop(std::prev(entries_.end()));
    cached_bytes += bytes;
    entries_.push_front(Entry{path, stamp, std::move(surface)});
    return entries_.front().surface.get();
  }

 private:
  struct Entry {
    std::string path;
    std::string stamp;
    SurfacePtr surface;
  };
  void drop(std::list<Entry>::iterator it) {
    cached_bytes -= bytes_of(it->surface.get());
    entries_.erase(it);
  }
  void drop_last() { drop(std::prev(entries_.end())); }
  std::list<Entry> entries_;
};

// Why cairo could not decode `path`: it reports a corrupt PNG as "out of
// memory" (CAIRO_STATUS_NO_MEMORY) as often as a read error, so the header
// is looked at to tell a corrupt file from a truly huge image.
std::string decode_failure(const std::string& path, cairo_status_t status) {
  unsigned char head[24] = {};
  std::size_t got = 0;
  try {
    io::InputFile in(path);
    while (got < sizeof head) {
      const std::size_t n = in.read(reinterpret_cast<char*>(head) + got, sizeof head - got);
      if (n == 0) break;
      got += n;
    }
  } catch (const io::InputError& error) {
    return error.what();
  }
  static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (got < 8 || !std::equal(head, head + 8, kSignature)) {
    return "not a PNG file (its first bytes are not the PNG signature)";
  }
  if (got < 24 || !std::equal(head + 12, head + 16, reinterpret_cast<const unsigned char*>("IHDR"))) {
    return "corrupt PNG (truncated before its header)";
  }
  const auto be32 = [&](int at) {
    return (std::uint64_t{head[at]} << 24) | (std::uint64_t{head[at + 1]} << 16) | (std::uint64_t{head[at + 2]} << 8) |
           std::uint64_t{head[at + 3]};
  };
  const std::uint64_t width = be32(16), height = be32(20);
  if (status == CAIRO_STATUS_NO_MEMORY && width * height * 4 > (std::uint64_t{1} << 30)) {
    return fmt::format("out of memory decoding a PNG of {} x {} pixels", width, height);
  }
  return fmt::format("corrupt PNG (cairo: {}; a {} x {} image, truncated or damaged after its header)",
                     status == CAIRO_STATUS_READ_ERROR ? "read error" : cairo_status_to_string(status), width, height);
}

// The PNG's bytes as cairo reads them: from the file opened as a regular file
// (io/input_file.hpp: a FIFO, a device or a directory put in the image's place
// since the scene was read is refused at once, never waited on), at most
// scene::kMaxImageFileBytes.
struct PngStream {
  io::InputFile file;
  std::size_t read = 0;
  bool too_large = false;
  std::string failure;  // a read error
  static cairo_status_t next(void* closure, unsigned char* data, unsigned int length) {
    auto* self = static_cast<PngStream*>(closure);
    try {
      unsigned int got = 0;
      while (got < length) {
        const std::size_t n = self->file.read(reinterpret_cast<char*>(data) + got, length - got);
        if (n == 0) return CAIRO_STATUS_READ_ERROR;  // the file ends before the PNG does
        got += static_cast<unsigned int>(n);
      }
      self->read += length;
      if (self->read > scene::kMaxImageFileBytes) {
        self->too_large = true;
        return CAIRO_STATUS_READ_ERROR;
      }
      return CAIRO_STATUS_SUCCESS;
    } catch (const io::InputError& error) {
      self->failure = error.what();
      return CAIRO_STATUS_READ_ERROR;
    }
  }
};

}  // namespace

cairo_surface_t* cached_image(const std::string& path, const std::string& name) {
  thread_local ThreadCache cache;
  const std::string stamp = file_stamp(path);
  if (cairo_surface_t* found = cache.find(path, stamp)) return found;
  std::optional<PngStream> stream;
  try {
    stream.emplace(PngStream{io::InputFile(path), 0, false, {}});
  } catch (const io::InputError& error) {
    throw ImageError(fmt::format("cannot read the image \"{}\": {}", name,
                                 error.kind() == io::InputError::Kind::cannot_open
                                     ? fmt::format("cannot open it ({})", error.what())
                                     : std::string(error.what())));
  }
  SurfacePtr surface(cairo_image_surface_create_from_png_stream(&PngStream::next, &*stream));
  const cairo_status_t status = cairo_surface_status(surface.get());
  if (stream->too_large) {
    throw ImageError(fmt::format("cannot read the image \"{}\": it is larger than the limit of {} MiB", name,
                                 scene::kMaxImageFileBytes >> 20));
  }
  if (!stream->failure.empty()) {
    throw ImageError(fmt::format("cannot read the image \"{}\" ({})", name, stream->failure));
  }
  if (status != CAIRO_STATUS_SUCCESS) {
    throw ImageError(fmt::format("cannot read the image \"{}\": {}", name, decode_failure(path, status)));
  }
  return cache.insert(path, stamp, std::move(surface));
}

std::size_t cached_image_bytes() { return cached_bytes.load(); }

}  // namespace pita::render
