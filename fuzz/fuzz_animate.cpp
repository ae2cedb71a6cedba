// Bytes -> the text that `pita animate` reads besides the scene's layers
// (docs/reference/animate.md "Animation"): the first line is the command
// line's options as a JSON object ({"fps", "duration", "frames", "out",
// "format", "scale", "budget"}, any of them), the rest a scene. The scene's
// "animation" and the options make the timeline (make_timeline), OUT its kind
// (output_kind), and the total work is checked (check_total_work). The same
// rest, written as frames.json into a folder of frame files, decides whether
// that folder is a frame directory pita may replace (is_frame_directory).
// Refusals are SceneError and AnimationError (exit 2); a timeline that is made
// has 2 to kMaxAnimationFrames frames at finite times in order.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <type_traits>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "animate/output.hpp"
#include "animate/timeline.hpp"
#include "fuzz_support.hpp"
#include "render/figure.hpp"
#include "render/panel_drawing.hpp"
#include "scene/limits.hpp"
#include "scene/scene.hpp"

namespace {

using namespace pita;
namespace fs = std::filesystem;
using Json = nlohmann::json;

const fs::path& frames_dir() {
  static const bool made = [] {
    fs::create_directories(fuzz::scratch_path("pita-fuzz-animate-"));
    std::ofstream(fuzz::scratch_path() / "frame-0001.png") << "not a png";
    return true;
  }();
  (void)made;
  return fuzz::scratch_path();
}

template <typename T>
std::optional<T> option(const Json& options, const char* name) {
  if (!options.is_object() || !options.contains(name)) return std::nullopt;
  const Json& v = options[name];
  if constexpr (std::is_same_v<T, std::string>) {
    if (v.is_string()) return v.get<std::string>();
  } else if constexpr (std::is_same_v<T, int>) {  // CLI11 reads --frames as an int
    if (v.is_number_integer() && v.get<std::int64_t>() >= -1'000'000'000 && v.get<std::int64_t>() <= 1'000'000'000) {
      return static_cast<int>(v.get<std::int64_t>());
    }
  } else {
    if (v.is_number()) return v.get<T>();
  }
  return std::nullopt;
}

void timeline(const Json& options, std::string_view text) {
  try {
    const scene::Scene scene = scene::parse_scene(text, "fuzz.json");
    animate::Overrides overrides;
    overrides.fps = option<double>(options, "fps");
    overrides.duration = option<double>(options, "duration");
    overrides.frames = option<int>(options, "frames");
    const animate::Timeline t = animate::make_timeline(scene, overrides);
    PITA_FUZZ_CHECK(t.frames >= 2 && t.frames <= scene::kMaxAnimationFrames);
    PITA_FUZZ_CHECK(std::isfinite(t.fps) && t.fps > 0);
    double previous = -INFINITY;
    for (const int k : {0, 1, t.frames / 2, t.frames - 1}) {
      const double at = t.time(k);
      PITA_FUZZ_CHECK(std::isfinite(at) && at >= previous);
      previous = at;
    }
    for (const double trail : t.trail_times(t.time(t.frames - 1))) PITA_FUZZ_CHECK(std::isfinite(trail));
    animate::Request request;
    request.out = option<std::string>(options, "out").value_or("frames");
    request.kind = animate::output_kind(request.out.string());
    const std::string format = option<std::string>(options, "format").value_or("png");
    request.frame_format = format == "svg" ? render::Format::svg : render::Format::png;
    const double scale = option<double>(options, "scale").value_or(1.0);
    const double budget = option<double>(options, "budget").value_or(1.0);
    if (scale >= render::kMinScale && scale <= render::kMaxScale) request.scale = scale;  // as the CLI checks
    if (budget > 0 && budget <= 1000) request.budget = budget;
    animate::check_total_work(scene, t, request);
  } catch (const scene::SceneError&) {
  } catch (const animate::AnimationError&) {
  } catch (const render::RenderError&) {  // the figure's estimate, as `render` refuses it
  }
}

void frame_directory(std::string_view text) {
  {
    std::ofstream out(frames_dir() / "frames.json", std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    PITA_FUZZ_CHECK(out.good());
  }
  const bool ours = animate::detail::is_frame_directory(frames_dir());
  const Json index = Json::parse(text, nullptr, false);
  PITA_FUZZ_CHECK(ours == (!index.is_discarded() && index.is_object() && index.contains("frame_list")));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = fuzz::text_of(data, size);
  const std::size_t line = text.find('\n');
  const Json options = Json::parse(text.substr(0, line), nullptr, false);
  const std::string_view rest = line == std::string_view::npos ? std::string_view() : text.substr(line + 1);
  timeline(options, rest);
  frame_directory(rest);
  return 0;
}
