#include "render/panel_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/overloaded.hpp"
#include "analysis/arrow_distance.hpp"
#include "analysis/audit.hpp"
#include "analysis/comparison.hpp"
#include "core/methods.hpp"
#include "analysis/measure.hpp"
#include "analysis/frame_derivatives.hpp"
#include "analysis/prediction.hpp"
#include "core/carrier.hpp"
#include "core/discrepancy.hpp"
#include "render/banner.hpp"
#include "render/carried_shapes.hpp"
#include "render/measure_text.hpp"
#include "render/plot.hpp"
#include "render/property_table.hpp"
#include "render/spiral.hpp"
#include "render/strip.hpp"
#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"
#include "motion/stage.hpp"
#include "render/panel_builder.hpp"

namespace pita::render {

namespace detail {

Drawing PanelBuilder::build() {
  const bool own = panel_.layers.has_value();
  const std::vector<scene::Layer>& layers = own ? *panel_.layers : scene_.layers;
  for (std::size_t i = 0; i < layers.size(); ++i) {
    layer_ = (own ? panel_.pointer : std::string()) + "/layers/" + std::to_string(i);
    // The reader has checked that the layer draws the panel's kind of keys
    // (scene/layer_kinds.hpp, the "draws" column); a layer drawn on the
    // other kind fails as its motion does (NoMotion), with the layer's pointer.
    std::visit([this](const auto& layer) { add(layer); }, layers[i]);
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
std::vector<double> PanelBuilder::sequence_times(const std::optional<int>& samples, const std::optional<scene::TimeRange>& range) const {
  if (selection_ == nullptr) return layer_times(panel_, samples, range);
  std::vector<double> times = selection_->trail;
  times.push_back(selection_->t);
  return times;
}

// A pattern layer with its own "method" or "options" draws the motion of
// a copy of the panel that has them (N57); its errors are the layer's.
motion::SceneMotion PanelBuilder::layer_motion(const scene::PatternLayer& layer) const {
  const MethodOptions options = layer.options.over(track_.options);
  const scene::Panel own = motion::layer_panel(panel_, layer.method, options);
  // An option the layer's method does not read would change nothing: refused.
  const Method drawn = scene::track_method(own.keys)->method;
  const bool chained =
      track_.chain.has_value() || keyframes_.size() > static_cast<std::size_t>(info(drawn).keyframe_count);
  for (const MethodOptionKey& key : kMethodOptionKeys) {
    if ((layer.options.given & key.option) == 0U || reads_option(drawn, key.option, chained)) continue;
    std::vector<std::string> readers;
    for (const MethodInfo& method : all_methods()) {
      if (reads_option(method.method, key.option, false)) readers.emplace_back(method.id);
    }
    fail(layer_ + "/options/" + std::string(key.name),
         fmt::format("{} does not read \"{}\", so it would change nothing here; {} read{} it", method_name(drawn),
                     key.name, fmt::join(readers, ", "), readers.size() == 1 ? "s" : ""));
  }
  try {
    return motion::with_layer_method(scene_, panel_, layer.method, options);
  } catch (const motion::NoMotion& error) {
    fail(layer_ + (layer.method ? "/method" : "/options"), error.reason());
  }
}

void PanelBuilder::add(const scene::PatternLayer& layer) {
  const bool own = layer.method.has_value() || !layer.options.empty();
  // "times": exactly those (an animation frame still draws its own time).
  const std::vector<double> times =
      layer.times.empty() || selection_ != nullptr ? sequence_times(layer.samples, layer.range) : layer.times;
  const std::vector<Arrow> pattern = own ? frames(layer_motion(layer), times) : frames(times);
  // A dot's radius: a fixed share of the first keyframe's magnitude.
  const double dot = 0.015 * std::max(keyframes_.front().arrow.m, 1e-300);
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    const Arrow& frame = pattern[i];
    const Segment s = layer.extended ? extended_form(frame) : Segment{frame.p, frame.q()};
    LineStyle line = layer.line;
    line.opacity *= fade(i, pattern.size());
    if (layer.dots) {
      push(static_cast<int>(i), Circle{frame.p, dot, line, line.color});
    } else if (layer.heads) {
      push(static_cast<int>(i), ArrowShape{s.from, s.to, line});
    } else {
      push(static_cast<int>(i), Polyline{{s.from, s.to}, false, line});
    }
    drawing_.items.back().moving = selection_ != nullptr;
    if (!layer.coils) continue;
    // The frame's winding, drawn as the keyframes layer draws A's, B's, C's.
    std::vector<Point> coil = winding_spiral(frame.p, frame.m, frame.w);
    if (coil.empty()) continue;
    push(static_cast<int>(i), Polyline{std::move(coil), false, line});
    drawing_.items.back().moving = selection_ != nullptr;
  }
}

// "shapes" (Sec. 7.1): the scene's shapes at each frame, carried by the
// similarity that takes the handle onto D(t) (core/carrier.hpp).
void PanelBuilder::add(const scene::ShapesLayer& layer) {
  const std::vector<Arrow> pattern = frames(sequence_times(layer.samples, layer.range));
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    for (Shape& shape : carried_shapes(panel_.shapes, carrier(handle(), pattern[i]), layer,
                                       scene_.canvas.y_up, fade(i, pattern.size()))) {
      push(static_cast<int>(i), std::move(shape));
      drawing_.items.back().moving = selection_ != nullptr;
    }
  }
}

void PanelBuilder::add(const scene::KeyframesLayer& layer) {
  for (std::size_t i = 0; i < keyframes_.size(); ++i) {
    const Arrow& key = keyframes_[i].arrow;
    const Color color = layer.colors[i % layer.colors.size()];
    const LineStyle line{color, layer.width, layer.opacity, {}};
    if (layer.winding) {
      const Point center =
          layer.spiral_center == scene::SpiralCenter::start ? key.p : 0.5 * (key.p + key.q());
      std::vector<Point> coil = winding_spiral(center, key.m, key.w);
      if (!coil.empty()) {
        push(static_cast<int>(i),
             Polyline{std::move(coil), false, LineStyle{color, 0.6 * layer.width, layer.opacity, {}}});
      }
    }
    const Segment s = layer.extended ? extended_form(key) : Segment{key.p, key.q()};
    push(static_cast<int>(i), ArrowShape{s.from, s.to, line});
  }
}

void PanelBuilder::add(const scene::TrajectoryLayer& layer) {
  const std::vector<Arrow> path = frames(layer_times(panel_, layer.samples, layer.range));
  std::vector<Point> points;
  points.reserve(path.size());
  for (const Arrow& frame : path) {
    switch (layer.point) {
      case scene::TrackedPoint::start: points.push_back(frame.p); break;
      case scene::TrackedPoint::end: points.push_back(frame.q()); break;
      case scene::TrackedPoint::middle: points.push_back(0.5 * (frame.p + frame.q())); break;
    }
  }
  push(-1, Polyline{std::move(points), false, layer.line});
}

void PanelBuilder::add(const scene::StrokeLayer& layer) {
  const std::vector<Arrow> pattern = frames(layer_times(panel_, layer.samples, layer.range));
  const QuadStrip strip(pattern);
  // One path of quads, each oriented counter-clockwise, filled with the
  // nonzero rule: overlapping quads stay filled and no seams show between
  // neighbours (as separately filled quads would show with antialiasing).
  FilledPath quads{{}, layer.fill, layer.opacity, std::nullopt};
  for (int i = 0; i < strip.quad_count(); ++i) {
    const auto corners = strip.quad(i);
    std::vector<Point> contour(corners.begin(), corners.end());
    double twice_area = 0.0;
    for (std::size_t k = 0; k < 4; ++k) {
      const Point a = contour[k], b = contour[(k + 1) % 4];
      twice_area += a.real() * b.imag() - b.real() * a.imag();
    }
    if (twice_area < 0.0) std::reverse(contour.begin(), contour.end());
    quads.contours.push_back(std::move(contour));
  }
  push(-1, std::move(quads));
  if (layer.outline) {
    std::vector<Point> boundary;
    for (const Arrow& frame : pattern) boundary.push_back(frame.p);
    for (auto it = pattern.rbegin(); it != pattern.rend(); ++it) boundary.push_back(it->q());
    push(-1, Polyline{std::move(boundary), true, *layer.outline});
  }
}

void PanelBuilder::add(const scene::BannerLayer& layer) {
  const std::vector<Arrow> pattern = frames(layer_times(panel_, layer.samples, layer.range));
  const QuadStrip strip(pattern);
  FilledPath glyphs{map_through_strip(text_outline(layer.text, layer.font), strip, layer.padding),
                    layer.fill, layer.opacity, layer.outline};
  push(-1, std::move(glyphs));
}

void PanelBuilder::add(const scene::HandleLayer& layer) {
  if (layer.shapes) {
    scene::ShapesLayer style;
    for (Shape& shape : carried_shapes(panel_.shapes, Affine2::identity(), style, scene_.canvas.y_up)) {
      push(-1, std::move(shape));
    }
  }
  push(-1, ArrowShape{handle().p, handle().q(), LineStyle{layer.color, layer.width, 1.0, {}}});
}

void PanelBuilder::add(const scene::LabelLayer& layer) {
  push(-1, Label{layer.text, layer.at, layer.size, layer.color});
}

void PanelBuilder::add(const scene::PointTrajectoryLayer& layer) {
  if (points_.empty()) {
    fail(layer_, "a point-trajectory draws a curve through timed \"points\"; this panel has keyframes");
  }
  const double from = layer.range ? layer.range->from : points_.front().t;
  const double to = layer.range ? layer.range->to : points_.back().t;
  std::vector<Point> path;
  path.reserve(static_cast<std::size_t>(layer.samples));
  if (layer.curve == PointCurve::pita) {
    try {
      for (const double t : motion::uniform_times(from, to, layer.samples)) path.push_back(motion_.point_at(t));
    } catch (const motion::NoMotion& error) {
      fail(layer_, error.reason());
    }
  } else {
    std::optional<PointCurveMotion> curve;
    try {
      curve.emplace(motion::point_curve(scene_, panel_, layer.curve));
    } catch (const motion::NoMotion& error) {
      fail(layer_ + "/curve", error.reason());
    }
    for (const double t : motion::uniform_times(from, to, layer.samples)) {
      const Point x = curve->at(t);
      if (!std::isfinite(x.real()) || !std::isfinite(x.imag())) {
        fail(layer_ + "/curve", fmt::format("the {} curve has no finite point at t = {} (its numbers overflow "
                                            "there: knots very uneven, or t far outside them)",
                                            info(layer.curve).name, t));
      }
      path.push_back(x);
    }
  }
  push(-1, Polyline{std::move(path), false, layer.line});
  if (!layer.dots) return;
  // Dots at the timed points, sized by the points' spread.
  Point low = points_.front().p, high = low;
  for (const TimedPoint& point : points_) {
    low = {std::min(low.real(), point.p.real()), std::min(low.imag(), point.p.imag())};
    high = {std::max(high.real(), point.p.real()), std::max(high.imag(), point.p.imag())};
  }
  const double radius = 0.012 * std::max(std::abs(high - low), 1e-300);
  for (std::size_t i = 0; i < points_.size(); ++i) {
    push(static_cast<int>(i), Circle{points_[i].p, radius, layer.line, layer.line.color});
  }
}

void PanelBuilder::add(const scene::LegendLayer& layer) {
  Legend legend{layer.corner, layer.size, {}};
  scene::KeyframesLayer colors;  // the colours of the first keyframes layer, else the defaults
  for (const scene::Layer& other : panel_.layers ? *panel_.layers : scene_.layers) {
    if (const auto* keys = std::get_if<scene::KeyframesLayer>(&other)) {
      colors = *keys;
      break;
    }
  }
  for (std::size_t i = 0; i < keyframes_.size(); ++i) {
    legend.entries.push_back({colors.colors[i % colors.colors.size()],
                              fmt::format("{}  t = {}", keyframe_name(i), keyframes_[i].t)});
  }
  // A panel of points: one entry per curve drawn, in its colour.
  for (const scene::Layer& other : panel_.layers ? *panel_.layers : scene_.layers) {
    const auto* curve = std::get_if<scene::PointTrajectoryLayer>(&other);
    if (curve == nullptr || curve->curve == PointCurve::pita) continue;
    legend.entries.push_back({curve->line.color, std::string(info(curve->curve).name)});
  }
  // The method in the colour of the first pattern layer (its frames), else
  // dark grey; after it the trajectories drawn, in their colour and dash.
  // Overlaid patterns (a "label", or their own "method" or "options") get
  // an entry each, named by the label, else by their method.
  Color method_color{0.2, 0.2, 0.2, 1.0};
  bool pattern_seen = false;
  std::vector<LegendEntry> paths, overlays;
  for (const scene::Layer& other : panel_.layers ? *panel_.layers : scene_.layers) {
    const auto* pattern = std::get_if<scene::PatternLayer>(&other);
    if (const auto* path = std::get_if<scene::TrajectoryLayer>(&other)) {
      paths.push_back({path->line.color, trajectory_name(path->point), path->line.dash});
    } else if (pattern != nullptr && (!pattern->label.empty() || pattern->method || !pattern->options.empty())) {
      overlays.push_back({pattern->line.color,
                          pattern->label.empty() ? method_name(pattern->method.value_or(track_.method))
                                                 : pattern->label,
                          pattern->line.dash});
    } else if (pattern != nullptr && !pattern_seen) {
      method_color = pattern->line.color;
      pattern_seen = true;
    }
  }
  if (overlays.empty() || pattern_seen) {
    legend.entries.push_back({method_color, method_name(track_.method)});
  }
  legend.entries.insert(legend.entries.end(), overlays.begin(), overlays.end());
  legend.entries.insert(legend.entries.end(), paths.begin(), paths.end());
  drawing_.legends.push_back(std::move(legend));
}

}  // namespace detail


RenderError::RenderError(const std::string& file, const std::string& pointer,
                         const std::string& reason)
    : std::runtime_error(scene::located(file, pointer, reason)) {}

std::vector<double> layer_times(const scene::Panel& panel, const std::optional<int>& samples,
                                const std::optional<scene::TimeRange>& range) {
  // The least and greatest knots (keyframes "as-given" may come in any order).
  double first = 0.0, last = 0.0;
  const auto knots = [&](const auto& items) {
    if (items.empty()) return;
    const auto [low, high] = std::minmax_element(items.begin(), items.end(),
                                                 [](const auto& a, const auto& b) { return a.t < b.t; });
    first = low->t;
    last = high->t;
  };
  std::visit(overloaded{[&](const scene::KeyframeKeys& given) { knots(given.keyframes); },
                        [&](const scene::PointKeys& given) { knots(given.points); },
                        [&](const scene::PlanePoseKeys& given) { knots(given.poses); },
                        [&](const scene::SpacePoseKeys& given) { knots(given.poses); }},
             panel.keys);
  const double from = range ? range->from : first;
  const double to = range ? range->to : last;
  return motion::uniform_times(from, to, samples.value_or(panel.samples));
}

double trail_fade(std::size_t i, std::size_t count) {
  return static_cast<double>(i + 1) / static_cast<double>(count);
}

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
  return Color{color.r + (1.0 - color.r) * white, color.g + (1.0 - color.g) * white,
               color.b + (1.0 - color.b) * white, color.a};
}

Drawing panel_drawing(const motion::Stage& stage, std::size_t index, const FrameSelection* selection) {
  return detail::PanelBuilder(stage, index, selection).build();
}

Drawing panel_drawing(const scene::Scene& scene, const scene::Panel& panel, const FrameSelection* selection) {
  return panel_drawing(motion::Stage(scene, panel), 0, selection);
}

}  // namespace pita::render
