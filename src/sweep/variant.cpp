#include "sweep/variant.hpp"

#include <optional>

#include <fmt/format.h>

#include "core/fnv1a.hpp"
#include "scene/did_you_mean.hpp"
#include "scene/json_reader.hpp"
#include "scene/json_text.hpp"
#include "scene/limits.hpp"
#include "scene/scene.hpp"

namespace pita::sweep {

namespace {

// What an error about `axis` names: its POINTER=SPEC.
About about_axis(const Axis& axis) { return About(Input::vary, axis.pointer + "=" + axis.spec); }

bool is_index(const std::string& token) {
  return !token.empty() && token.find_first_not_of("0123456789") == std::string::npos &&
         (token.size() == 1 || token.front() != '0');
}

// The tokens of a JSON Pointer, unescaped.
std::vector<std::string> tokens_of(const std::string& pointer) {
  std::vector<std::string> tokens;
  Json::json_pointer p(pointer);
  while (!p.empty()) {
    tokens.insert(tokens.begin(), p.back());
    p.pop_back();
  }
  return tokens;
}

// The pointer that exists and is nearest to `tokens`: each missing member
// replaced by the closest existing name, a missing element by the last one,
// as far as the document goes.
std::string nearest_pointer(const Json& document, const std::vector<std::string>& tokens) {
  const Json* at = &document;
  std::string nearest;
  for (const std::string& token : tokens) {
    if (at->is_object()) {
      if (at->contains(token)) {
        nearest = scene::detail::member_pointer(nearest, token);
        at = &(*at)[token];
        continue;
      }
      std::vector<std::string> names;
      for (const auto& [key, value] : at->items()) names.push_back(key);
      std::vector<std::string_view> views(names.begin(), names.end());
      const std::vector<std::string> close = scene::closest_names(token, views);
      if (close.empty()) break;
      nearest = scene::detail::member_pointer(nearest, close.front());
      at = &(*at)[close.front()];
    } else if (at->is_array() && !at->empty()) {
      const std::size_t last = at->size() - 1;
      const std::size_t i = is_index(token) ? std::min<std::size_t>(std::stoull(token.substr(0, 18)), last) : last;
      nearest += '/';
      nearest += std::to_string(i);
      at = &(*at)[i];
    } else {
      break;
    }
  }
  return nearest.empty() ? "\"\" (the whole scene)" : nearest;
}

// Sets `value` at `tokens`, creating missing members as objects; throws
// SweepUsageError when an element is missing or a step is not a container.
void set_at(Json& document, const Axis& axis, const std::vector<std::string>& tokens, const Json& value,
            const Json& base) {
  Json* at = &document;
  std::string walked;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const std::string& token = tokens[i];
    const bool last = i + 1 == tokens.size();
    if (at->is_object()) {
      if (last) {
        (*at)[token] = value;
        return;
      }
      if (!at->contains(token)) {
        // A missing member is created as an object; an array cannot be made
        // up, element by element, from a pointer.
        if (is_index(tokens[i + 1]) || tokens[i + 1] == "-") {
          throw SweepUsageError(about_axis(axis), fmt::format("{} has no \"{}\", and a pointer cannot create an array; "
                                                              "the nearest pointer that exists is {}",
                                                              walked.empty() ? "the scene" : walked, token,
                                                              nearest_pointer(base, tokens_of(axis.pointer))));
        }
        (*at)[token] = Json::object();
      }
      at = &(*at)[token];
    } else if (at->is_array()) {
      if (!is_index(token) || token.size() > 18 || std::stoull(token) >= at->size()) {
        throw SweepUsageError(about_axis(axis),
                              fmt::format("{} has no element \"{}\" ({} element{}); the nearest "
                                          "pointer that exists is {}",
                                          walked.empty() ? "the scene" : walked, token, at->size(),
                                          at->size() == 1 ? "" : "s", nearest_pointer(base, tokens_of(axis.pointer))));
      }
      const std::size_t index = std::stoull(token);
      if (last) {
        (*at)[index] = value;
        return;
      }
      at = &(*at)[index];
    } else {
      throw SweepUsageError(about_axis(axis),
                            fmt::format("{} is {}, not an object or array, so it has no \"{}\"; the "
                                        "nearest pointer that exists is {}",
                                        walked.empty() ? "the scene" : walked, std::string(at->type_name()), token,
                                        nearest_pointer(base, tokens_of(axis.pointer))));
    }
    walked = scene::detail::member_pointer(walked, token);
  }
}

// An axis every value of which the scene reader refuses at the axis's
// pointer (or inside it), the other axes at their first values, runs no
// variant: refused as usage, with the first value's reason (an option the
// method does not read, magnitudes all negative). Axes of up to
// kMaxValuesTried values are tried.
constexpr std::size_t kMaxValuesTried = 100;

void check_axes_run(const BaseScene& base, const Grid& grid) {
  const std::vector<Json> first = grid.values(0);
  for (std::size_t k = 0; k < grid.axes().size(); ++k) {
    const Axis& axis = grid.axes()[k];
    if (axis.size() > kMaxValuesTried || (grid.zip() && grid.axes().size() > 1)) continue;
    std::optional<std::string> reason;
    bool all_refused = true;
    for (std::size_t i = 0; i < axis.size() && all_refused; ++i) {
      std::vector<Json> values = first;
      values[k] = axis.value(i);
      try {
        (void)scene::parse_scene(variant_text(variant_document(base, grid, values)), base.path);
        all_refused = false;
      } catch (const scene::SceneError& error) {
        const bool at_axis = error.pointer() == axis.pointer || error.pointer().starts_with(axis.pointer + "/");
        all_refused = at_axis;
        if (at_axis && !reason) reason = fmt::format("{}: {}", error.pointer(), error.reason());
      }
    }
    if (all_refused && reason) {
      throw SweepUsageError(about_axis(axis),
                            fmt::format("every value is refused, so no variant would run: {}", *reason));
    }
  }
}

}  // namespace

BaseScene load_base(const std::string& path, const Grid& grid) {
  BaseScene base;
  base.path = path;
  const std::string text = scene::read_input_file(path, scene::kMaxSceneFileBytes, "scene file");
  // A bad base scene is bad input (exit 2), named by the reader.
  (void)scene::parse_scene(text, path);
  base.document = Json::parse(text);
  if (grid.size() == 0) return base;
  // Every pointer settable, and the first variant read: a member the scene
  // may not have is refused there, at a pointer the sweep created.
  const std::vector<Json> first = grid.values(0);
  Json document = base.document;
  for (std::size_t k = 0; k < grid.axes().size(); ++k) {
    set_at(document, grid.axes()[k], tokens_of(grid.axes()[k].pointer), first[k], base.document);
  }
  try {
    (void)scene::parse_scene(variant_text(document), path);
  } catch (const scene::SceneError& error) {
    if (error.reason().starts_with("unknown field")) {
      for (const Axis& axis : grid.axes()) {
        const bool created = !base.document.contains(Json::json_pointer(axis.pointer));
        const bool under = axis.pointer == error.pointer() || axis.pointer.starts_with(error.pointer() + "/");
        if (created && under) {
          throw SweepUsageError(about_axis(axis), fmt::format("{} is not in {} and the scene may not have it: {}; the "
                                                              "nearest pointer that exists is {}",
                                                              axis.pointer, path, error.reason(),
                                                              nearest_pointer(base.document, tokens_of(axis.pointer))));
        }
      }
    }
    // Any other error is the first variant's own: it is a failed row.
  }
  check_axes_run(base, grid);
  return base;
}

Json variant_document(const BaseScene& base, const Grid& grid, const std::vector<Json>& values) {
  Json document = base.document;
  for (std::size_t k = 0; k < grid.axes().size(); ++k) {
    set_at(document, grid.axes()[k], tokens_of(grid.axes()[k].pointer), values[k], base.document);
  }
  // The title says what varies: the values its "{/pointer}" templates do
  // not show already follow it, "(/method = P3)".
  const auto title = document.find("title");
  if (title != document.end() && title->is_string() && !title->get<std::string>().empty()) {
    std::string text = title->get<std::string>();
    std::string added;
    for (std::size_t k = 0; k < grid.axes().size(); ++k) {
      const std::string& pointer = grid.axes()[k].pointer;
      if (pointer == "/title" || text.find("{" + pointer + "}") != std::string::npos) continue;
      added += fmt::format("{}{} = {}", added.empty() ? "" : ", ", pointer, value_text(values[k]));
    }
    if (!added.empty()) *title = text + " (" + added + ")";
  }
  return document;
}

std::string variant_text(const Json& document) { return document.dump(2) + "\n"; }

std::string content_hash(const std::string& text, const std::string& salt) {
  Fnv1a hash;
  hash.add(std::string_view(text));
  hash.add(std::string_view("\0", 1));
  hash.add(std::string_view(salt));
  return fmt::format("{:016x}", hash.value());
}

}  // namespace pita::sweep
