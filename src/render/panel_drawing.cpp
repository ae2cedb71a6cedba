#include "render/panel_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "core/discrepancy.hpp"
#include "core/steady_morph.hpp"
#include "render/banner.hpp"
#include "render/spiral.hpp"
#include "render/strip.hpp"
#include "scene/sampling.hpp"

namespace pita::render {

namespace {

std::string located(const std::string& file, const std::string& pointer,
                    const std::string& reason) {
  return pointer.empty() ? file + ": " + reason : file + ": " + pointer + ": " + reason;
}

// Names of the keyframes in legends, as the paper writes them.
constexpr const char* kKeyframeNames[] = {"A", "B", "C"};

class PanelBuilder {
 public:
  PanelBuilder(const scene::Scene& scene, const scene::Panel& panel)
      : scene_(scene), panel_(panel) {
    try {
      motion_ = make_motion(panel.method, panel.keyframes, panel.options);
    } catch (const std::exception& error) {
      fail(panel.pointer.empty() ? "/keyframes" : panel.pointer,
           fmt::format("{}: {}", panel.method_name, error.what()));
    }
  }

  Drawing build() {
    const bool own = panel_.layers.has_value();
    const std::vector<scene::Layer>& layers = own ? *panel_.layers : scene_.layers;
    for (std::size_t i = 0; i < layers.size(); ++i) {
      layer_ = (own ? panel_.pointer : std::string()) + "/layers/" + std::to_string(i);
      std::visit([this](const auto& layer) { add(layer); }, layers[i]);
    }
    return std::move(drawing_);
  }

 private:
  [[noreturn]] void fail(const std::string& pointer, const std::string& reason) const {
    // A scene-wide layer drawn in a panel: say which panel too.
    const bool elsewhere = !panel_.pointer.empty() && !pointer.starts_with(panel_.pointer);
    throw RenderError(scene_.path, pointer,
                      elsewhere ? reason + " (in the panel at " + panel_.pointer + ")" : reason);
  }

  Arrow frame_at(double t) const {
    Arrow frame;
    try {
      frame = motion_->at(t);
    } catch (const std::exception& error) {
      fail(layer_, fmt::format("no frame at t = {}: {}", t, error.what()));
    }
    if (!is_finite(frame)) {
      fail(layer_, fmt::format("{} gives a non-finite frame at t = {} (the motion overflows there)",
                               panel_.method_name, t));
    }
    return frame;
  }

  std::vector<Arrow> frames(const std::vector<double>& times) const {
    std::vector<Arrow> result;
    result.reserve(times.size());
    for (double t : times) result.push_back(frame_at(t));
    return result;
  }

  void push(int index, Shape shape) { drawing_.items.push_back({layer_, index, std::move(shape)}); }

  void add(const scene::PatternLayer& layer) {
    const std::vector<Arrow> pattern = frames(layer_times(panel_, layer.samples, layer.range));
    for (std::size_t i = 0; i < pattern.size(); ++i) {
      const Arrow& frame = pattern[i];
      const Segment s = layer.extended ? extended_form(frame) : Segment{frame.p, frame.q()};
      push(static_cast<int>(i), Polyline{{s.from, s.to}, false, layer.line});
    }
  }

  void add(const scene::KeyframesLayer& layer) {
    for (std::size_t i = 0; i < panel_.keyframes.size(); ++i) {
      const Arrow& key = panel_.keyframes[i].arrow;
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

  void add(const scene::TrajectoryLayer& layer) {
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

  void add(const scene::StrokeLayer& layer) {
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

  void add(const scene::BannerLayer& layer) {
    const std::vector<Arrow> pattern = frames(layer_times(panel_, layer.samples, layer.range));
    const QuadStrip strip(pattern);
    FilledPath glyphs{map_through_strip(text_outline(layer.text, layer.font), strip, layer.padding),
                      layer.fill, layer.opacity, layer.outline};
    push(-1, std::move(glyphs));
  }

  // The prediction of frame i (Sec. 6.1), or nullopt where it does not exist.
  std::optional<Arrow> prediction(const scene::DiscrepancyLayer& layer,
                                  const std::vector<double>& times,
                                  const std::vector<Arrow>& pattern, std::size_t i) const {
    switch (layer.predictor) {
      case scene::Predictor::previous:
        if (i < 1) return std::nullopt;
        return pattern[i - 1];
      case scene::Predictor::average:
        if (i < 1 || i + 1 >= pattern.size()) return std::nullopt;
        return steady_average(pattern[i - 1], pattern[i + 1]);
      case scene::Predictor::pita: {
        // The method through the frames just before (three, or two for SMA).
        const Method method = layer.method.value_or(panel_.method);
        const auto count = static_cast<std::size_t>(info(method).keyframe_count);
        if (i < count) return std::nullopt;
        std::vector<Keyframe> observed;
        for (std::size_t k = i - count; k < i; ++k) observed.push_back({times[k], pattern[k]});
        try {
          return make_motion(method, observed, panel_.options)->at(times[i]);
        } catch (const std::exception& error) {
          fail(layer_, fmt::format("cannot predict the frame at t = {}: {}", times[i], error.what()));
        }
      }
    }
    return std::nullopt;
  }

  void add(const scene::DiscrepancyLayer& layer) {
    const std::vector<double> times = layer_times(panel_, layer.samples, std::nullopt);
    const std::vector<Arrow> pattern = frames(times);
    for (std::size_t i = 0; i < pattern.size(); ++i) {
      const std::optional<Arrow> predicted = prediction(layer, times, pattern, i);
      if (!predicted) continue;
      const double radius = layer.scale * discrepancy(pattern[i], *predicted);
      if (!std::isfinite(radius)) {
        fail(layer_, fmt::format("the discrepancy at t = {} is not finite", times[i]));
      }
      push(static_cast<int>(i), Circle{pattern[i].p, radius, layer.line, layer.fill});
    }
  }

  void add(const scene::LabelLayer& layer) {
    push(-1, Label{layer.text, layer.at, layer.size, layer.color});
  }

  void add(const scene::LegendLayer& layer) {
    Legend legend{layer.corner, layer.size, {}};
    scene::KeyframesLayer colors;  // the colours of the first keyframes layer, else the defaults
    for (const scene::Layer& other : panel_.layers ? *panel_.layers : scene_.layers) {
      if (const auto* keys = std::get_if<scene::KeyframesLayer>(&other)) {
        colors = *keys;
        break;
      }
    }
    for (std::size_t i = 0; i < panel_.keyframes.size(); ++i) {
      legend.entries.push_back({colors.colors[i % colors.colors.size()],
                                fmt::format("{}  t = {}", kKeyframeNames[i % 3],
                                            panel_.keyframes[i].t)});
    }
    const MethodInfo& about = info(panel_.method);
    legend.entries.push_back({Color{0.2, 0.2, 0.2, 1.0},
                              about.id == about.mnemonic
                                  ? std::string(about.id)
                                  : fmt::format("{} {}", about.id, about.mnemonic)});
    drawing_.legends.push_back(std::move(legend));
  }

  const scene::Scene& scene_;
  const scene::Panel& panel_;
  std::unique_ptr<Motion> motion_;
  std::string layer_;
  Drawing drawing_;
};

}  // namespace

RenderError::RenderError(const std::string& file, const std::string& pointer,
                         const std::string& reason)
    : std::runtime_error(located(file, pointer, reason)) {}

std::vector<double> layer_times(const scene::Panel& panel, const std::optional<int>& samples,
                                const std::optional<scene::TimeRange>& range) {
  const double from = range ? range->from : panel.keyframes.front().t;
  const double to = range ? range->to : panel.keyframes.back().t;
  return scene::uniform_times(from, to, samples.value_or(panel.samples));
}

Drawing panel_drawing(const scene::Scene& scene, const scene::Panel& panel) {
  return PanelBuilder(scene, panel).build();
}

}  // namespace pita::render
