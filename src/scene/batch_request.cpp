#include "scene/batch_request.hpp"

#include <cstdio>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "scene/json_text.hpp"
#include "scene/limits.hpp"
#include "scene/scene.hpp"

namespace pita::scene {

bool next_batch_line(std::FILE* file, BatchLine& line) {
  line.text.clear();
  line.too_long = false;
  bool any = false;
  // A byte at a time (getc_unlocked is a buffered read): a NUL byte is part
  // of its line (the request's JSON then refuses it), never the end of it.
  for (int c = getc_unlocked(file); c != EOF; c = getc_unlocked(file)) {
    any = true;
    if (c == '\n') return true;
    if (line.too_long) continue;
    if (line.text.size() >= kMaxBatchLineBytes) {
      line.too_long = true;
      line.text = std::string();  // its memory too
      continue;
    }
    line.text.push_back(static_cast<char>(c));
  }
  return any;
}

std::vector<std::string> batch_request_arguments(std::string_view text, const std::string& where) {
  nlohmann::ordered_json request;
  try {
    request = parse_json(text, where);
  } catch (const SceneError& error) {
    throw SceneError(where, "", fmt::format("column {}: {}", error.column(), error.reason()));
  }
  if (!request.is_array()) {
    throw SceneError(where, "",
                     "a request is the arguments of one `pita eval` as a JSON array of "
                     "strings, for example [\"scene.json\", \"--t=0,0.5\"]");
  }
  std::vector<std::string> arguments;
  for (std::size_t i = 0; i < request.size(); ++i) {
    if (!request[i].is_string()) throw SceneError(where, fmt::format("/{}", i), "an argument must be a string");
    arguments.push_back(request[i].get<std::string>());
    // A command line cannot hold one either ("secret.txt\u0000.json" would be cut short).
    if (arguments.back().find('\0') != std::string::npos) {
      throw SceneError(where, fmt::format("/{}", i), "an argument must not hold a NUL character (\\u0000)");
    }
  }
  return arguments;
}

}  // namespace pita::scene
