// The one HTML escape (src/text/html.cpp): the five characters of markup,
// the control characters XML refuses, and nothing else.
#include <string>

#include <gtest/gtest.h>

#include "text/html.hpp"

namespace pita::text {
namespace {

TEST(HtmlEscaped, EscapesTheCharactersOfMarkup) {
  EXPECT_EQ(html_escaped("a < b && c > \"d\" 'e'"), "a &lt; b &amp;&amp; c &gt; &quot;d&quot; &apos;e&apos;");
}

TEST(HtmlEscaped, LeavesOtherTextAsItIs) {
  EXPECT_EQ(html_escaped(""), "");
  EXPECT_EQ(html_escaped("Fig. 16: D(t) = A^(1-t) B^t, tab\there\nand a newline"),
            "Fig. 16: D(t) = A^(1-t) B^t, tab\there\nand a newline");
  // UTF-8 passes through, U+0085 (NEL) too.
  EXPECT_EQ(html_escaped("\xcf\x80 \xc3\xa9 \xc2\x85"), "\xcf\x80 \xc3\xa9 \xc2\x85");
}

TEST(HtmlEscaped, WritesControlCharactersAsReferences) {
  EXPECT_EQ(html_escaped(std::string("\x01|\x1b|\x7f|\x0b|\r", 9)), "&#x1;|&#x1b;|&#x7f;|&#xb;|\r");
  // U+0080 and U+009F (C1 controls, 0xC2 0x80 and 0xC2 0x9F in UTF-8).
  EXPECT_EQ(html_escaped("\xc2\x80x\xc2\x9f"), "&#x80;x&#x9f;");
}

}  // namespace
TEST(RelativeUrl, EncodesAllButUnreservedCharactersAndSlashes) {
  EXPECT_EQ(relative_url("out/fig01-eight_pitas.v2~.png"), "out/fig01-eight_pitas.v2~.png");
  EXPECT_EQ(relative_url("javascript:alert(1).png"), "javascript%3Aalert%281%29.png");  // no scheme
  EXPECT_EQ(relative_url("a b?c#d&e\"f'g<h>"), "a%20b%3Fc%23d%26e%22f%27g%3Ch%3E");
  EXPECT_EQ(relative_url("caf\xc3\xa9"), "caf%C3%A9");
}

}  // namespace pita::text
