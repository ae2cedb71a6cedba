// The arrow layers that draw a measure of the motion: discrepancy circles,
// plots, the property table, vectors, fixed points, measures, guesses and
// comparisons (members of the panel builder, panel_builder.hpp).
#include <algorithm>
#include <cmath>

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

namespace pita::render::detail {

void PanelBuilder::add(const scene::DiscrepancyLayer& layer) {
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

void PanelBuilder::add(const scene::PlotLayer& layer) {
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

void PanelBuilder::add(const scene::PropertyTableLayer& layer) {
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

// "vectors" (Figs. 9, 14, 15): scale x dx/du or d2x/du2, u = (t - a)/(c - a).
void PanelBuilder::add(const scene::VectorsLayer& layer) {
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
void PanelBuilder::add(const scene::FixedPointsLayer& layer) {
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

// "measures": the numbers of `pita measure` for this panel's motion.
void PanelBuilder::add(const scene::MeasuresLayer& layer) {
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

// "guesses" (Sec. 6.1, 6.3; Figs. 16, 18): each drawn arrow G at its time t,
// the frame D(t) under it, and per measure shown a line
//   "E(L, D(2)) = 0.0123"  (Eq. 47 as corrected, docs/paper-notes.md N5)
//   "d(L, D(2)) = 0.42"    (max(|dp|, |dq|), docs/paper-notes.md N53).
void PanelBuilder::add(const scene::GuessesLayer& layer) {
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
void PanelBuilder::add(const scene::CompareLayer& layer) {
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

}  // namespace pita::render::detail
