#include "scene/animation_reader.hpp"

#include <array>
#include <cmath>

#include <fmt/format.h>

#include "scene/layer_family.hpp"
#include "scene/limits.hpp"

namespace pita::scene::detail {

namespace {

constexpr std::array<std::string_view, 7> kAnimationFields = {"duration", "fps",   "frames", "loop",
                                                              "what",     "trail", "overlay"};
constexpr std::array<std::string_view, 2> kWhatNames = {"motion", "pattern"};
constexpr std::array<Animation::What, 2> kWhats = {Animation::What::motion, Animation::What::pattern};

}  // namespace

Animation default_animation(bool moving) {
  Animation animation;
  animation.what = moving ? Animation::What::pattern : Animation::What::motion;
  return animation;
}

template <class LayerType>
Animation read_animation(const JsonReader& reader, const Json& value, const std::string& pointer, bool moving) {
  constexpr bool poses = LayerFamily<LayerType>::moves_poses;
  reader.object(value, pointer, "the animation");
  reader.check_fields(value, pointer, kAnimationFields);
  Animation animation = default_animation(moving);
  if (const Json* duration = JsonReader::member(value, "duration")) {
    animation.duration =
        reader.number(*duration, pointer + "/duration", Interval{0.0, kMaxAnimationDuration, true, false});
  }
  if (const Json* fps = JsonReader::member(value, "fps")) {
    animation.fps = reader.number(*fps, pointer + "/fps", Interval{0.0, kMaxFps, true, false});
  }
  if (const Json* frames = JsonReader::member(value, "frames")) {
    animation.frames = reader.integer(*frames, pointer + "/frames", kMinAnimationFrames, kMaxAnimationFrames);
  } else {
    const double count = std::round(animation.duration * animation.fps);
    if (count < kMinAnimationFrames || count > kMaxAnimationFrames) {
      reader.fail(JsonReader::member(value, "duration") ? pointer + "/duration" : pointer + "/fps",
                  fmt::format("duration x fps = {:g} x {:g} gives {:g} frames; an animation has {} to {} frames",
                              animation.duration, animation.fps, count, kMinAnimationFrames, kMaxAnimationFrames));
    }
  }
  if (animation.frames && *animation.frames / animation.fps > kMaxAnimationDuration) {
    reader.fail(pointer + "/fps", fmt::format("{} frames at {:g} frames per second play {:g} s; an animation plays at "
                                              "most {:g} s",
                                              *animation.frames, animation.fps, *animation.frames / animation.fps,
                                              kMaxAnimationDuration));
  }
  if (const Json* loop = JsonReader::member(value, "loop")) animation.loop = reader.boolean(*loop, pointer + "/loop");
  if (const Json* what = JsonReader::member(value, "what")) {
    animation.what = reader.choice(*what, pointer + "/what", kWhatNames, kWhats);
    if (animation.what == Animation::What::pattern && poses) {
      reader.fail(pointer + "/what",
                  "\"pattern\" animates a pattern whose keyframes move, and a pose scene has no "
                  "keyframes: animate the \"motion\"");
    }
    if (animation.what == Animation::What::pattern && !moving) {
      reader.fail(pointer + "/what",
                  "\"pattern\" animates a pattern whose keyframes move, and no keyframe moves: give keyframes "
                  "{\"t\": .., \"from\": ARROW, \"to\": ARROW}, or animate the \"motion\"");
    }
  }
  if (const Json* trail = JsonReader::member(value, "trail")) {
    animation.trail = reader.integer(*trail, pointer + "/trail", 0, kMaxTrail);
  }
  if (const Json* overlay = JsonReader::member(value, "overlay")) {
    const std::string at = pointer + "/overlay";
    if (!overlay->is_array() || overlay->empty() || overlay->size() > static_cast<std::size_t>(kMaxOverlay)) {
      reader.fail(at, fmt::format("must be an array of 1 to {} values of tau in [0, 1] (got {})", kMaxOverlay,
                                  value_text(*overlay)));
    }
    if (poses) reader.fail(at, "\"overlay\" shows moving keyframes at several tau, and a pose scene has no keyframes");
    if (!moving) reader.fail(at, "\"overlay\" shows moving keyframes at several tau, and no keyframe moves");
    animation.overlay.clear();
    for (std::size_t i = 0; i < overlay->size(); ++i) {
      animation.overlay.push_back(reader.number((*overlay)[i], element_pointer(at, i), Interval{0.0, 1.0}));
    }
  }
  return animation;
}

template Animation read_animation<Layer>(const JsonReader&, const Json&, const std::string&, bool);
template Animation read_animation<PoseLayer>(const JsonReader&, const Json&, const std::string&, bool);

}  // namespace pita::scene::detail
