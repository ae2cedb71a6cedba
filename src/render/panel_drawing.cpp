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

namespace pita::render {

namespace {


// Names of the keyframes in legends, as the paper writes them (A, B, C, then
// on through the alphabet for longer tracks).
std::string keyframe_name(std::size_t i) {
  return i < 26 ? std::string(1, static_cast<char>('A' + i)) : fmt::format("K{}", i);
}

// A trajectory's legend text.
std::string trajectory_name(scene::TrackedPoint point) {
  switch (point) {
    case scene::TrackedPoint::start: return "path of p";
    case scene::TrackedPoint::end: return "path of q";
    case scene::TrackedPoint::middle: return "path of the midpoint";
  }
  return "path";
}

// A printed comparison: a value below 1e-12 in magnitude is rounding noise,
// whose digits differ between compilers, so it is printed as "< 1e-12".
std::string rounding_or_value(double value) {
  return std::abs(value) < 1e-12 ? std::string("< 1e-12") : fmt::format("{:.3g}", value);
}

// A method as legends name it: "P6 La-LP", "SMA".
std::string method_name(Method method) {
  const MethodInfo& about = info(method);
  return about.id == about.mnemonic ? std::string(about.id) : fmt::format("{} {}", about.id, about.mnemonic);
}

class PanelBuilder {
 public:
  PanelBuilder(const motion::Stage& stage, std::size_t index, const FrameSelection* selection)
      : stage_(stage),
        index_(index),
        scene_(stage.scene()),
        panel_(stage.panel(index)),
        selection_(selection),
        motion_(built(stage, index)),
        track_(track_of(stage.scene(), panel_)),
        keyframes_(keyframes_of(panel_)),
        points_(points_of(panel_)) {}

  Drawing build() {
    const bool own = panel_.layers.has_value();
    const std::vector<scene::Layer>& layers = own ? *panel_.layers : scene_.layers;
    for (std::size_t i = 0; i < layers.size(); ++i) {
      layer_ = (own ? panel_.pointer : std::string()) + "/layers/" + std::to_string(i);
      const bool for_points = std::holds_alternative<scene::PointTrajectoryLayer>(layers[i]) ||
                              std::holds_alternative<scene::LabelLayer>(layers[i]) ||
                              std::holds_alternative<scene::LegendLayer>(layers[i]) ||
                              std::holds_alternative<scene::MeasuresLayer>(layers[i]);
      if (!points_.empty() && !for_points) {
        fail(layer_, "this layer draws a motion of keyframes, and the panel has timed \"points\": draw them "
                     "with \"point-trajectory\" (labels and legends are fine too)");
      }
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

  // The panel's method, and its keyframes or points (the other empty).
  static const scene::TrackMethod& track_of(const scene::Scene& scene, const scene::Panel& panel) {
    if (const scene::TrackMethod* track = scene::track_method(panel.keys)) return *track;
    throw RenderError(scene.path, panel.pointer, "arrow layers draw keyframes or points; this panel has poses");
  }
  static const std::vector<Keyframe>& keyframes_of(const scene::Panel& panel) {
    static const std::vector<Keyframe> kNone;
    const auto* given = std::get_if<scene::KeyframeKeys>(&panel.keys);
    return given != nullptr ? given->keyframes : kNone;
  }
  static const std::vector<TimedPoint>& points_of(const scene::Panel& panel) {
    static const std::vector<TimedPoint> kNone;
    const auto* given = std::get_if<scene::PointKeys>(&panel.keys);
    return given != nullptr ? given->points : kNone;
  }
  // The arrow that carries the shapes (PITA Sec. 7.1).
  Arrow handle() const { return std::get<scene::KeyframeKeys>(panel_.keys).handle(); }

  static const motion::SceneMotion& built(const motion::Stage& stage, std::size_t index) {
    try {
      return stage.motion(index);
    } catch (const motion::NoMotion& error) {
      throw RenderError(error.file(), error.pointer(), error.reason());
    }
  }

  // The frames at `times` (of the panel's motion, or of a layer's own); a
  // frame that does not exist is the layer's error.
  std::vector<Arrow> frames(const std::vector<double>& times) const { return frames(motion_, times); }
  std::vector<Arrow> frames(const motion::SceneMotion& motion, const std::vector<double>& times) const {
    std::vector<Arrow> result;
    result.reserve(times.size());
    try {
      for (double t : times) result.push_back(motion.arrow_at(t));
    } catch (const motion::NoMotion& error) {
      fail(layer_, error.reason());
    }
    return result;
  }

  void push(int index, Shape shape) { drawing_.items.push_back({layer_, index, std::move(shape)}); }

  // The times of a layer that draws a sequence of frames: an animation
  // frame's trail and time, else the layer's samples over its range.
  std::vector<double> sequence_times(const std::optional<int>& samples, const std::optional<scene::TimeRange>& range) const {
    if (selection_ == nullptr) return layer_times(panel_, samples, range);
    std::vector<double> times = selection_->trail;
    times.push_back(selection_->t);
    return times;
  }
  double fade(std::size_t i, std::size_t count) const {
    return selection_ != nullptr ? trail_fade(i, count) : 1.0;
  }

  // A pattern layer with its own "method" or "options" draws the motion of
  // a copy of the panel that has them (N57); its errors are the layer's.
  motion::SceneMotion layer_motion(const scene::PatternLayer& layer) const {
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

  void add(const scene::PatternLayer& layer) {
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
  void add(const scene::ShapesLayer& layer) {
    const std::vector<Arrow> pattern = frames(sequence_times(layer.samples, layer.range));
    for (std::size_t i = 0; i < pattern.size(); ++i) {
      for (Shape& shape : carried_shapes(panel_.shapes, carrier(handle(), pattern[i]), layer,
                                         scene_.canvas.y_up, fade(i, pattern.size()))) {
        push(static_cast<int>(i), std::move(shape));
        drawing_.items.back().moving = selection_ != nullptr;
      }
    }
  }

  void add(const scene::KeyframesLayer& layer) {
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

  void add(const scene::DiscrepancyLayer& layer) {
    const std::vector<double> times = layer_times(panel_, layer.samples, std::nullopt);
    const std::vector<Arrow> pattern = frames(times);
    const Method method = layer.method.value_or(track_.method);
    for (std::size_t i = 0; i < pattern.size(); ++i) {
      std::optional<double> discrepancy;
      try {
        discrepancy = analysis::frame_discrepancy(layer.predictor, method, track_.options, times, pattern, i);
      } catch (const std::exception& error) {
        fail(layer_, fmt::format("cannot predict the frame at t = {}: {}", times[i], error.what()));
      }
      if (!discrepancy) continue;
      const double radius = layer.scale * *discrepancy;
      if (!std::isfinite(radius)) {
        fail(layer_, fmt::format("the discrepancy at t = {} is not finite", times[i]));
      }
      push(static_cast<int>(i), Circle{pattern[i].p, radius, layer.line, layer.fill});
    }
  }

  void add(const scene::PlotLayer& layer) {
    try {
      for (Item& item : plot_items(layer, motion_, layer_times(panel_, std::nullopt, std::nullopt), layer_)) {
        drawing_.items.push_back(std::move(item));
      }
    } catch (const motion::NoMotion& error) {
      fail(layer_, error.reason());
    } catch (const std::invalid_argument& error) {
      fail(layer_, fmt::format("cannot plot the distance of {}: {}", scene::method_id(panel_.keys), error.what()));
    }
  }

  void add(const scene::PropertyTableLayer& layer) {
    analysis::AuditOptions options;
    options.methods = layer.methods;
    options.configs = layer.configs;
    options.seed = static_cast<std::uint64_t>(layer.seed);
    options.jobs = 1;  // figures are drawn in parallel already
    const PropertyTable table = property_table(analysis::run_audit(options));
    for (const Item& item : table.drawing.items) {
      // The table is laid out with y down; on mathematical axes it is mirrored
      // back so that it reads top to bottom.
      const auto place = [&](Point x) {
        return layer.at + (scene_.canvas.y_up ? Point{x.real(), -x.imag()} : x);
      };
      Shape shape = item.shape;
      std::visit([&](auto& s) {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, Polyline>) {
          for (Point& x : s.points) x = place(x);
        } else if constexpr (std::is_same_v<S, FilledPath>) {
          for (auto& contour : s.contours) for (Point& x : contour) x = place(x);
        } else if constexpr (std::is_same_v<S, Label>) {
          s.at = place(s.at);
        }
      }, shape);
      push(-1, std::move(shape));
    }
  }

  void add(const scene::HandleLayer& layer) {
    if (layer.shapes) {
      scene::ShapesLayer style;
      for (Shape& shape : carried_shapes(panel_.shapes, Affine2::identity(), style, scene_.canvas.y_up)) {
        push(-1, std::move(shape));
      }
    }
    push(-1, ArrowShape{handle().p, handle().q(), LineStyle{layer.color, layer.width, 1.0, {}}});
  }

  // The derivatives of D at `times`; a stencil node where the motion does not
  // exist is the layer's error.
  std::vector<analysis::FrameDerivatives> derivatives(const std::vector<double>& times) const {
    std::vector<analysis::FrameDerivatives> result;
    result.reserve(times.size());
    try {
      for (double t : times) result.push_back(analysis::frame_derivatives(motion_, t));
    } catch (const motion::NoMotion& error) {
      fail(layer_, error.reason());
    }
    return result;
  }

  // "vectors" (Figs. 9, 14, 15): scale x dx/du or d2x/du2, u = (t - a)/(c - a).
  void add(const scene::VectorsLayer& layer) {
    const std::vector<double> times = layer_times(panel_, layer.samples, layer.range);
    const double span = motion_.last() - motion_.first();
    const bool velocity = layer.of == scene::VectorKind::velocity;
    const double factor = layer.scale * (velocity ? span : span * span);
    int index = 0;
    for (const analysis::FrameDerivatives& d : derivatives(times)) {
      const auto vector = [&](Point at, Vector rate, const Color& color) {
        const Vector drawn = factor * rate;
        if (!std::isfinite(drawn.real()) || !std::isfinite(drawn.imag())) {
          fail(layer_, fmt::format("the {} at t = {} is not finite", velocity ? "velocity" : "acceleration", d.t));
        }
        const Point from = layer.tail_at_point ? at : at - drawn;
        const Point to = layer.tail_at_point ? at + drawn : at;
        LineStyle line = layer.line;
        line.color = color;
        if (layer.heads) {
          push(index, ArrowShape{from, to, line});
        } else {
          push(index, Polyline{{from, to}, false, line});
        }
      };
      if (layer.at_p) vector(d.p, velocity ? d.dp : d.ddp, layer.color_p);
      if (layer.at_q) vector(d.q, velocity ? d.dq : d.ddq, layer.color_q);
      ++index;
    }
  }

  // "fixed-points" (Fig. 9): segments from D(t).p (q, mid) to P7's global
  // fixed point or to the instantaneous center at t (core/instant_center.hpp).
  void add(const scene::FixedPointsLayer& layer) {
    const std::vector<double> times = layer_times(panel_, layer.samples, layer.range);
    std::optional<Point> global;
    if (layer.center == scene::CenterKind::global) {
      if (track_.method != Method::P7 || motion_.chain()) {
        fail(layer_ + "/center", fmt::format("\"global\" is P7's fixed point (Eq. 35-36); the panel's method is {}: "
                                             "use \"acceleration\" or \"velocity\" (instantaneous centers)",
                                             motion::method_label(scene_, panel_)));
      }
      global = motion_.arrows().global_fixed_point();
      // f at infinity (P7 degenerate to P1's parabola): nothing to draw.
      if (!global) return;
    }
    const double dot = 0.025 * std::max(keyframes_.front().arrow.m, 1e-300);
    int index = 0;
    for (const analysis::FrameDerivatives& d : derivatives(times)) {
      std::optional<Point> center = global;
      if (layer.center == scene::CenterKind::acceleration) center = analysis::acceleration_center(d);
      if (layer.center == scene::CenterKind::velocity) center = analysis::velocity_center(d);
      if (center) {
        const Point from = layer.point == scene::TrackedPoint::start ? d.p
                           : layer.point == scene::TrackedPoint::end ? d.q
                                                                     : 0.5 * (d.p + d.q);
        push(index, Polyline{{from, *center}, false, layer.line});
        if (layer.dots && (!global || index == 0)) {
          push(index, Circle{*center, dot, layer.line, layer.line.color});
        }
      }
      ++index;
    }
  }

  void add(const scene::LabelLayer& layer) {
    push(-1, Label{layer.text, layer.at, layer.size, layer.color});
  }

  // "measures": the numbers of `pita measure` for this panel's motion.
  void add(const scene::MeasuresLayer& layer) {
    if (selection_ != nullptr) return;  // a figure's numbers, not an animation frame's
    // "angle:M@t" and "handle-shift" compare with another motion
    // (analysis/comparison.hpp); the others are `pita measure`'s.
    std::vector<std::string> lines(layer.show.size());
    std::vector<scene::MeasureName> others;
    for (std::size_t i = 0; i < layer.show.size(); ++i) {
      const scene::MeasureName& name = layer.show[i];
      const std::string at = layer_ + "/show/" + std::to_string(i);
      try {
        if (name.kind == scene::MeasureKind::handle_shift) {
          if (panel_.shapes.empty()) {
            fail(at, "\"handle-shift\" measures how far the panel's shapes land, and the panel has no shapes: "
                     "give the scene or the panel \"shapes\" (README \"Shapes\")");
          }
          lines[i] = fmt::format("handle shift: {}", rounding_or_value(analysis::handle_shift(stage_, index_)));
        } else if (name.kind == scene::MeasureKind::angle) {
          const double angle = analysis::vector_angle(stage_, index_, name.method, name.t);
          if (!std::isfinite(angle)) {
            fail(at, fmt::format("the angle at t = {} is undefined: the frame vector of {} or of {} vanishes there",
                                 name.t, scene::method_id(panel_.keys), entry_of(name.method).id));
          }
          lines[i] = fmt::format("angle {}, {} at t = {}: {} rad", scene::method_id(panel_.keys), entry_of(name.method).id,
                                 name.text.substr(name.text.find('@') + 1), rounding_or_value(angle));
        } else {
          others.push_back(name);
        }
      } catch (const motion::NoMotion& error) {
        fail(layer_, error.reason());
      }
    }
    if (!others.empty()) {
      const analysis::MotionMeasures measures = analysis::measure_panel(stage_, index_);
      if (measures.no_motion) fail(layer_, *measures.no_motion);
      const std::vector<std::string> measured = measure_lines(measures, others);
      for (std::size_t i = 0, k = 0; i < lines.size(); ++i) {
        if (lines[i].empty()) lines[i] = measured[k++];
      }
    }
    add_measure_text(layer, lines, drawing_, layer_);
  }

  // Printed lines of a layer, at its world point (one label) or in its corner
  // (a text-only legend, each line in its colour).
  void add_lines(const std::vector<LegendEntry>& lines, const std::optional<Point>& at,
                 scene::LegendLayer::Corner corner, double size, const Color& color) {
    if (at) {
      std::string text;
      for (const LegendEntry& line : lines) text += (text.empty() ? "" : "\n") + line.text;
      push(-1, Label{text, *at, size, color});
      return;
    }
    drawing_.legends.push_back(Legend{corner, size, lines, false});
  }

  // "guesses" (Sec. 6.1, 6.3; Figs. 16, 18): each drawn arrow G at its time t,
  // the frame D(t) under it, and per measure shown a line
  //   "E(L, D(2)) = 0.0123"  (Eq. 47 as corrected, docs/paper-notes.md N5)
  //   "d(L, D(2)) = 0.42"    (max(|dp|, |dq|), docs/paper-notes.md N53).
  void add(const scene::GuessesLayer& layer) {
    std::vector<LegendEntry> lines;
    for (std::size_t i = 0; i < layer.guesses.size(); ++i) {
      const scene::Guess& guess = layer.guesses[i];
      const Arrow frame = frames({guess.t}).front();
      const int index = static_cast<int>(i);
      push(index, ArrowShape{frame.p, frame.q(), LineStyle{layer.frame_color, layer.width, 1.0, {}}});
      push(index, ArrowShape{guess.arrow.p, guess.arrow.q(), LineStyle{guess.color, layer.width, 1.0, {}}});
      for (const scene::GuessMeasure measure : layer.show) {
        const bool discrepancy = measure == scene::GuessMeasure::discrepancy;
        const double value = discrepancy ? pita::discrepancy(guess.arrow, frame)
                                         : analysis::endpoint_distance(guess.arrow, frame);
        if (!std::isfinite(value)) fail(layer_, fmt::format("the {} of {} is not finite", discrepancy ? "discrepancy" : "distance", guess.name));
        lines.push_back({guess.color, fmt::format("{}({}, D({:g})) = {:.3g}", discrepancy ? "E" : "d", guess.name,
                                                  guess.t, value)});
      }
    }
    if (selection_ == nullptr) add_lines(lines, layer.at, layer.corner, layer.size, layer.color);
  }

  // "compare" (appendix B, Fig. B.30): the pattern of another method through
  // the panel's keyframes over the panel's own, and the printed line
  // "max |P3 - P10| = 2.1e-15", the largest endpoint distance between frames
  // at the same times (analysis/arrow_distance.hpp).
  void add(const scene::CompareLayer& layer) {
    const std::vector<double> times = sequence_times(layer.samples, std::nullopt);
    const std::vector<Arrow> own = frames(times);
    std::vector<Arrow> other;
    try {
      const motion::SceneMotion motion = motion::with_method(scene_, panel_, layer.method);
      for (const double t : times) other.push_back(motion.arrow_at(t));
    } catch (const motion::NoMotion& error) {
      fail(layer_ + "/method", error.reason());
    }
    for (std::size_t i = 0; i < other.size(); ++i) {
      LineStyle line = layer.line;
      line.opacity *= fade(i, other.size());
      push(static_cast<int>(i), Polyline{{other[i].p, other[i].q()}, false, line});
    }
    const double distance = analysis::pattern_distance(own, other);
    if (!std::isfinite(distance)) fail(layer_, "the distance between the two patterns is not finite");
    const Color text{0.1, 0.1, 0.1, 1.0};
    if (selection_ == nullptr) {
      add_lines({{text, fmt::format("max |{} \u2212 {}| = {:.3g}", scene::method_id(panel_.keys), layer.method_name, distance)}},
                layer.at, layer.corner, layer.size, text);
    }
  }

  void add(const scene::PointTrajectoryLayer& layer) {
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

  void add(const scene::LegendLayer& layer) {
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

  const motion::Stage& stage_;
  std::size_t index_;
  const scene::Scene& scene_;
  const scene::Panel& panel_;
  const FrameSelection* selection_ = nullptr;
  const motion::SceneMotion& motion_;
  const scene::TrackMethod& track_;
  const std::vector<Keyframe>& keyframes_;
  const std::vector<TimedPoint>& points_;
  std::string layer_;
  Drawing drawing_;
};

}  // namespace

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
  return PanelBuilder(stage, index, selection).build();
}

Drawing panel_drawing(const scene::Scene& scene, const scene::Panel& panel, const FrameSelection* selection) {
  return panel_drawing(motion::Stage(scene, panel), 0, selection);
}

}  // namespace pita::render
