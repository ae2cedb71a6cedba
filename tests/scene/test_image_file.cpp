// The image files that scenes name (src/scene/image_file.cpp; PITA Sec. 7.1,
// docs/reference/render.md "Figure fields of a scene"): where a path may lead (relative, inside the
// scene's folder once ".." and symbolic links are resolved; absolute only
// with --allow-absolute-paths), what the file must be (a regular file, a PNG
// of 1 to kMaxImageSide pixels a side) and the size read from its IHDR
// header. Each test builds its scene folder in a temporary directory. The
// same refusals through pita: tests/data/bad/images-*.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include "scene/image_file.hpp"
#include "scene/limits.hpp"
#include "scene/scene.hpp"

namespace pita::scene {
namespace {

namespace fs = std::filesystem;

// The bytes of a PNG's signature and IHDR chunk for `width` x `height`
// pixels: all that check_image_file reads (the CRC is not checked; cairo
// decodes the rest when drawing).
std::string png_header(std::uint32_t width, std::uint32_t height) {
  std::string bytes("\x89PNG\r\n\x1a\n", 8);
  const auto be32 = [&bytes](std::uint32_t x) {
    for (int shift = 24; shift >= 0; shift -= 8) bytes += static_cast<char>((x >> shift) & 0xFFU);
  };
  be32(13);
  bytes += "IHDR";
  be32(width);
  be32(height);
  bytes += std::string("\x08\x06\x00\x00\x00", 5);  // 8-bit RGBA, no interlace
  be32(0);                                          // CRC (not read)
  return bytes;
}

class ImageFile : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("pita-test-image-file-" + std::to_string(::getpid()) + "-" +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    fs::create_directories(root_ / "scene" / "images");
    scene_file_ = (root_ / "scene" / "scene.json").string();
    write("scene/picture.png", png_header(160, 120));
    write("scene/images/wide.png", png_header(300, 20));
    write("outside.png", png_header(10, 10));  // beside the scene's folder, not in it
  }
  void TearDown() override { fs::remove_all(root_); }

  void write(const fs::path& relative, const std::string& bytes) const {
    std::ofstream(root_ / relative, std::ios::binary) << bytes;
  }

  ImageRef check(const std::string& given, bool allow_absolute = false) const {
    return check_image_file(scene_file_, given, ReadOptions{allow_absolute, std::nullopt});
  }

  // The reason check_image_file gives for `given`, or "(accepted)".
  std::string refusal(const std::string& given, bool allow_absolute = false) const {
    try {
      check(given, allow_absolute);
    } catch (const std::invalid_argument& error) {
      return error.what();
    }
    return "(accepted)";
  }

  fs::path root_;
  std::string scene_file_;
};

TEST_F(ImageFile, ReadsWidthAndHeightFromTheHeader) {
  const ImageRef picture = check("picture.png");
  EXPECT_EQ(picture.width, 160);
  EXPECT_EQ(picture.height, 120);
  EXPECT_EQ(picture.given, "picture.png");
  EXPECT_EQ(fs::path(picture.path), root_ / "scene" / "picture.png");
  // Width first, then height (not a square, so that a swap shows).
  const ImageRef wide = check("images/wide.png");
  EXPECT_EQ(wide.width, 300);
  EXPECT_EQ(wide.height, 20);
  EXPECT_EQ(wide.given, "images/wide.png");
  EXPECT_TRUE(fs::equivalent(wide.path, root_ / "scene" / "images" / "wide.png"));
}

TEST_F(ImageFile, SidesUpToTheLimitAreAccepted) {
  write("scene/largest.png", png_header(kMaxImageSide, kMaxImageSide));
  const ImageRef largest = check("largest.png");
  EXPECT_EQ(largest.width, kMaxImageSide);
  EXPECT_EQ(largest.height, kMaxImageSide);
  write("scene/one.png", png_header(1, 1));
  EXPECT_EQ(check("one.png").width, 1);
}

TEST_F(ImageFile, TooLargeOrEmptyImagesAreRefused) {
  write("scene/too-wide.png", png_header(9000, 10));
  EXPECT_EQ(refusal("too-wide.png"),
            "image \"too-wide.png\" is 9000 x 10 pixels; images may have 1 to 8192 pixels a side");
  write("scene/too-tall.png", png_header(10, kMaxImageSide + 1));
  EXPECT_EQ(refusal("too-tall.png"),
            "image \"too-tall.png\" is 10 x 8193 pixels; images may have 1 to 8192 pixels a side");
  write("scene/empty.png", png_header(0, 10));
  EXPECT_EQ(refusal("empty.png"), "image \"empty.png\" is 0 x 10 pixels; images may have 1 to 8192 pixels a side");
  // A width that would be negative as a signed 32-bit number.
  write("scene/huge.png", png_header(0x80000000U, 10));
  EXPECT_EQ(refusal("huge.png"),
            "image \"huge.png\" is 2147483648 x 10 pixels; images may have 1 to 8192 pixels a side");
}

TEST_F(ImageFile, OnlyPngFilesAreRead) {
  write("scene/fake.png", "This is a text file named fake.png.\n");
  EXPECT_EQ(refusal("fake.png"), "image \"fake.png\" is not a PNG file (only PNG images are read)");
  // The signature alone: no IHDR header to read the size from.
  write("scene/short.png", png_header(4, 4).substr(0, 8));
  EXPECT_EQ(refusal("short.png"), "image \"short.png\" is not a PNG file (only PNG images are read)");
  // The signature, then another chunk than IHDR first.
  std::string bad_chunk = png_header(4, 4);
  bad_chunk.replace(12, 4, "IDAT");
  write("scene/no-ihdr.png", bad_chunk);
  EXPECT_EQ(refusal("no-ihdr.png"), "image \"no-ihdr.png\" is not a PNG file (only PNG images are read)");
  write("scene/empty-file.png", "");
  EXPECT_EQ(refusal("empty-file.png"), "image \"empty-file.png\" is not a PNG file (only PNG images are read)");
}

TEST_F(ImageFile, MissingFilesAndFoldersAreRefused) {
  EXPECT_EQ(refusal("missing.png"),
            "image \"missing.png\" does not exist (image paths are relative to the scene's folder)");
  EXPECT_EQ(refusal("images"), "image \"images\" cannot be read: it is a directory");
  EXPECT_EQ(refusal(""), "the image path is empty");
  EXPECT_EQ(refusal(std::string("pic\0ture.png", 12)), "the image path contains a NUL character");
}

// Issue 60: an image that is a FIFO (no writer: opening it would wait for
// one), or a device, is refused at once, saying what it is.
TEST_F(ImageFile, FifosAndDevicesAreRefusedAtOnce) {
  ASSERT_EQ(::mkfifo((root_ / "scene" / "pipe.png").c_str(), 0600), 0);
  EXPECT_EQ(refusal("pipe.png"), "image \"pipe.png\" cannot be read: it is a named pipe (FIFO), not a regular file");
  EXPECT_EQ(refusal("/dev/zero", true), "image \"/dev/zero\" cannot be read: it is a device, not a regular file");
}

TEST_F(ImageFile, PathsOutOfTheScenesFolderAreRefusedEvenWhenTheFileExists) {
  ASSERT_TRUE(fs::exists(root_ / "outside.png"));
  const std::string reason = "(images must be in the scene's folder or below it: no \"..\" and no symbolic link out)";
  EXPECT_EQ(refusal("../outside.png"), "image \"../outside.png\" lies outside the scene's folder " + reason);
  EXPECT_EQ(refusal("images/../../outside.png"),
            "image \"images/../../outside.png\" lies outside the scene's folder " + reason);
  // Also with --allow-absolute-paths: that allows absolute paths, not "..".
  EXPECT_EQ(refusal("../outside.png", true), "image \"../outside.png\" lies outside the scene's folder " + reason);
  // ".." that stays inside is fine.
  EXPECT_EQ(check("images/../picture.png").width, 160);
  EXPECT_EQ(check("./images/wide.png").width, 300);
}

TEST_F(ImageFile, SymbolicLinksOutOfTheScenesFolderAreRefused) {
  std::error_code error;
  fs::create_symlink(root_ / "outside.png", root_ / "scene" / "link-out.png", error);
  if (error) GTEST_SKIP() << "cannot create a symbolic link here: " << error.message();
  fs::create_directory_symlink(root_, root_ / "scene" / "folder-out", error);
  ASSERT_FALSE(error) << error.message();
  fs::create_symlink("picture.png", root_ / "scene" / "link-in.png", error);
  ASSERT_FALSE(error) << error.message();
  ASSERT_TRUE(fs::exists(root_ / "scene" / "link-out.png"));  // the link works: only where it leads is wrong

  const std::string reason = "(images must be in the scene's folder or below it: no \"..\" and no symbolic link out)";
  EXPECT_EQ(refusal("link-out.png"), "image \"link-out.png\" lies outside the scene's folder " + reason);
  EXPECT_EQ(refusal("folder-out/outside.png"),
            "image \"folder-out/outside.png\" lies outside the scene's folder " + reason);
  // A link that stays in the folder is followed.
  const ImageRef in = check("link-in.png");
  EXPECT_EQ(in.width, 160);
  EXPECT_EQ(in.height, 120);
}

TEST_F(ImageFile, AbsolutePathsOnlyWithAllowAbsolutePaths) {
  const std::string absolute = (root_ / "outside.png").string();
  ASSERT_TRUE(fs::path(absolute).is_absolute());
  // Refused as absolute before anything else: whether it exists, what it is.
  const std::string refused = "\"" + absolute +
                              "\" is an absolute path; images are found relative to the scene's folder (pass "
                              "--allow-absolute-paths to allow absolute ones)";
  EXPECT_EQ(refusal(absolute), refused);
  EXPECT_EQ(refusal("/etc/passwd"),
            "\"/etc/passwd\" is an absolute path; images are found relative to the scene's folder (pass "
            "--allow-absolute-paths to allow absolute ones)");
  EXPECT_EQ(refusal("/no/such/image.png"),
            "\"/no/such/image.png\" is an absolute path; images are found relative to the scene's folder (pass "
            "--allow-absolute-paths to allow absolute ones)");

  // --allow-absolute-paths: the PNG outside the scene's folder is read.
  const ImageRef image = check(absolute, true);
  EXPECT_EQ(image.path, absolute);
  EXPECT_EQ(image.given, absolute);
  EXPECT_EQ(image.width, 10);
  EXPECT_EQ(image.height, 10);
  // ... and still checked as a file.
  EXPECT_EQ(refusal("/no/such/image.png", true), "image \"/no/such/image.png\" does not exist");
  write("fake.png", "text");
  EXPECT_EQ(refusal((root_ / "fake.png").string(), true),
            "image \"" + (root_ / "fake.png").string() + "\" is not a PNG file (only PNG images are read)");
}

// Through the scene reader: an image shape is found beside the scene file,
// the option of load_scene reaches it, and its refusal names the pointer.
TEST_F(ImageFile, SceneReaderChecksImageShapes) {
  const auto scene_with = [](const std::string& image) {
    return R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
      {"t": 0.5, "p": [1, 1], "m": 1, "w": 0}, {"t": 1, "p": [2, 0], "m": 1, "w": 0}],
      "shapes": [{"image": ")" +
           image + R"(", "box": [[0, 0], [2, 1.5]]}]})";
  };
  { std::ofstream(scene_file_) << scene_with("images/wide.png"); }
  const Scene scene = load_scene(scene_file_);
  ASSERT_EQ(figure_of<KeyframeKeys>(scene).shapes.size(), 1u);
  ASSERT_TRUE(figure_of<KeyframeKeys>(scene).shapes[0].image.has_value());
  EXPECT_EQ(figure_of<KeyframeKeys>(scene).shapes[0].image->given, "images/wide.png");
  EXPECT_EQ(figure_of<KeyframeKeys>(scene).shapes[0].image->width, 300);

  const std::string absolute = (root_ / "outside.png").string();
  { std::ofstream(scene_file_) << scene_with(absolute); }
  try {
    load_scene(scene_file_);
    ADD_FAILURE() << "an absolute path was accepted without --allow-absolute-paths";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.pointer(), "/shapes/0/image");
  }
  const Scene allowed = load_scene(scene_file_, ReadOptions{true, std::nullopt});
  ASSERT_TRUE(figure_of<KeyframeKeys>(allowed).shapes[0].image.has_value());
  EXPECT_EQ(figure_of<KeyframeKeys>(allowed).shapes[0].image->path, absolute);
  // parse_scene finds images from the folder of its source name too.
  EXPECT_EQ(figure_of<KeyframeKeys>(parse_scene(scene_with("picture.png"), scene_file_)).shapes[0].image->height, 120);
}

}  // namespace
}  // namespace pita::scene
