#include "scene/title_template.hpp"

#include <fmt/format.h>

namespace pita::scene::detail {

std::string expand_title(const JsonReader& reader, const Json& document, const std::string& title,
                         const std::string& pointer) {
  std::string out;
  std::size_t at = 0;
  while (true) {
    const std::size_t open = title.find("{/", at);
    if (open == std::string::npos) break;
    const std::size_t close = title.find('}', open);
    if (close == std::string::npos) break;  // no template: the text as it is
    const std::string field = title.substr(open + 1, close - open - 1);
    const Json* value = nullptr;
    try {
      const Json::json_pointer path(field);
      if (document.contains(path)) value = &document.at(path);
    } catch (const Json::exception&) {
      value = nullptr;  // not a JSON Pointer ("{/a~2}"): named below
    }
    if (value == nullptr) {
      reader.fail(pointer, fmt::format("\"{{{}}}\" names no field of the scene (a title's \"{{/...}}\" shows the "
                                       "value at that JSON Pointer, such as \"{{/method}}\")",
                                       field));
    }
    if (value->is_object() || value->is_array()) {
      reader.fail(pointer, fmt::format("\"{{{}}}\" names {}; name a number or a string inside it", field,
                                       value->is_object() ? "an object" : "an array"));
    }
    out += title.substr(at, open - at);
    out += value->is_string()   ? value->get<std::string>()
           : value->is_number() ? number_text(value->get<double>())
                                : value->dump();
    at = close + 1;
  }
  return out + title.substr(at);
}

}  // namespace pita::scene::detail
