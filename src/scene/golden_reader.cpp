// "golden": a scene's own tolerances for `pita check` (docs/reference/check.md "Goldens").
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "scene/scene_readers.hpp"

namespace pita::scene::detail {

namespace {
constexpr std::array<std::string_view, 4> kGoldenFields = {"number_tolerance", "svg_tolerance", "pixel_tolerance",
                                                           "max_differing"};
}  // namespace

// "golden": {"number_tolerance", "svg_tolerance", "pixel_tolerance", "max_differing"}.
void read_golden(const JsonReader& reader, const Json& value, Scene::GoldenTolerances& out) {
  reader.object(value, "/golden", "\"golden\"");
  reader.check_fields(value, "/golden", kGoldenFields);
  if (const Json* x = JsonReader::member(value, "number_tolerance")) {
    out.numbers = reader.number(*x, "/golden/number_tolerance", Interval{0.0, 1.0});
  }
  if (const Json* x = JsonReader::member(value, "svg_tolerance")) {
    out.svg = reader.number(*x, "/golden/svg_tolerance", Interval{0.0, 1000.0});
  }
  if (const Json* x = JsonReader::member(value, "pixel_tolerance")) {
    out.pixel = reader.integer(*x, "/golden/pixel_tolerance", 0, 255);
  }
  if (const Json* x = JsonReader::member(value, "max_differing")) {
    out.max_differing = reader.number(*x, "/golden/max_differing", Interval{0.0, 1.0});
  }
}

}  // namespace pita::scene::detail
