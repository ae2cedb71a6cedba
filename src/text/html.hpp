// Text written into HTML, SVG or XML (the golden report, a sweep's index
// page, the animated SVG): one escape for every writer of markup.
#pragma once

#include <string>
#include <string_view>

namespace pita::text {

// `text` as character data or as a quoted attribute value: &, <, >, " and '
// as &amp; &lt; &gt; &quot; &apos;, and the control characters that XML does
// not allow as text (U+0001-U+0008, U+000B, U+000C, U+000E-U+001F,
// U+007F-U+0084, U+0086-U+009F) as hexadecimal references such as &#x1b;.
// Everything else, UTF-8 included, is copied as it is: the same bytes as
// GLib's g_markup_escape_text.
std::string html_escaped(std::string_view text);

// A relative path pita wrote, as the value of an href or src: every byte but
// the unreserved ones (letters, digits, - _ . ~) and "/" percent-encoded, so
// that no part of it reads as a scheme ("javascript:x.png" becomes
// "javascript%3Ax.png", a file), a query or a fragment. Safe in a quoted
// attribute without html_escaped.
std::string relative_url(std::string_view path);

}  // namespace pita::text
