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
}  // namespace pita::text
