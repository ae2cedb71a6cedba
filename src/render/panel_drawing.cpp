#include "render/panel_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/overloaded.hpp"
#include "render/panel_builder.hpp"
#include "scene/option_use.hpp"

namespace pita::render {

namespace detail {

Drawing PanelBuilder::build() {
  const scene::LayersOf<scene::Layer> drawn = scene::layers_of<scene::Layer>(scene_, panel_);
  const std::vector<scene::Layer>& layers = drawn.layers;
  for (std::size_t i = 0; i < layers.size(); ++i) {
    layer_ = drawn.pointer(i);
    // The reader has checked that the layer draws the panel's kind of keys
    // (scene/layer_kinds.hpp, the "draws" column); a layer drawn on the
    // other kind fails as its motion does (NoMotion), with the layer's pointer.
    draw_layer(cache_, index_, i, drawing_, [&] {
      read_frame_ = false;
      std::visit([this](const auto& layer) { add(layer); }, layers[i]);
      return read_frame_;
    });
  }
  return std::move(drawing_);
}

// The panel's method, and its keyframes or points (the other empty).
const scene::TrackMethod& PanelBuilder::track_of(const scene::Scene& scene, const scene::Panel& panel) {
  if (const scene::TrackMethod* track = scene::track_method(panel.keys)) return *track;
  throw RenderError(scene.path, panel.pointer, "arrow layers draw keyframes or points; this panel has poses");
}

const motion::SceneMotion& PanelBuilder::built(const motion::Stage& stage, std::size_t index) {
  try {
    return stage.motion(index);
  } catch (const motion::NoMotion& error) {
    throw RenderError(error.file(), error.pointer(), error.reason());
  }
}

std::vector<Arrow> PanelBuilder::frames(const motion::SceneMotion& motion, const std::vector<double>& times) const {
  std::vector<Arrow> result;
  result.reserve(times.size());
  try {
    for (double t : times) result.push_back(motion.arrow_at(t));
  } catch (const motion::NoMotion& error) {
    fail(layer_, error.reason());
  }
  return result;
}

// The times of a layer that draws a sequence of frames: an animation
// frame's trail and time, else the layer's samples over its range.
std::vector<double> PanelBuilder::sequence_times(const std::optional<int>& samples,
                                                 const std::optional<scene::TimeRange>& range) const {
  if (selection() == nullptr) return layer_times(panel_, samples, range);
  std::vector<double> times = selection()->trail;
  times.push_back(selection()->t);
  return times;
}

// A pattern layer with its own "method" or "options" draws the motion of
// a copy of the panel that has them (N57); its errors are the layer's.
motion::SceneMotion PanelBuilder::layer_motion(std::optional<Method> method,
                                               const scene::MethodOptionsPatch& patch) const {
  const MethodOptions options = patch.over(track_.options);
  const scene::Panel own = motion::layer_panel(panel_, method, options);
  // An option the layer's method does not read would change nothing: refused.
  const Method drawn = scene::track_method(own.keys)->method;
  for (const MethodOptionKey& key : kMethodOptionKeys) {
    if ((patch.given & key.option) == 0U || scene::keys_read_option(own.keys, key.option)) continue;
    fail(layer_ + "/options/" + std::string(key.name),
         scene::unread_option_reason(std::span(&drawn, 1), key.name, key.option));
  }
  try {
    return motion::with_layer_method(scene_, panel_, method, options);
  } catch (const motion::NoMotion& error) {
    fail(layer_ + (method ? "/method" : "/options"), error.reason());
  }
}

// The derivatives of D at `times`; a stencil node where the motion does not
// exist is the layer's error.
std::vector<analysis::FrameDerivatives> PanelBuilder::derivatives(const std::vector<double>& times) const {
  std::vector<analysis::FrameDerivatives> result;
  result.reserve(times.size());
  try {
    for (double t : times) result.push_back(analysis::frame_derivatives(motion_, t));
  } catch (const motion::NoMotion& error) {
    fail(layer_, error.reason());
  }
  return result;
}

}  // namespace detail

std::vector<double> layer_times(const scene::Panel& panel, const std::optional<int>& samples,
                                const std::optional<scene::TimeRange>& range) {
  // The least and greatest knots.
  const std::vector<double> knots = scene::knots(panel.keys);
  const double first = knots.empty() ? 0.0 : knots.front();
  const double last = knots.empty() ? 0.0 : knots.back();
  const double from = range ? range->from : first;
  const double to = range ? range->to : last;
  return motion::uniform_times(from, to, samples.value_or(panel.samples));
}

double trail_fade(std::size_t i, std::size_t count) { return static_cast<double>(i + 1) / static_cast<double>(count); }

std::vector<double> selected_times(const FrameSelection* selection, std::vector<double> all) {
  if (selection == nullptr) return all;
  std::vector<double> times = selection->trail;
  times.push_back(selection->t);
  return times;
}

std::vector<double> lightness_whites(const std::vector<double>& measures) {
  constexpr double kMostWhite = 0.8;
  std::vector<double> whites(measures.size(), 0.0);
  if (measures.empty()) return whites;
  const auto [smallest, largest] = std::minmax_element(measures.begin(), measures.end());
  if (!(*largest > *smallest)) return whites;
  for (std::size_t i = 0; i < measures.size(); ++i) {
    whites[i] = kMostWhite * (measures[i] - *smallest) / (*largest - *smallest);
  }
  return whites;
}

Color lightened(Color color, double white) {
  return Color{color.r + (1.0 - color.r) * white, color.g + (1.0 - color.g) * white, color.b + (1.0 - color.b) * white,
               color.a};
}

Drawing panel_drawing(const motion::Stage& stage, std::size_t index, const FrameSelection* selection,
                      StaticLayers* cache) {
  return detail::PanelBuilder(stage, index, selection, cache).build();
}

Drawing panel_drawing(const scene::Scene& scene, const scene::Panel& panel, const FrameSelection* selection) {
  return panel_drawing(motion::Stage(scene, panel), 0, selection);
}

}  // namespace pita::render
