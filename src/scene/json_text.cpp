// The JSON text of a scene: read with a size limit, scanned for its nesting
// depth, parsed with nlohmann, with the checks the DOM cannot make afterwards
// (a NUL byte, a member given twice, numbers beyond a double, positions of
// syntax errors as line and column).
#include "scene/json_text.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "io/input_file.hpp"
#include "scene/limits.hpp"
#include "scene/scene.hpp"

namespace pita::scene {

using Json = nlohmann::ordered_json;

namespace {

std::pair<int, int> line_and_column(std::string_view text, std::size_t index) {
  index = std::min(index, text.size());
  const std::string_view before = text.substr(0, index);
  const auto line = 1 + std::count(before.begin(), before.end(), '\n');
  const std::size_t line_start = before.rfind('\n') == std::string_view::npos ? 0 : before.rfind('\n') + 1;
  return {static_cast<int>(line), static_cast<int>(index - line_start + 1)};
}

// nlohmann's message without its "[json.exception.parse_error.101] parse error
// at line 3, column 14: " prefix (we print our own position).
std::string parse_error_reason(const std::string& message) {
  const std::size_t start = message.find("parse error");
  if (start == std::string::npos) return message;
  const std::size_t colon = message.find(": ", start);
  if (colon == std::string::npos) return message;
  return message.substr(colon + 2);
}

// A number too large for a double (1e999) is refused by nlohmann with an
// out_of_range exception that carries no position. This event-only second
// pass finds where: the parser reports the position just after the number.
class NumberOverflowLocator : public nlohmann::json_sax<Json> {
 public:
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t position, const std::string& last_token, const Json::exception&) override {
    end = position;
    token = last_token;
    return false;
  }

  std::size_t end = 0;  // bytes read, up to and including the number
  std::string token;    // the number as written
};

// A member given twice in one object ("m": 1, "m": -1): JSON leaves its
// meaning open and nlohmann keeps the last one silently, so we refuse it.
struct DuplicateKey {
  std::string pointer;
  std::string key;
};

// Follows the parser's events to know the JSON Pointer of the value being
// read, and throws DuplicateKey at a member's second occurrence. A pass of
// its own, before the DOM is built: nlohmann's callback parser, which could
// watch the events while building, walks the enclosing array at the end of
// each object, so that 300 000 keyframes took 26 s to be refused.
class DuplicateKeyFinder : public nlohmann::json_sax<Json> {
 public:
  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return start(false); }
  bool start_array(std::size_t) override { return start(true); }
  bool end_object() override { return end(); }
  bool end_array() override { return end(); }
  bool key(string_t& name) override {
    Frame& top = stack_.back();
    top.key = name;
    if (!top.keys.insert(top.key).second) throw DuplicateKey{pointer(), top.key};
    return true;
  }
  // The parser's own error is reported by the parse that builds the DOM.
  bool parse_error(std::size_t, const std::string&, const Json::exception&) override { return false; }

 private:
  struct Frame {
    bool array = false;
    std::size_t index = 0;
    std::set<std::string> keys;
    std::string key;
  };

  bool value() {
    next_element();
    return true;
  }
  bool start(bool array) {
    stack_.emplace_back();
    stack_.back().array = array;
    return true;
  }
  bool end() {
    stack_.pop_back();
    next_element();
    return true;
  }

  void next_element() {
    if (!stack_.empty() && stack_.back().array) ++stack_.back().index;
  }

  std::string pointer() const {
    std::string text;
    for (const Frame& frame : stack_) {
      if (frame.array) {
        text += '/' + std::to_string(frame.index);
      } else {
        text += '/';
        for (char c : frame.key)
          text += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
      }
    }
    return text;
  }

  std::vector<Frame> stack_;
};

// The first place where arrays and objects nest deeper than kMaxJsonDepth, as
// a byte index, or npos. A linear scan that knows strings and escapes and
// nothing else: it runs before the parser, whose DOM building (and nlohmann's
// ordered_map copies) recurse once per level and overflow the stack on deep
// enough input (issue 11: 85 000 levels). Syntax errors are left to the parser.
std::size_t too_deep_at(std::string_view text) {
  std::size_t depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        in_string = false;
      }
      continue;
    }
    switch (c) {
      case '"':
        in_string = true;
        break;
      case '[':
      case '{':
        if (++depth > kMaxJsonDepth) return i;
        break;
      case ']':
      case '}':
        if (depth > 0) --depth;
        break;
      default:
        break;
    }
  }
  return std::string_view::npos;
}

}  // namespace

std::string read_input_file(const std::filesystem::path& path, std::size_t max_bytes, std::string_view what) {
  try {
    return io::read_regular_file(path, max_bytes);
  } catch (const io::InputError& error) {
    throw SceneError(path.string(), "", error.sentence(std::string(what)));
  }
}

Json parse_json(std::string_view text, const std::string& file) {
  // nlohmann stops at a NUL byte as if the text ended there.
  if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
    const auto [line, column] = line_and_column(text, nul);
    throw SceneError(file, line, column,
                     "the file contains a NUL byte: a scene is UTF-8 text (is this file UTF-16 "
                     "or binary?)");
  }
  if (const std::size_t deep = too_deep_at(text); deep != std::string_view::npos) {
    const auto [line, column] = line_and_column(text, deep);
    throw SceneError(file, line, column,
                     fmt::format("arrays and objects nest deeper than {} levels (no scene "
                                 "needs more than about 8)",
                                 kMaxJsonDepth));
  }
  try {
    DuplicateKeyFinder duplicates;
    Json::sax_parse(text, &duplicates);
    return Json::parse(text);
  } catch (const DuplicateKey& duplicate) {
    throw SceneError(file, duplicate.pointer,
                     fmt::format("field \"{}\" is given twice in the same object", duplicate.key));
  } catch (const Json::parse_error& error) {
    // error.byte counts the bytes read, the offending one included.
    const auto [line, column] = line_and_column(text, error.byte == 0 ? 0 : error.byte - 1);
    throw SceneError(file, line, column, "malformed JSON: " + parse_error_reason(error.what()));
  } catch (const Json::out_of_range&) {
    NumberOverflowLocator locator;
    Json::sax_parse(text, &locator);
    const std::size_t start = locator.end >= locator.token.size() ? locator.end - locator.token.size() : 0;
    const auto [line, column] = line_and_column(text, start);
    throw SceneError(file, line, column,
                     fmt::format("number {} is out of range (too large for a double)", locator.token));
  }
}

}  // namespace pita::scene
