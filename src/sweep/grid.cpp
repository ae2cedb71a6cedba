#include "sweep/grid.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <set>

#include <fmt/format.h>

namespace pita::sweep {

namespace {

// What an error about the argument `argument` of an axis names.
About about_vary(std::string_view argument) { return About(Input::vary, std::string(argument)); }

// Integral values within 2^53 become JSON integers, so that a swept count
// ("/samples") reads as an integer and "0:1:3" sets 0, 0.5 and 1.
Json number_value(double v) {
  if (std::nearbyint(v) == v && std::abs(v) < 9007199254740992.0) return Json(static_cast<std::int64_t>(v));
  return Json(v);
}

bool parse_double(std::string_view text, double& out) {
  if (text.empty()) return false;
  const char* first = text.data();
  if (*first == '+') ++first;  // from_chars takes no '+'
  const auto [end, error] = std::from_chars(first, text.data() + text.size(), out);
  return error == std::errc() && end == text.data() + text.size();
}

double finite_number(std::string_view text, std::string_view argument, std::string_view what) {
  double v = 0;
  if (!parse_double(text, v) || !std::isfinite(v)) {
    throw SweepUsageError(about_vary(argument), fmt::format("{} must be a finite number (got \"{}\")", what, text));
  }
  return v;
}

std::int64_t count(std::string_view text, std::string_view argument) {
  std::int64_t n = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) {
    throw SweepUsageError(about_vary(argument),
                          fmt::format("the count n must be a whole number >= 1 (got \"{}\")", text));
  }
  if (n < 1) throw SweepUsageError(about_vary(argument), fmt::format("the count n must be >= 1 (got {})", n));
  if (n > kMaxVariants) {
    throw SweepUsageError(about_vary(argument),
                          fmt::format("the count n must be at most {} (got {})", kMaxVariants, n));
  }
  return n;
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t at = text.find(separator, start);
    parts.push_back(text.substr(start, at == std::string_view::npos ? std::string_view::npos : at - start));
    if (at == std::string_view::npos) return parts;
    start = at + 1;
  }
}

// The items of a list, split at commas outside JSON strings ("a,b" is one item).
std::vector<std::string_view> split_list(std::string_view text, std::string_view argument) {
  std::vector<std::string_view> items;
  std::size_t start = 0;
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (quoted) {
      if (text[i] == '\\') {
        ++i;
      } else if (text[i] == '"') {
        quoted = false;
      }
    } else if (text[i] == '"') {
      quoted = true;
    } else if (text[i] == ',') {
      items.push_back(text.substr(start, i - start));
      start = i + 1;
    }
  }
  if (quoted) throw SweepUsageError(about_vary(argument), "a quoted value is not closed");
  items.push_back(text.substr(start));
  return items;
}

Json list_item(std::string_view item) {
  double v = 0;
  if (parse_double(item, v) && std::isfinite(v)) return number_value(v);
  if (item == "true") return Json(true);
  if (item == "false") return Json(false);
  if (item == "null") return Json(nullptr);
  return Json(std::string(item));
}

// `text` with its control characters as \xNN, for a message.
std::string printable_item(std::string_view text) {
  std::string out;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    out += u < 0x20 || u == 0x7f ? fmt::format("\\x{:02x}", static_cast<unsigned>(u)) : std::string(1, c);
  }
  return out;
}

// A NUL or a terminal control (ESC, BEL) would go into manifest.csv,
// index.html and messages: swept text is printable (tabs and line breaks
// allowed).
void check_printable(const std::string& text, std::string_view item) {
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if ((u < 0x20 && c != '\t' && c != '\n') || u == 0x7f) {
      throw SweepUsageError(About{Input::vary},
                            fmt::format("{} contains the control character U+{:04X}: a swept string must be "
                                        "printable text",
                                        printable_item(item), static_cast<unsigned>(u)));
    }
  }
}

}  // namespace

Axis parse_axis(std::string_view argument) {
  const std::size_t equals = argument.find('=');
  if (equals == std::string_view::npos) {
    throw SweepUsageError(about_vary(argument), "expected POINTER=SPEC, for example /keyframes/1/t=0.2:0.8:7");
  }
  Axis axis;
  axis.pointer = std::string(argument.substr(0, equals));
  axis.spec = std::string(argument.substr(equals + 1));
  if (axis.pointer.empty() || axis.pointer.front() != '/') {
    throw SweepUsageError(
        about_vary(argument),
        fmt::format("the pointer must be a JSON Pointer starting with '/' (got \"{}\")", axis.pointer));
  }
  try {
    (void)Json::json_pointer(axis.pointer);
  } catch (const Json::exception& error) {
    throw SweepUsageError(about_vary(argument),
                          fmt::format("\"{}\" is not a JSON Pointer ({})", axis.pointer, error.what()));
  }
  const std::string_view spec = argument.substr(equals + 1);
  if (spec.empty()) throw SweepUsageError(about_vary(argument), "the SPEC after '=' is empty");
  const std::vector<std::string_view> colon = split(spec, ':');
  const bool geometric = colon.size() == 4 && colon[0] == "log";
  const bool has_quotes = spec.find('"') != std::string_view::npos;  // a list of JSON strings
  if (!has_quotes && (colon.size() == 3 || geometric)) {
    const std::size_t k = geometric ? 1 : 0;
    const double a = finite_number(colon[k], argument, "a");
    const double b = finite_number(colon[k + 1], argument, "b");
    const std::int64_t n = count(colon[k + 2], argument);
    if (geometric && !(a * b > 0)) {
      throw SweepUsageError(about_vary(argument),
                            fmt::format("log:a:b:n needs a and b of one sign and not 0 (got {} and {})", a, b));
    }
    // Every value between the ends must be a finite number too.
    // (A geometric axis steps in logarithms, so log:1e-300:1e300:5 is fine.)
    if (!geometric && !std::isfinite(b - a)) {
      throw SweepUsageError(about_vary(argument),
                            fmt::format("the values between {} and {} are not all finite numbers", a, b));
    }
    axis.kind = geometric ? Axis::Kind::geometric : Axis::Kind::linear;
    axis.a = a;
    axis.b = b;
    axis.n = n;
    return axis;
  }
  if (colon.size() != 1 && spec.find(',') == std::string_view::npos && !has_quotes) {
    throw SweepUsageError(about_vary(argument),
                          fmt::format("SPEC must be a:b:n, log:a:b:n or a list v1,v2,... (got \"{}\")", spec));
  }
  for (const std::string_view item : split_list(spec, argument)) {
    if (item.empty()) {
      throw SweepUsageError(about_vary(argument), fmt::format("an empty value in the list \"{}\"", spec));
    }
    if (item.front() == '"') {
      // A JSON string: any text, commas and quotes included ("1" is a string).
      try {
        const Json parsed = Json::parse(item);
        if (!parsed.is_string()) throw std::runtime_error("not a string");
        axis.items.push_back(parsed);
      } catch (const std::exception&) {
        throw SweepUsageError(about_vary(argument), fmt::format("{} is not a JSON string", item));
      }
      check_printable(axis.items.back().get_ref<const std::string&>(), item);
      continue;
    }
    axis.items.push_back(list_item(item));
    if (axis.items.back().is_string()) check_printable(axis.items.back().get_ref<const std::string&>(), item);
  }
  return axis;
}

Json Axis::value(std::size_t i) const {
  if (kind == Kind::list) return items.at(i);
  // The ends exactly as typed; between them the linear or geometric step.
  const auto k = static_cast<std::int64_t>(i);
  if (k == 0) return number_value(a);
  if (k == n - 1) return number_value(b);
  const double u = static_cast<double>(k) / static_cast<double>(n - 1);
  // Geometric: a (b/a)^u in logarithms (b/a may overflow: log:1e-300:1e300:5).
  const double v =
      kind == Kind::geometric
          ? std::copysign(std::exp(std::log(std::abs(a)) + (std::log(std::abs(b)) - std::log(std::abs(a))) * u), a)
          : a + (b - a) * u;
  // Rounded to 15 significant digits, so that 0.1:0.9:5 sets 0.3, not
  // 0.30000000000000004 (the step's rounding is not the user's value).
  const std::string rounded = fmt::format("{:.15g}", v);
  return number_value(std::strtod(rounded.c_str(), nullptr));  // strtod: no exception for subnormals
}

Grid::Grid(std::vector<Axis> axes, bool zip) : axes_(std::move(axes)), zip_(zip) {
  if (axes_.empty()) throw SweepUsageError(About{Input::vary}, "give at least one POINTER=SPEC");
  std::set<std::string> seen;
  for (const Axis& axis : axes_) {
    if (!seen.insert(axis.pointer).second) {
      throw SweepUsageError(About{Input::vary}, fmt::format("the pointer {} is varied twice", axis.pointer));
    }
  }
  if (zip_) {
    for (const Axis& axis : axes_) {
      if (axis.size() != axes_.front().size()) {
        throw SweepUsageError(About{Input::zip},
                              fmt::format("values are paired one by one, so every axis needs as "
                                          "many: {} has {}, {} has {}",
                                          axes_.front().pointer, axes_.front().size(), axis.pointer, axis.size()));
      }
    }
    size_ = static_cast<std::int64_t>(axes_.front().size());
    return;
  }
  size_ = 1;
  for (const Axis& axis : axes_) {
    const auto n = static_cast<std::int64_t>(axis.size());
    if (size_ > kMaxVariants / n) {
      std::string sizes;
      for (const Axis& a : axes_) sizes += fmt::format("{}{}", sizes.empty() ? "" : " x ", a.size());
      throw SweepUsageError(About{Input::vary},
                            fmt::format("{} variants is more than the limit of {}; sweep fewer values or "
                                        "split the sweep",
                                        sizes, kMaxVariants));
    }
    size_ *= n;
  }
}

std::vector<std::size_t> Grid::positions(std::int64_t index) const {
  std::vector<std::size_t> at(axes_.size());
  if (zip_) {
    for (std::size_t& p : at) p = static_cast<std::size_t>(index);
    return at;
  }
  for (std::size_t k = axes_.size(); k-- > 0;) {
    const auto n = static_cast<std::int64_t>(axes_[k].size());
    at[k] = static_cast<std::size_t>(index % n);
    index /= n;
  }
  return at;
}

std::vector<Json> Grid::values(std::int64_t index) const {
  const std::vector<std::size_t> at = positions(index);
  std::vector<Json> result;
  result.reserve(at.size());
  for (std::size_t k = 0; k < at.size(); ++k) result.push_back(axes_[k].value(at[k]));
  return result;
}

std::string value_text(const Json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number_float()) return fmt::format("{}", value.get<double>());
  return value.dump();
}

}  // namespace pita::sweep
