// The builder of an arrow panel's drawing (internal to src/render/): one
// add() per layer kind of arrow scenes (the compiler refuses a kind without
// one), each defined in its kind's file, src/render/layers/<kind>.cpp; what
// they share (the frames, the times, the derivatives) in panel_drawing.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "analysis/frame_derivatives.hpp"
#include "core/methods.hpp"
#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"
#include "motion/stage.hpp"
#include "render/measure_text.hpp"
#include "render/panel_drawing.hpp"
#include "render/static_layers.hpp"

namespace pita::render::detail {

// Names of the keyframes in legends, as the paper writes them (A, B, C, then
// on through the alphabet for longer tracks).
inline std::string keyframe_name(std::size_t i) {
  return i < 26 ? std::string(1, static_cast<char>('A' + i)) : fmt::format("K{}", i);
}

// A trajectory's legend text.
inline std::string trajectory_name(scene::TrackedPoint point) {
  switch (point) {
    case scene::TrackedPoint::start:
      return "path of p";
    case scene::TrackedPoint::end:
      return "path of q";
    case scene::TrackedPoint::middle:
      return "path of the midpoint";
  }
  return "path";
}

class PanelBuilder {
 public:
  PanelBuilder(const motion::Stage& stage, std::size_t index, const FrameSelection* selection,
               StaticLayers* cache = nullptr)
      : stage_(stage),
        index_(index),
        scene_(stage.scene()),
        panel_(stage.panel(index)),
        frame_(selection),
        cache_(selection != nullptr ? cache : nullptr),
        motion_(built(stage, index)),
        track_(track_of(stage.scene(), panel_)),
        keyframes_(keyframes_of(panel_)),
        points_(points_of(panel_)) {}

  Drawing build();

 private:
  [[noreturn]] void fail(const std::string& pointer, const std::string& reason) const {
    // A scene-wide layer drawn in a panel: say which panel too.
    const bool elsewhere = !panel_.pointer.empty() && !pointer.starts_with(panel_.pointer);
    throw RenderError(scene_.path, pointer, elsewhere ? reason + " (in the panel at " + panel_.pointer + ")" : reason);
  }

  // The panel's method, and its keyframes or points (the other empty).
  static const scene::TrackMethod& track_of(const scene::Scene& scene, const scene::Panel& panel);
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

  static const motion::SceneMotion& built(const motion::Stage& stage, std::size_t index);

  // The frames at `times` (of the panel's motion, or of a layer's own); a
  // frame that does not exist is the layer's error.
  std::vector<Arrow> frames(const std::vector<double>& times) const { return frames(motion_, times); }
  std::vector<Arrow> frames(const motion::SceneMotion& motion, const std::vector<double>& times) const;

  void push(int index, Shape shape) { drawing_.items.push_back({layer_, index, std::move(shape)}); }

  // The times of a layer that draws a sequence of frames: an animation
  // frame's trail and time, else the layer's samples over its range.
  std::vector<double> sequence_times(const std::optional<int>& samples,
                                     const std::optional<scene::TimeRange>& range) const;
  double fade(std::size_t i, std::size_t count) const { return selection() != nullptr ? trail_fade(i, count) : 1.0; }

  // An animation frame's time and trail, or nullptr for the static figure.
  // Every layer asks here, so that a layer that never asks is known to be
  // the same at every frame (render/static_layers.hpp).
  const FrameSelection* selection() const {
    read_frame_ = true;
    return frame_;
  }

  // A pattern layer with its own "method" or "options" draws the motion of
  // a copy of the panel that has them (N57); its errors are the layer's.
  // The motion of a layer's own "method" and "options" (pattern, trajectory).
  motion::SceneMotion layer_motion(std::optional<Method> method, const scene::MethodOptionsPatch& patch) const;

  void add(const scene::PatternLayer& layer);

  // "shapes" (Sec. 7.1): the scene's shapes at each frame, carried by the
  // similarity that takes the handle onto D(t) (core/carrier.hpp).
  void add(const scene::ShapesLayer& layer);

  void add(const scene::KeyframesLayer& layer);

  void add(const scene::TrajectoryLayer& layer);

  void add(const scene::StrokeLayer& layer);

  void add(const scene::BannerLayer& layer);

  void add(const scene::DiscrepancyLayer& layer);

  void add(const scene::PlotLayer& layer);

  void add(const scene::PropertyTableLayer& layer);

  void add(const scene::HandleLayer& layer);

  // The derivatives of D at `times`; a stencil node where the motion does not
  // exist is the layer's error.
  std::vector<analysis::FrameDerivatives> derivatives(const std::vector<double>& times) const;

  // "vectors" (Figs. 9, 14, 15): scale x dx/du or d2x/du2, u = (t - a)/(c - a).
  void add(const scene::VectorsLayer& layer);

  // "fixed-points" (Fig. 9): segments from D(t).p (q, mid) to P7's global
  // fixed point or to the instantaneous center at t (core/instant_center.hpp).
  void add(const scene::FixedPointsLayer& layer);

  void add(const scene::LabelLayer& layer);

  // "measures": the numbers of `pita measure` for this panel's motion.
  void add(const scene::MeasuresLayer& layer);

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
    drawing_.legends.push_back(Legend{corner, size, lines, false, layer_});
  }

  // "guesses" (Sec. 6.1, 6.3; Figs. 16, 18): each drawn arrow G at its time t,
  // the frame D(t) under it, and per measure shown a line
  //   "E(L, D(2)) = 0.0123"  (PITA Eq. 47 as corrected, docs/paper-notes.md N5)
  //   "d(L, D(2)) = 0.42"    (max(|dp|, |dq|), docs/paper-notes.md N53).
  void add(const scene::GuessesLayer& layer);

  // "compare" (appendix B, Fig. B.30): the pattern of another method through
  // the panel's keyframes over the panel's own, and the printed line
  // "max |P3 - P10| = 2.1e-15", the largest endpoint distance between frames
  // at the same times (analysis/arrow_distance.hpp).
  void add(const scene::CompareLayer& layer);

  void add(const scene::PointTrajectoryLayer& layer);

  void add(const scene::LegendLayer& layer);

  const motion::Stage& stage_;
  std::size_t index_;
  const scene::Scene& scene_;
  const scene::Panel& panel_;
  const FrameSelection* frame_ = nullptr;  // through selection() only
  StaticLayers* cache_ = nullptr;          // with a frame: its layers that read nothing of it
  mutable bool read_frame_ = false;        // the layer being drawn asked for the frame
  const motion::SceneMotion& motion_;
  const scene::TrackMethod& track_;
  const std::vector<Keyframe>& keyframes_;
  const std::vector<TimedPoint>& points_;
  std::string layer_;
  Drawing drawing_;
};

}  // namespace pita::render::detail
