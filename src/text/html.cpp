#include "text/html.hpp"

#include <fmt/format.h>

namespace pita::text {

namespace {

// Whether the code point is one that is escaped as a reference.
bool escaped_control(unsigned code) {
  return (code >= 0x1 && code <= 0x8) || code == 0xb || code == 0xc || (code >= 0xe && code <= 0x1f) ||
         (code >= 0x7f && code <= 0x84) || (code >= 0x86 && code <= 0x9f);
}

}  // namespace

std::string html_escaped(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    switch (c) {
      case '&':
        out += "&amp;";
        continue;
      case '<':
        out += "&lt;";
        continue;
      case '>':
        out += "&gt;";
        continue;
      case '"':
        out += "&quot;";
        continue;
      case '\'':
        out += "&apos;";
        continue;
      default:
        break;
    }
    const auto byte = static_cast<unsigned char>(c);
    if (escaped_control(byte) && byte < 0x80) {
      out += fmt::format("&#x{:x};", byte);
    } else if (byte == 0xc2 && i + 1 < text.size() && escaped_control(static_cast<unsigned char>(text[i + 1])) &&
               static_cast<unsigned char>(text[i + 1]) >= 0x80) {
      // U+0080-U+009F in UTF-8 are 0xC2 0x80-0x9F.
      out += fmt::format("&#x{:x};", static_cast<unsigned char>(text[i + 1]));
      ++i;
    } else {
      out += c;
    }
  }
  return out;
}

std::string relative_url(std::string_view path) {
  std::string out;
  out.reserve(path.size());
  for (const char c : path) {
    const auto u = static_cast<unsigned char>(c);
    const bool unreserved = (u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z') || (u >= '0' && u <= '9') || c == '-' ||
                            c == '_' || c == '.' || c == '~' || c == '/';
    out += unreserved ? std::string(1, c) : fmt::format("%{:02X}", u);
  }
  return out;
}

}  // namespace pita::text
