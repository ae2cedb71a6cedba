#include "golden/svg_compare.hpp"

#include <cctype>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

namespace pita::golden {

namespace {

// The text with every <defs> ... </defs> block removed.
std::string without_defs(std::string_view svg) {
  std::string out;
  std::size_t at = 0;
  while (true) {
    const std::size_t start = svg.find("<defs", at);
    if (start == std::string_view::npos) break;
    out.append(svg.substr(at, start - at));
    const std::size_t end = svg.find("</defs>", start);
    if (end == std::string_view::npos) return out;  // unterminated: ignore the rest
    at = end + 7;
  }
  out.append(svg.substr(at));
  return out;
}

bool starts_number(std::string_view s, std::size_t i) {
  const char c = s[i];
  if (std::isdigit(static_cast<unsigned char>(c))) return true;
  if ((c == '-' || c == '+' || c == '.') && i + 1 < s.size()) {
    return std::isdigit(static_cast<unsigned char>(s[i + 1])) ||
           (s[i + 1] == '.' && i + 2 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 2])));
  }
  return false;
}

}  // namespace

std::vector<double> svg_numbers(std::string_view svg) {
  const std::string text = without_defs(svg);
  std::vector<double> numbers;
  // Numbers are read only inside attribute values (between quotes within a
  // tag), so element and attribute names never count; the values of ids,
  // hrefs ("#glyph0-1") and namespaces are skipped, and digits that end an
  // identifier ("surface1") are not numbers.
  bool in_tag = false, in_value = false, skip_value = false;
  char quote = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (!in_tag) {
      if (c == '<') in_tag = true;
      continue;
    }
    if (!in_value) {
      if (c == '>') {
        in_tag = false;
      } else if (c == '"' || c == '\'') {
        in_value = true;
        quote = c;
        // The attribute's name precedes "=".
        std::size_t end = i;
        while (end > 0 && (text[end - 1] == '=' || text[end - 1] == ' ')) --end;
        std::size_t begin = end;
        while (begin > 0 && !std::isspace(static_cast<unsigned char>(text[begin - 1]))) --begin;
        const std::string_view name(text.data() + begin, end - begin);
        skip_value = name == "id" || name.ends_with("href") || name == "version" || name == "xmlns" ||
                     name.starts_with("xmlns:");
      }
      continue;
    }
    if (c == quote) {
      in_value = false;
      continue;
    }
    if (skip_value || !starts_number(text, i)) continue;
    // Not the tail of an identifier ("rgb(20%" is fine; "surface1" is skipped via id).
    if (i > 0 && (std::isalpha(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '_')) {
      while (i + 1 < text.size() && std::isalnum(static_cast<unsigned char>(text[i + 1]))) ++i;
      continue;
    }
    std::size_t start = i + (text[i] == '+' ? 1 : 0);
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data() + start, text.data() + text.size(), value);
    if (error == std::errc{}) {
      numbers.push_back(value);
      i = static_cast<std::size_t>(end - text.data()) - 1;
    }
  }
  return numbers;
}

SvgComparison compare_svg(std::string_view expected, std::string_view actual, double tolerance) {
  const std::vector<double> e = svg_numbers(expected), a = svg_numbers(actual);
  SvgComparison c;
  c.expected_count = e.size();
  c.actual_count = a.size();
  if (e.size() != a.size()) {
    c.matches = false;
    return c;
  }
  for (std::size_t i = 0; i < e.size(); ++i) {
    const double d = std::abs(a[i] - e[i]);
    if (!(d <= tolerance)) {
      ++c.differing;
      c.matches = false;
    }
    if (i == 0 || !(d <= c.difference)) {
      c.worst = i;
      c.expected = e[i];
      c.actual = a[i];
      c.difference = std::isnan(d) ? INFINITY : d;
    }
  }
  return c;
}

std::string describe(const SvgComparison& c, double tolerance) {
  if (c.expected_count != c.actual_count) {
    return fmt::format("the SVG draws {} numbers where the golden has {} (its paths changed)", c.actual_count,
                       c.expected_count);
  }
  return fmt::format(
      "{} of {} SVG numbers differ by more than {:g} px; the worst, number {}, "
      "is {} instead of {}",
      c.differing, c.expected_count, tolerance, c.worst, c.actual, c.expected);
}

}  // namespace pita::golden
