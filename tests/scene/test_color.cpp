// Colors of a scene (src/scene/color.cpp).
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "scene/color.hpp"

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

}  // namespace
}  // namespace pita::scene
