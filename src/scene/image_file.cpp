#include "scene/image_file.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "io/input_file.hpp"
#include "scene/limits.hpp"

namespace pita::scene {

namespace {

namespace fs = std::filesystem;

// `path` lies in the folder `root` (both canonical): every component of root
// starts path.
bool inside(const fs::path& root, const fs::path& path) {
  auto r = root.begin();
  auto p = path.begin();
  for (; r != root.end(); ++r, ++p) {
    if (p == path.end() || *r != *p) return false;
  }
  return true;
}

std::uint32_t big_endian(const unsigned char* bytes) {
  return (std::uint32_t{bytes[0]} << 24) | (std::uint32_t{bytes[1]} << 16) | (std::uint32_t{bytes[2]} << 8) |
         std::uint32_t{bytes[3]};
}

}  // namespace

ImageRef check_image_file(const std::string& scene_file, const std::string& given, const ReadOptions& options) {
  if (given.empty()) throw std::invalid_argument("the image path is empty");
  if (given.find('\0') != std::string::npos) throw std::invalid_argument("the image path contains a NUL character");
  const fs::path path(given);
  const fs::path folder =
      fs::path(scene_file).parent_path().empty() ? fs::path(".") : fs::path(scene_file).parent_path();
  std::error_code error;
  fs::path resolved;
  if (path.is_absolute()) {
    if (!options.allow_absolute_paths) {
      throw std::invalid_argument(
          fmt::format("\"{}\" is an absolute path; images are found relative to the scene's "
                      "folder (pass --allow-absolute-paths to allow absolute ones)",
                      given));
    }
    resolved = path;
  } else {
    const fs::path root = fs::canonical(folder, error);
    if (error) {
      throw std::invalid_argument(
          fmt::format("cannot resolve the scene's folder {} ({})", folder.string(), error.message()));
    }
    const fs::path candidate = fs::weakly_canonical(root / path, error);
    if (error) {
      throw std::invalid_argument(fmt::format("image \"{}\" cannot be resolved ({})", given, error.message()));
    }
    if (!inside(root, candidate)) {
      throw std::invalid_argument(
          fmt::format("image \"{}\" lies outside the scene's folder (images must be in the "
                      "scene's folder or below it: no \"..\" and no symbolic link out)",
                      given));
    }
    resolved = folder / path;
  }
  const fs::file_status status = fs::status(resolved, error);
  if (error || !fs::exists(status)) {
    throw std::invalid_argument(
        fmt::format("image \"{}\" does not exist{}", given,
                    path.is_absolute() ? "" : " (image paths are relative to the scene's folder)"));
  }
  // Opened as a regular file only (a FIFO, a device or a directory is refused
  // at once: io/input_file.hpp), and no larger than kMaxImageFileBytes.
  std::array<unsigned char, 24> header{};
  std::size_t got = 0;
  try {
    io::InputFile in(resolved);
    const auto size = fs::file_size(resolved, error);
    if (!error && size > kMaxImageFileBytes) {
      throw std::invalid_argument(
          fmt::format("image \"{}\" is larger than the limit of {} MiB", given, kMaxImageFileBytes >> 20));
    }
    while (got < header.size()) {
      const std::size_t n = in.read(reinterpret_cast<char*>(header.data()) + got, header.size() - got);
      if (n == 0) break;
      got += n;
    }
  } catch (const io::InputError& failure) {
    throw std::invalid_argument(fmt::format("image \"{}\" {}", given,
                                            failure.kind() == io::InputError::Kind::cannot_open
                                                ? fmt::format("cannot be opened ({})", failure.what())
                                                : fmt::format("cannot be read: {}", failure.what())));
  }
  static constexpr std::array<unsigned char, 8> kSignature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (got < header.size() || !std::equal(kSignature.begin(), kSignature.end(), header.begin()) ||
      std::memcmp(header.data() + 12, "IHDR", 4) != 0) {
    throw std::invalid_argument(fmt::format("image \"{}\" is not a PNG file (only PNG images are read)", given));
  }
  const std::uint32_t width = big_endian(header.data() + 16), height = big_endian(header.data() + 20);
  if (width == 0 || height == 0 || width > static_cast<std::uint32_t>(kMaxImageSide) ||
      height > static_cast<std::uint32_t>(kMaxImageSide)) {
    throw std::invalid_argument(fmt::format("image \"{}\" is {} x {} pixels; images may have 1 to {} pixels a side",
                                            given, width, height, kMaxImageSide));
  }
  return ImageRef{resolved.string(), given, static_cast<int>(width), static_cast<int>(height), ""};
}

std::vector<std::filesystem::path> image_files(const Scene& scene) {
  std::vector<std::filesystem::path> files;
  for (const Panel& panel : scene.panels) {
    for (const ShapeOutline& shape : outlines_of(panel)) {
      if (shape.image && std::find(files.begin(), files.end(), shape.image->path) == files.end()) {
        files.emplace_back(shape.image->path);
      }
    }
  }
  return files;
}

}  // namespace pita::scene
