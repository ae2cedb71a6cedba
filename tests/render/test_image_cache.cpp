// The image cache (src/render/image_cache.cpp): decoded images stay under
// kImageCacheBytes however many distinct images a thread paints (a sweep or
// a multi-scene render held every one of them: 815 MB for twelve 4096²
// images), the image asked for is always there, and a file that is not a PNG
// or is cut short is named as such, not as "out of memory".
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include "render/cairo_handles.hpp"
#include "render/image_cache.hpp"

namespace pita::render {
namespace {

namespace fs = std::filesystem;

class ImageCache : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pita-test-image-cache-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // A blank PNG of side x side pixels (small on disk, side² x 4 bytes decoded).
  fs::path blank_png(const std::string& name, int side) const {
    const SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, side, side));
    const fs::path path = dir_ / name;
    EXPECT_EQ(cairo_surface_write_to_png(surface.get(), path.c_str()), CAIRO_STATUS_SUCCESS);
    return path;
  }
  fs::path dir_;
};

TEST_F(ImageCache, DistinctImagesStayUnderTheBudget) {
  constexpr int kSide = 2048;  // 16 MiB decoded
  const std::size_t one = std::size_t{kSide} * kSide * 4;
  const std::size_t images = kImageCacheBytes / one + 4;
  const fs::path model = blank_png("model.png", kSide);  // encoded once, copied under new names
  for (std::size_t i = 0; i < images; ++i) {
    const fs::path path = dir_ / ("i" + std::to_string(i) + ".png");
    fs::copy_file(model, path);
    cairo_surface_t* surface = cached_image(path.string(), path.filename().string());
    ASSERT_NE(surface, nullptr);
    EXPECT_EQ(cairo_image_surface_get_width(surface), kSide);
    EXPECT_LE(cached_image_bytes(), kImageCacheBytes) << i;
    fs::remove(path);  // decoded once; the cache holds what it keeps
  }
  EXPECT_GE(cached_image_bytes(), kImageCacheBytes - one);  // it does keep what fits
}

TEST_F(ImageCache, NotAPngAndACutPngAreNamed) {
  std::ofstream(dir_ / "text.png") << "hello, not an image";
  try {
    (void)cached_image((dir_ / "text.png").string(), "text.png");
    ADD_FAILURE() << "no error";
  } catch (const ImageError& e) {
    EXPECT_NE(std::string(e.what()).find("not a PNG file"), std::string::npos) << e.what();
  }
  const fs::path whole = blank_png("whole.png", 300);
  std::ifstream in(whole, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::ofstream(dir_ / "cut.png", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  try {
    (void)cached_image((dir_ / "cut.png").string(), "cut.png");
    ADD_FAILURE() << "no error";
  } catch (const ImageError& e) {
    EXPECT_NE(std::string(e.what()).find("corrupt PNG"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("out of memory"), std::string::npos) << e.what();
  }
}

// Issue 60: an image replaced by a FIFO or a folder after the scene was read
// is refused at once (opened with O_NONBLOCK, checked with fstat), naming
// the image and what it is; cairo never opens it by its name.
TEST_F(ImageCache, AFifoOrAFolderInTheImagesPlaceIsRefusedAtOnce) {
  ASSERT_EQ(::mkfifo((dir_ / "pipe.png").c_str(), 0600), 0);
  fs::create_directories(dir_ / "folder.png");
  for (const auto& [name, what] : {std::pair<std::string, std::string>{"pipe.png", "it is a named pipe (FIFO)"},
                                   {"folder.png", "it is a directory"}}) {
    try {
      (void)cached_image((dir_ / name).string(), name);
      ADD_FAILURE() << name << ": no error";
    } catch (const ImageError& e) {
      EXPECT_NE(std::string(e.what()).find("the image \"" + name + "\": " + what), std::string::npos) << e.what();
    }
  }
  // A good image still decodes from its bytes.
  const fs::path good = blank_png("good.png", 7);
  EXPECT_EQ(cairo_image_surface_get_width(cached_image(good.string(), "good.png")), 7);
}

}  // namespace
}  // namespace pita::render
