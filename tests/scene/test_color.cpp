// Colors of a scene (src/scene/color.cpp).
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "scene/color.hpp"
#include "scene/limits.hpp"

namespace pita::scene {
namespace {

std::string color_error(std::string_view text) {
  try {
    parse_color(text);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(Color, ReadsHexForms) {
  EXPECT_EQ(parse_color("#000000"), (Color{0, 0, 0, 1}));
  EXPECT_EQ(parse_color("#ffffff"), (Color{1, 1, 1, 1}));
  EXPECT_EQ(parse_color("#ff8000"), (Color{1, 128 / 255.0, 0, 1}));
  EXPECT_EQ(parse_color("#FF8000"), parse_color("#ff8000"));  // any case
  EXPECT_EQ(parse_color("#aBc"), parse_color("#aabbcc"));     // #rgb doubles each digit
  EXPECT_EQ(parse_color("#f00"), (Color{1, 0, 0, 1}));
  EXPECT_EQ(parse_color("#11223344"), (Color{0x11 / 255.0, 0x22 / 255.0, 0x33 / 255.0, 0x44 / 255.0}));
  EXPECT_EQ(parse_color("#12345600").a, 0.0);
}

TEST(Color, ReadsNames) {
  EXPECT_EQ(parse_color("black"), (Color{0, 0, 0, 1}));
  EXPECT_EQ(parse_color("white"), (Color{1, 1, 1, 1}));
  EXPECT_EQ(parse_color("red"), parse_color("#d00000"));
  EXPECT_EQ(parse_color("gray"), parse_color("grey"));
  for (const NamedColor& named : named_colors()) {
    SCOPED_TRACE(std::string(named.name));
    EXPECT_EQ(parse_color(named.name), parse_color(named.hex));
    EXPECT_EQ(named.hex.size(), 7U);
  }
  EXPECT_EQ(named_colors().size(), 13U);
}

TEST(Color, RefusesOtherText) {
  EXPECT_EQ(color_error("#12345"),
            "\"#12345\" is not a color: \"#\" must be followed by 3, 6 or 8 hex digits (\"#rgb\", "
            "\"#rrggbb\" or \"#rrggbbaa\")");
  EXPECT_EQ(color_error("#ggg").substr(0, 22), "\"#ggg\" is not a color:");
  EXPECT_EQ(color_error("#"),
            "\"#\" is not a color: \"#\" must be followed by 3, 6 or 8 hex digits "
            "(\"#rgb\", \"#rrggbb\" or \"#rrggbbaa\")");
  EXPECT_EQ(color_error("#1234567").substr(0, 26), "\"#1234567\" is not a color:");
  EXPECT_EQ(color_error(" #fff").substr(0, 15), "unknown color \"");
  EXPECT_EQ(color_error("rde"), "unknown color \"rde\"; did you mean \"red\"?");
  EXPECT_EQ(color_error("Red"), "unknown color \"Red\"; did you mean \"red\"?");  // names are lower case
  EXPECT_EQ(color_error("gery"), "unknown color \"gery\"; did you mean \"gray\" or \"grey\"?");
  EXPECT_EQ(color_error("chartreuse"),
            "unknown color \"chartreuse\"; a color is \"#rgb\", \"#rrggbb\", \"#rrggbbaa\" or one "
            "of black, white, red, green, blue, gray, grey, orange, purple, brown, magenta, cyan, "
            "yellow");
  EXPECT_EQ(color_error("").substr(0, 16), "unknown color \"\"");
}

// The default series of keyframe and pose colours: the red, green and blue
// of old first; no two alike as "#rrggbb" for as many keyframes as a scene
// may have; each dark enough to read on white (luma under 0.75); a layer's
// own colours are cycled as given.
TEST(SeriesColor, DefaultSeriesNeverRepeatsAndReadsOnWhite) {
  EXPECT_EQ(series_color({}, 0), (Color{0.85, 0.0, 0.0, 1.0}));
  EXPECT_EQ(series_color({}, 1), (Color{0.0, 0.6, 0.0, 1.0}));
  EXPECT_EQ(series_color({}, 2), (Color{0.0, 0.0, 0.85, 1.0}));
  std::set<std::string> seen;
  for (std::size_t i = 0; i < static_cast<std::size_t>(kMaxKeyframes); ++i) {
    const Color c = series_color({}, i);
    const std::string hex =
        fmt::format("#{:02x}{:02x}{:02x}", static_cast<int>(std::lround(255 * c.r)),
                    static_cast<int>(std::lround(255 * c.g)), static_cast<int>(std::lround(255 * c.b)));
    EXPECT_TRUE(seen.insert(hex).second) << "keyframe " << i << " repeats " << hex;
    EXPECT_LT(0.299 * c.r + 0.587 * c.g + 0.114 * c.b, 0.75) << "keyframe " << i << " is " << hex;
    for (double channel : {c.r, c.g, c.b}) {
      EXPECT_GE(channel, 0.0);
      EXPECT_LE(channel, 1.0);
    }
  }
}

TEST(SeriesColor, GivenColoursAreCycled) {
  const std::vector<Color> given{parse_color("black"), parse_color("orange")};
  EXPECT_EQ(series_color(given, 0), given[0]);
  EXPECT_EQ(series_color(given, 3), given[1]);
}

}  // namespace
}  // namespace pita::scene
