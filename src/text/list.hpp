// Lists of items written with a separator, as command-line values are
// ("--format svg,png", "--t 0,0.5,1", "--methods P1,P6"): one splitter for
// every such list.
#pragma once

#include <cstddef>
#include <string_view>

namespace pita::text {

// Calls `item(text)` for each item of `text` between separators, in order, as
// std::string_view into `text`: "a,b" gives "a" and "b"; "" gives ""; "a,,b"
// and "a," give empty items too, which the caller refuses or skips with its
// own message. Items are not trimmed. The items are visited one at a time, so
// that a long list (a million times) is never copied and the caller may stop
// at its own limit by throwing.
template <class Visit>
void for_each_item(std::string_view text, Visit&& item, char separator = ',') {
  std::size_t start = 0;
  while (true) {
    const std::size_t stop = text.find(separator, start);
    item(text.substr(start, stop == std::string_view::npos ? std::string_view::npos : stop - start));
    if (stop == std::string_view::npos) return;
    start = stop + 1;
  }
}

}  // namespace pita::text
