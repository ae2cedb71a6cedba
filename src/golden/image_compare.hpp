// Comparing two PNG images pixel by pixel, with a per-channel tolerance and
// an allowed share of differing pixels, and drawing where they differ.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace pita::golden {

struct ImageTolerance {
  int channel = 2;         // a pixel differs when a channel (R, G, B, A; 0-255) differs by more
  double max_share = 0.0;  // the images match while differing pixels are at most this share
};

struct ImageComparison {
  int expected_width = 0, expected_height = 0, actual_width = 0, actual_height = 0;
  bool same_size = false;
  std::size_t differing = 0;       // pixels beyond the tolerance (all of them when sizes differ)
  double share = 0.0;              // differing / pixels (1 when sizes differ)
  int max_channel_difference = 0;  // largest channel difference (255 when sizes differ)
  bool matches = false;
  // PNG: the expected image faded to light grey with differing pixels in
  // saturated red (sizes differ: the actual image inside a red border).
  std::string diff_png;
};

// Larger images are refused from their header, before decoding (a 16384^2
// ARGB image is 1 GiB).
inline constexpr std::uint32_t kMaxImageSide = 16384;

// A golden (or fresh) file that cannot be read or decoded.
class GoldenError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Channels are compared as stored by cairo (premultiplied ARGB32), which is
// what both images went through. Throws GoldenError naming "expected" or
// "actual" when a PNG cannot be decoded.
ImageComparison compare_png(std::string_view expected_png, std::string_view actual_png,
                            const ImageTolerance& tolerance);

}  // namespace pita::golden
