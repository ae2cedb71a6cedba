#include "serve/json_edit.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace pita::serve {

namespace {

struct MemberSpan {
  std::string name;
  std::size_t key_begin = 0;
  std::size_t key_end = 0;
  TextSpan value;
};

// A reader of JSON text that knows where each value starts and ends; it
// checks the structure it walks through, not the whole grammar (the scene
// reader checks the result).
class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}

  // Skips the value at the position; returns where it ends.
  std::size_t skip_value() {
    space();
    if (at_ >= text_.size()) fail("a value");
    const char c = text_[at_];
    if (c == '{') {
      ++at_;
      space();
      if (peek('}')) return ++at_;
      while (true) {
        string();
        expect(':');
        skip_value();
        space();
        if (peek(',')) {
          ++at_;
          continue;
        }
        expect('}');
        return at_;
      }
    }
    if (c == '[') {
      ++at_;
      space();
      if (peek(']')) return ++at_;
      while (true) {
        skip_value();
        space();
        if (peek(',')) {
          ++at_;
          continue;
        }
        expect(']');
        return at_;
      }
    }
    if (c == '"') {
      string();
      return at_;
    }
    const std::size_t start = at_;
    while (at_ < text_.size() && std::string_view("{}[],: \t\r\n\"").find(text_[at_]) == std::string_view::npos) ++at_;
    if (at_ == start) fail("a value");
    return at_;
  }

  // The span of the member `key` of the object at the position, or of
  // element `index` of the array there.
  TextSpan member(const std::string& key) {
    space();
    expect('{');
    space();
    if (peek('}')) fail("member \"" + key + "\"");
    while (true) {
      const std::string name = string();
      expect(':');
      space();
      const std::size_t begin = at_;
      const std::size_t end = skip_value();
      if (name == key) return {begin, end};
      space();
      if (peek(',')) {
        ++at_;
        space();
        continue;
      }
      fail("member \"" + key + "\"");
    }
  }
  TextSpan element(std::size_t index) {
    space();
    expect('[');
    space();
    for (std::size_t i = 0;; ++i) {
      if (peek(']')) fail("element " + std::to_string(index));
      space();
      const std::size_t begin = at_;
      const std::size_t end = skip_value();
      if (i == index) return {begin, end};
      space();
      if (!peek(',')) fail("element " + std::to_string(index));
      ++at_;
    }
  }
  // Every member of the object at the position: where its key starts, where
  // its key's closing quote ends, and its value's span.
  std::vector<MemberSpan> members() {
    std::vector<MemberSpan> all;
    space();
    expect('{');
    space();
    while (!peek('}')) {
      MemberSpan m;
      m.key_begin = position();
      m.name = string();
      m.key_end = at_;
      expect(':');
      m.value.begin = position();
      m.value.end = skip_value();
      all.push_back(m);
      space();
      if (!peek(',')) break;
      ++at_;
      space();
    }
    space();
    if (!peek('}')) fail("'}'");
    return all;
  }
  bool object_here() {
    space();
    return peek('{');
  }
  bool array_here() {
    space();
    return peek('[');
  }
  void jump(std::size_t to) { at_ = to; }
  std::size_t position() {
    space();
    return at_;
  }

 private:
  void space() {
    while (at_ < text_.size() &&
           (text_[at_] == ' ' || text_[at_] == '\t' || text_[at_] == '\r' || text_[at_] == '\n')) {
      ++at_;
    }
  }
  bool peek(char c) const { return at_ < text_.size() && text_[at_] == c; }
  void expect(char c) {
    space();
    if (!peek(c)) fail(std::string("'") + c + "'");
    ++at_;
  }
  // A string at the position (escapes decoded: \" \\ \/ \b \f \n \r \t; \u as UTF-8).
  std::string string() {
    space();
    expect('"');
    std::string out;
    while (at_ < text_.size() && text_[at_] != '"') {
      char c = text_[at_++];
      if (c == '\\') {
        if (at_ >= text_.size()) break;
        c = text_[at_++];
        if (c == 'u') {
          if (at_ + 4 > text_.size()) fail("an escape");
          const unsigned code = static_cast<unsigned>(std::stoul(std::string(text_.substr(at_, 4)), nullptr, 16));
          at_ += 4;
          if (code < 0x80) {
            out += static_cast<char>(code);
          } else if (code < 0x800) {
            out += static_cast<char>(0xC0 | (code >> 6));
            out += static_cast<char>(0x80 | (code & 0x3F));
          } else {
            out += static_cast<char>(0xE0 | (code >> 12));
            out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (code & 0x3F));
          }
          continue;
        }
        const std::string_view from = "\"\\/bfnrt", to = "\"\\/\b\f\n\r\t";
        const std::size_t which = from.find(c);
        if (which == std::string_view::npos) fail("an escape");
        c = to[which];
      }
      out += c;
    }
    expect('"');
    return out;
  }
  [[noreturn]] void fail(const std::string& wanted) const {
    throw std::invalid_argument("expected " + wanted + " at byte " + std::to_string(at_));
  }

  std::string_view text_;
  std::size_t at_ = 0;
};

// The tokens of a JSON Pointer, unescaped (~1 is /, ~0 is ~).
std::vector<std::string> tokens(std::string_view pointer) {
  std::vector<std::string> all;
  if (pointer.empty()) return all;
  if (pointer.front() != '/') throw std::invalid_argument("a JSON Pointer starts with /");
  std::size_t start = 1;
  while (true) {
    const std::size_t slash = pointer.find('/', start);
    std::string token(pointer.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start));
    std::string out;
    for (std::size_t i = 0; i < token.size(); ++i) {
      if (token[i] == '~' && i + 1 < token.size() && (token[i + 1] == '0' || token[i + 1] == '1')) {
        out += token[i + 1] == '0' ? '~' : '/';
        ++i;
      } else {
        out += token[i];
      }
    }
    all.push_back(out);
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  return all;
}

}  // namespace

TextSpan value_span(std::string_view text, std::string_view pointer) {
  Scanner scanner(text);
  TextSpan span{scanner.position(), 0};
  span.end = scanner.skip_value();
  for (const std::string& token : tokens(pointer)) {
    scanner.jump(span.begin);
    if (scanner.object_here()) {
      span = scanner.member(token);
    } else if (scanner.array_here()) {
      if (token.empty() || token.find_first_not_of("0123456789") != std::string::npos || token.size() > 9) {
        throw std::invalid_argument("\"" + token + "\" is not an index of an array");
      }
      span = scanner.element(std::stoul(token));
    } else {
      throw std::invalid_argument("\"" + token + "\" is inside a value that is neither an object nor an array");
    }
  }
  return span;
}

std::string replace_value(std::string_view text, std::string_view pointer, std::string_view replacement) {
  const TextSpan span = value_span(text, pointer);
  std::string out(text.substr(0, span.begin));
  out += replacement;
  out += text.substr(span.end);
  return out;
}

namespace {

// The pointer of the first `count` tokens of `pointer`, spelled as given.
std::string pointer_prefix(std::string_view pointer, std::size_t count) {
  std::size_t end = 0;
  for (std::size_t k = 0; k < count; ++k) {
    end = pointer.find('/', end + 1);
    if (end == std::string_view::npos) return std::string(pointer);
  }
  return std::string(pointer.substr(0, end));
}

// A key as JSON text: quoted, with '"', '\\' and control characters escaped.
std::string quoted(const std::string& key) {
  std::string out = "\"";
  for (const char c : key) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      static const char* const kHex = "0123456789abcdef";
      out += "\\u00";
      out += kHex[(c >> 4) & 0xF];
      out += kHex[c & 0xF];
    } else {
      out += c;
    }
  }
  return out + "\"";
}

// The members of the object whose value is at `span` (throws when it is not an object).
std::vector<MemberSpan> members_of(std::string_view text, TextSpan span) {
  Scanner scanner(text);
  scanner.jump(span.begin);
  if (!scanner.object_here()) throw std::invalid_argument("a member can be added to an object only");
  return scanner.members();
}

}  // namespace

std::string set_value(std::string_view text, std::string_view pointer, std::string_view value, Undo* undo) {
  try {
    const TextSpan span = value_span(text, pointer);
    if (undo != nullptr) *undo = {std::string(pointer), std::string(text.substr(span.begin, span.end - span.begin))};
    return replace_value(text, pointer, value);
  } catch (const std::invalid_argument&) {
    // Not there: added below, to the deepest object on the way that is.
  }
  const std::vector<std::string> names = tokens(pointer);
  if (names.empty()) throw std::invalid_argument("the whole document cannot be added");
  std::size_t have = names.size() - 1;  // tokens of the deepest value there
  TextSpan parent{};
  while (true) {
    try {
      parent = value_span(text, pointer_prefix(pointer, have));
      break;
    } catch (const std::invalid_argument&) {
      if (have == 0) throw;
      --have;
    }
  }
  // The missing objects, innermost first, written on one line.
  std::string added(value);
  for (std::size_t k = names.size() - 1; k > have; --k) added = "{" + quoted(names[k]) + ": " + added + "}";
  const std::vector<MemberSpan> members = members_of(text, parent);
  std::string inserted;
  std::size_t at = 0;
  if (members.empty()) {
    // Right after the '{': "{}" becomes {"key": value}, "{ }" {"key": value }.
    at = parent.begin + 1;
    inserted = quoted(names[have]) + ": " + added;
  } else {
    // After the last member, spaced as it is: the bytes before its key
    // (a line break and indent, or a space) and between its key and value.
    const MemberSpan& last = members.back();
    std::size_t space = last.key_begin;
    while (space > parent.begin + 1 && std::string_view(" \t\r\n").find(text[space - 1]) != std::string_view::npos) {
      --space;
    }
    std::string before(text.substr(space, last.key_begin - space));
    if (before.empty() && members.size() == 1) before = " ";
    at = last.value.end;
    inserted = "," + before + quoted(names[have]) +
               std::string(text.substr(last.key_end, last.value.begin - last.key_end)) + added;
  }
  if (undo != nullptr) *undo = {pointer_prefix(pointer, have + 1), std::nullopt};
  std::string out(text.substr(0, at));
  out += inserted;
  out += text.substr(at);
  return out;
}

std::string remove_member(std::string_view text, std::string_view pointer) {
  const std::vector<std::string> names = tokens(pointer);
  if (names.empty()) throw std::invalid_argument("the whole document cannot be removed");
  const TextSpan parent = value_span(text, pointer_prefix(pointer, names.size() - 1));
  const std::vector<MemberSpan> members = members_of(text, parent);
  for (std::size_t j = 0; j < members.size(); ++j) {
    if (members[j].name != names.back()) continue;
    // The bytes set_value adds: from the end of the member before (its comma
    // and spacing) or, for the only member, from the '{'.
    std::size_t begin = j > 0 ? members[j - 1].value.end : parent.begin + 1;
    std::size_t end = members[j].value.end;
    if (j == 0 && members.size() > 1) {
      begin = members[0].key_begin;
      end = members[1].key_begin;
    }
    std::string out(text.substr(0, begin));
    out += text.substr(end);
    return out;
  }
  throw std::invalid_argument("expected member \"" + names.back() + "\" to remove");
}

}  // namespace pita::serve
