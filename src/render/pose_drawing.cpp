#include "render/pose_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "analysis/area_time.hpp"
#include "analysis/measure.hpp"
#include "analysis/swept_edge.hpp"
#include "analysis/velocity_field.hpp"
#include "core/affine_power.hpp"
#include "core/grazing_point.hpp"
#include "core/pose_motion.hpp"
#include "core/sam_velocity_field.hpp"
#include "core/sam_splines.hpp"
#include "core/steadiness.hpp"
#include "render/carried_shapes.hpp"
#include "render/measure_text.hpp"
#include "render/plot.hpp"
#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"
#include "motion/stage.hpp"

namespace pita::render {

namespace {

// Points per integral curve of a "field" layer.
constexpr int kFieldCurveSamples = 257;

class PoseBuilder {
 public:
  PoseBuilder(const motion::Stage& stage, std::size_t index, const FrameSelection* selection)
      : stage_(stage), index_(index), scene_(stage.scene()), panel_(stage.panel(index)), selection_(selection),
        keys_(keys_of(stage.scene(), stage.panel(index))) {}

  Drawing build() {
    const bool own = panel_.pose_layers.has_value();
    const std::vector<scene::PoseLayer>& layers = own ? *panel_.pose_layers : scene_.pose_layers;
    for (std::size_t i = 0; i < layers.size(); ++i) {
      layer_ = (own ? panel_.pointer : std::string()) + "/layers/" + std::to_string(i);
      std::visit([this](const auto& layer) { add(layer); }, layers[i]);
    }
    return std::move(drawing_);
  }

 private:
  // The panel's poses (a panel of another kind is not drawn here).
  static const scene::PlanePoseKeys& keys_of(const scene::Scene& scene, const scene::Panel& panel) {
    if (const auto* keys = std::get_if<scene::PlanePoseKeys>(&panel.keys)) return *keys;
    throw RenderError(scene.path, panel.pointer, "these layers draw poses; this panel has none of this kind");
  }

  [[noreturn]] void fail(const std::string& reason) const {
    const bool elsewhere = !panel_.pointer.empty() && !layer_.starts_with(panel_.pointer);
    throw RenderError(scene_.path, layer_,
                      elsewhere ? reason + " (in the panel at " + panel_.pointer + ")" : reason);
  }

  // The panel's motion, from the stage, when a layer needs it (layers such
  // as "existence" draw without poses).
  const motion::SceneMotion& motion() const {
    if (keys_.poses.empty()) fail("this layer draws a motion, and the panel has no poses");
    try {
      return stage_.motion(index_);
    } catch (const motion::NoMotion& error) {  // at the poses (or panel) it blames
      throw RenderError(error.file(), error.pointer(), error.reason());
    }
  }

  Affine2 pose_at(double t) {
    try {
      return motion().pose_at(t);
    } catch (const motion::NoMotion& error) {
      fail(error.reason());
    }
  }

  std::vector<double> times(const std::optional<int>& samples,
                            const std::optional<scene::TimeRange>& range) {
    const double from = range ? range->from : motion().first();
    const double to = range ? range->to : motion().last();
    return motion::uniform_times(from, to, samples.value_or(panel_.samples));
  }

  void push(int index, Shape shape) { drawing_.items.push_back({layer_, index, std::move(shape)}); }

  std::vector<Point> mapped(const Affine2& pose, const scene::ShapeOutline& shape) const {
    std::vector<Point> points;
    points.reserve(shape.points.size());
    for (const Point p : shape.points) points.push_back(pita::apply(pose, p));
    return points;
  }

  void add(const scene::ShapesLayer& layer) {
    // An animation frame draws the shapes at its time (and its trail), else
    // at every frame of the layer.
    const std::vector<double> ts =
        selected_times(selection_, selection_ != nullptr ? std::vector<double>{} : times(layer.samples, layer.range));
    // "lightness": "area" (SAM Fig. 9, N48): white mixed in by the frame's area.
    std::vector<double> areas;
    if (layer.lightness_by_area) {
      for (const double t : ts) areas.push_back(std::abs(pose_at(t).L.determinant()));
    }
    const std::vector<double> whites = lightness_whites(areas);
    for (std::size_t i = 0; i < ts.size(); ++i) {
      const double fade = selection_ != nullptr ? trail_fade(i, ts.size()) : 1.0;
      scene::ShapesLayer style = layer;
      if (!whites.empty() && whites[i] > 0.0) {
        style.line.color = lightened(style.line.color, whites[i]);
        if (style.fill) style.fill = lightened(*style.fill, whites[i]);
      }
      for (Shape& shape : carried_shapes(panel_.shapes, pose_at(ts[i]), style, scene_.canvas.y_up, fade)) {
        push(static_cast<int>(i), std::move(shape));
        drawing_.items.back().moving = selection_ != nullptr;
      }
    }
  }

  // SAM Figs. 4, 5: the shapes under another method's motion through the
  // panel's poses, each pose raised to `power` as a displacement from the
  // first pose (figure.hpp, VersusLayer).
  void add(const scene::VersusLayer& layer) {
    const PoseMethodInfo& about = info(layer.method);
    const auto count = static_cast<int>(keys_.poses.size());
    if (count < about.min_poses || count > about.max_poses) {
      fail(count_reason(layer.method, keys_.poses.size()));
    }
    std::optional<motion::SceneMotion> motion;
    try {
      motion.emplace(motion::with_pose_method(scene_, panel_, layer.method));
    } catch (const motion::NoMotion& error) {
      fail(fmt::format("method {}: {}", about.id, error.reason()));
    }
    std::vector<double> ts = layer.at;
    if (selection_ != nullptr) {
      ts = selection_->trail;
      ts.push_back(selection_->t);
    } else if (ts.empty()) {
      const double from = layer.range ? layer.range->from : motion->first();
      const double to = layer.range ? layer.range->to : motion->last();
      ts = motion::uniform_times(from, to, layer.samples.value_or(panel_.samples));
    }
    const scene::ShapesLayer style{layer.line, layer.fill, layer.fill_opacity, std::nullopt, std::nullopt};
    const Affine2 first = keys_.poses.front().pose;
    for (std::size_t i = 0; i < ts.size(); ++i) {
      Affine2 pose;
      try {
        pose = motion->pose_at(ts[i]);
      } catch (const motion::NoMotion& error) {
        fail(fmt::format("method {}: {}", about.id, error.reason()));
      }
      // (D(t) o D(t0)^-1)^k o D(t0), by k - 1 compositions.
      const Affine2 step = compose(pose, inverse(first));
      for (int k = 1; k < layer.power; ++k) pose = compose(step, pose);
      // The power multiplies the step: a large one can overflow where the
      // pose itself did not (no NaN reaches a figure).
      if (!pose.L.allFinite() || !pose.b.allFinite()) {
        fail(fmt::format("method {}: the pose at t = {} to the power {} is not finite (it overflows); use a "
                         "smaller \"power\" or times nearer the first pose",
                         about.id, ts[i], layer.power));
      }
      const double fade = selection_ != nullptr ? trail_fade(i, ts.size()) : 1.0;
      for (Shape& shape : carried_shapes(panel_.shapes, pose, style, scene_.canvas.y_up, fade)) {
        push(static_cast<int>(i), std::move(shape));
        drawing_.items.back().moving = selection_ != nullptr;
      }
    }
  }

  static std::string count_reason(PoseMethod method, std::size_t count) {
    const PoseMethodInfo& about = info(method);
    const std::string wanted = about.min_poses == about.max_poses
                                   ? fmt::format("exactly {}", about.min_poses)
                                   : fmt::format("at least {}", about.min_poses);
    return fmt::format("method {} takes {} poses (the panel has {})", about.id, wanted, count);
  }

  void add(const scene::PosesLayer& layer) {
    const std::vector<TimedPose>& poses = keys_.poses;
    if (poses.empty()) fail("this layer draws the poses, and the panel has no poses");
    const auto draw = [&](int index, const Affine2& pose, Color color) {
      const LineStyle line{color, layer.width, 1.0, {}};
      for (const scene::ShapeOutline& shape : panel_.shapes) {
        std::vector<Point> points = mapped(pose, shape);
        if (shape.closed) {
          push(index, FilledPath{{std::move(points)}, color, layer.fill_opacity, line});
        } else {
          push(index, Polyline{std::move(points), false, line});
        }
      }
    };
    // SAM Fig. 13's green blocks: the poses the last of the panel's four-point
    // subdivision steps inserts, every other one of the subdivided sequence
    // (subdivide_four_point keeps the old poses at the even places; N43).
    if (layer.inserted && keys_.method == PoseMethod::four_point && keys_.subdivisions > 0) {
      (void)motion();  // the panel's motion, or its error, first
      std::vector<Affine2> controls;
      for (const TimedPose& pose : poses) controls.push_back(pose.pose);
      try {
        for (int step = 0; step < keys_.subdivisions; ++step) controls = subdivide_four_point(controls);
      } catch (const NoRealLogarithm& error) {
        fail(fmt::format("the four-point subdivision needs a SAM that does not exist: {}", error.what()));
      }
      for (std::size_t k = 1; k < controls.size(); k += 2) {
        draw(static_cast<int>(poses.size() + k / 2), controls[k], *layer.inserted);
      }
    }
    for (std::size_t i = 0; i < poses.size(); ++i) {
      draw(static_cast<int>(i), poses[i].pose, layer.colors[i % layer.colors.size()]);
    }
  }

  // d/du of the pose at time t, u the time normalised to the motion's
  // duration (1 from the first pose to the last): PoseMotion::velocity.
  Affine2 velocity_at(double t) {
    const double duration = motion().last() - motion().first();
    Affine2 rate;
    try {
      rate = motion().pose_velocity(t);
    } catch (const motion::NoMotion& error) {
      fail(error.reason());
    }
    return Affine2{rate.L * duration, rate.b * duration};
  }

  void add(const scene::VelocitiesLayer& layer) {
    const std::vector<double> ts = times(layer.samples, layer.range);
    for (std::size_t i = 0; i < ts.size(); ++i) {
      const Affine2 pose = pose_at(ts[i]);
      const Affine2 velocity = velocity_at(ts[i]);
      for (const scene::ShapeOutline& shape : panel_.shapes) {
        for (const Point p : shape.points) {
          const Point from = pita::apply(pose, p);
          const Point rate = pita::apply(velocity, p);  // (dL/du) p + db/du
          push(static_cast<int>(i), ArrowShape{from, from + layer.scale * rate, layer.line});
        }
      }
    }
  }

  void add(const scene::PathsLayer& layer) {
    const std::vector<double> ts = times(layer.samples, layer.range);
    std::vector<Affine2> poses;
    poses.reserve(ts.size());
    for (const double t : ts) poses.push_back(pose_at(t));
    for (const scene::ShapeOutline& shape : panel_.shapes) {
      for (const Point p : shape.points) {
        std::vector<Point> path;
        path.reserve(poses.size());
        for (const Affine2& pose : poses) path.push_back(pita::apply(pose, p));
        push(-1, Polyline{std::move(path), false, layer.line});
      }
    }
  }

  void add(const scene::ExistenceLayer& layer) {
    for (Item& item : existence_drawing(layer, layer_).items) drawing_.items.push_back(std::move(item));
  }
  void add(const scene::Sam3dExistenceLayer& layer) {
    for (Item& item : sam3d_existence_drawing(layer, layer_).items) drawing_.items.push_back(std::move(item));
  }

  // Fig. 11: the shapes at sam_patch(A, B, C, D, i/(columns-1), j/(rows-1)).
  void add(const scene::PatchLayer& layer) {
    const std::vector<TimedPose>& poses = keys_.poses;
    const std::size_t needed = layer.regular ? 3 : 4;
    if (poses.size() < needed) {
      fail(fmt::format("a patch takes the panel's first {} poses as corners (top left, top right, "
                       "bottom left{}); the panel has {}",
                       needed, layer.regular ? "" : ", bottom right", poses.size()));
    }
    const Affine2 &A = poses[0].pose, &B = poses[1].pose, &C = poses[2].pose;
    try {
      const Affine2 D = layer.regular ? regular_patch_corner(A, B, C) : poses[3].pose;
      int index = 0;
      for (int j = 0; j < layer.rows; ++j) {
        const double v = static_cast<double>(j) / (layer.rows - 1);
        for (int i = 0; i < layer.columns; ++i, ++index) {
          const double u = static_cast<double>(i) / (layer.columns - 1);
          const Affine2 pose = sam_patch(A, B, C, D, u, v);
          if (!pose.L.allFinite() || !pose.b.allFinite()) fail("the patch overflows");
          for (const scene::ShapeOutline& shape : panel_.shapes) {
            LineStyle line = layer.line;
            if (shape.color) line.color = *shape.color;
            const bool corner = i == layer.columns - 1 && j == layer.rows - 1;
            if (corner && layer.corner) line = *layer.corner;  // F_D highlighted
            std::vector<Point> points = mapped(pose, shape);
            if (layer.fill && shape.closed) {
              push(index, FilledPath{{std::move(points)}, *layer.fill, layer.fill_opacity, line});
            } else {
              push(index, Polyline{std::move(points), shape.closed, line});
            }
          }
        }
      }
    } catch (const NoRealLogarithm& error) {
      fail(fmt::format("the patch needs a SAM that does not exist: {}", error.what()));
    }
  }

  // "of": "area" (SAM Fig. 9, N48): each method's motion on the panel's poses.
  void add_area_plot(const scene::PlotLayer& layer) {
    (void)motion();  // the panel's own motion, or its error, first
    const std::vector<double> marks = times(std::nullopt, std::nullopt);
    const std::vector<double> samples = times(layer.samples, std::nullopt);
    std::vector<PoseMethod> methods = layer.methods;
    if (methods.empty()) methods.push_back(keys_.method);
    std::vector<AreaSeries> series;
    for (std::size_t k = 0; k < methods.size(); ++k) {
      const PoseMethodInfo& about = info(methods[k]);
      const auto count = static_cast<int>(keys_.poses.size());
      if (count < about.min_poses || count > about.max_poses) {
        fail(fmt::format("methods/{}: {} takes {} to {} poses; the panel has {}", k, about.id, about.min_poses,
                         about.max_poses, count));
      }
      try {
        const motion::SceneMotion moving = motion::with_pose_method(scene_, panel_, methods[k]);
        series.push_back({std::string(about.id), layer.colors[k % layer.colors.size()],
                          analysis::area_over_time(moving, samples), analysis::area_over_time(moving, marks)});
      } catch (const motion::NoMotion& error) {
        fail(fmt::format("methods/{}: {}", k, error.reason()));
      }
    }
    for (Item& item : area_plot_items(layer, series, motion().first(), motion().last(), layer_)) {
      drawing_.items.push_back(std::move(item));
    }
  }

  void add(const scene::PlotLayer& layer) {
    if (layer.of == scene::PlotOf::area) return add_area_plot(layer);
    const std::vector<double> marks = times(std::nullopt, std::nullopt);
    try {
      for (Item& item : plot_items(layer, motion(), marks, layer_)) drawing_.items.push_back(std::move(item));
    } catch (const motion::NoMotion& error) {
      fail(error.reason());
    } catch (const std::invalid_argument& error) {
      fail(fmt::format("cannot plot the distance of {}: {}", scene::method_id(panel_.keys), error.what()));
    }
  }

  // SAM Fig. 8 (Eq. 7, N47): the field of the panel's SAM at the nodes of a
  // grid, its integral curves through every `curves`-th node, the fixed point,
  // and the measured agreement of the curves with the field.
  void add(const scene::FieldLayer& layer) {
    if (keys_.method != PoseMethod::sam) {
      fail(fmt::format("a field layer draws the stationary velocity field of a SAM; the panel's method is {}",
                       scene::method_id(panel_.keys)));
    }
    const double first = motion().first(), last = motion().last();
    std::optional<SamVelocityField> field;
    try {
      field.emplace(SamVelocityField::between(keys_.poses.front().pose, keys_.poses.back().pose));
    } catch (const NoRealLogarithm& error) {
      fail(error.what());
    }
    // u = (t - first) / (last - first): the field per unit of u, as "velocities".
    const auto node = [&](int i, int j) {
      const Point low = layer.box.min, high = layer.box.max;
      return Eigen::Vector2d(low.real() + (high.real() - low.real()) * i / (layer.columns - 1),
                             low.imag() + (high.imag() - low.imag()) * j / (layer.rows - 1));
    };
    const auto point = [](const Eigen::Vector2d& x) { return Point{x.x(), x.y()}; };
    for (int j = 0; j < layer.rows; ++j) {
      for (int i = 0; i < layer.columns; ++i) {
        const Eigen::Vector2d x = node(i, j);
        push(-1, ArrowShape{point(x), point(x + layer.scale * field->at(x)), layer.line});
      }
    }
    std::vector<Eigen::Vector2d> starts;
    if (layer.curves > 0) {
      for (int j = 0; j < layer.rows; j += layer.curves) {
        for (int i = 0; i < layer.columns; i += layer.curves) starts.push_back(node(i, j));
      }
    }
    const double from = layer.range ? layer.range->from : first, to = layer.range ? layer.range->to : last;
    std::vector<double> us;
    for (const double t : motion::uniform_times(from, to, kFieldCurveSamples)) us.push_back((t - first) / (last - first));
    for (const Eigen::Vector2d& x0 : starts) {
      std::vector<Point> curve;
      for (const double u : us) curve.push_back(point(field->trajectory(x0, u)));
      push(-1, Polyline{std::move(curve), false, layer.curve});
    }
    const double side = std::min(layer.box.max.real() - layer.box.min.real(), layer.box.max.imag() - layer.box.min.imag());
    if (layer.fixed_point && field->fixed_point()) {
      const Point q = point(*field->fixed_point());
      push(-1, Circle{q, 0.012 * side, LineStyle{Color{0, 0, 0, 1}, 1.0, 1.0, {}}, Color{0, 0, 0, 1}});
      push(-1, Label{"q", q + Point{0.02 * side, 0.02 * side}, 12.0, Color{0, 0, 0, 1}});
    }
    if (selection_ == nullptr && !starts.empty()) {
      // Every curve, at 33 times of its range: velocity by finite differences
      // against the field at the same point (analysis/velocity_field.hpp).
      std::vector<double> checked;
      for (std::size_t k = 0; k < us.size(); k += us.size() / 32) checked.push_back(us[k]);
      const analysis::FieldCheck check = analysis::check_integral_curves(*field, starts, checked);
      // Below 1e-10 the digits are rounding noise that varies between
      // compilers, so the figure prints the bound (golden-stable).
      const std::string deviation =
          check.deviation < 1e-10 ? std::string("< 1e-10") : fmt::format("= {:.1e}", check.deviation);
      push(-1, Label{fmt::format("stationary field: |x'(u) - v(x(u))| / max|v| {} on {} curve points",
                                 deviation, check.samples),
                     Point{layer.box.min.real(), layer.box.min.imag() - 0.09 * side}, 13.0,
                     Color{0.1, 0.1, 0.1, 1.0}});
    }
  }

  void add(const scene::LabelLayer& layer) {
    push(-1, Label{layer.text, layer.at, layer.size, layer.color});
  }

  // The ARA (core/steadiness.hpp) of the panel's motion over a regular grid
  // of the shapes' bounding box in reference coordinates, printed.
  void add(const scene::AraLayer& layer) {
    if (panel_.shapes.empty()) fail("an ara layer samples the panel's shapes, and the panel has none");
    Point low = panel_.shapes.front().points.front(), high = low;
    for (const scene::ShapeOutline& shape : panel_.shapes) {
      for (const Point p : shape.points) {
        low = {std::min(low.real(), p.real()), std::min(low.imag(), p.imag())};
        high = {std::max(high.real(), p.real()), std::max(high.imag(), p.imag())};
      }
    }
    std::vector<Eigen::Vector2d> points;
    for (int i = 0; i < layer.grid; ++i) {
      for (int j = 0; j < layer.grid; ++j) {
        const double x = low.real() + (high.real() - low.real()) * i / (layer.grid - 1);
        const double y = low.imag() + (high.imag() - low.imag()) * j / (layer.grid - 1);
        points.emplace_back(x, y);
      }
    }
    const double ara = average_relative_acceleration(motion().poses(), points);
    if (!std::isfinite(ara)) fail("the ARA of this motion is not finite (a pose on the way is singular)");
    push(-1, Label{fmt::format("ARA = {:.{}f}", ara, layer.digits), layer.at, layer.size, layer.color});
  }

  // "measures": ARA and area monotonicity (or any name) of the panel's motion.
  void add(const scene::MeasuresLayer& layer) {
    if (selection_ != nullptr) return;  // a figure's numbers, not an animation frame's
    (void)motion();  // the panel's poses must give a motion (its error otherwise)
    const analysis::MotionMeasures measures = analysis::measure_panel(stage_, index_);
    if (measures.no_motion) fail(*measures.no_motion);
    add_measure_text(layer, measure_lines(measures, layer.show), drawing_, layer_);
  }

  // SAM paper Fig. 10 (Sec. 7.2, Eq. 8): an edge swept by the panel's motion,
  // the envelope of its grazing points and the paths of points grazing at a
  // few instants (analysis/swept_edge.hpp), and what the grazing parameter
  // does over the layer's range.
  void add(const scene::SweptLayer& layer) {
    const auto vector = [](Point p) { return Eigen::Vector2d(p.real(), p.imag()); };
    const auto point = [](const Eigen::Vector2d& x) { return Point(x.x(), x.y()); };
    const Edge edge{vector(layer.edge[0]), vector(layer.edge[1])};
    const analysis::PoseTrack track{[this](double t) { return pose_at(t); },
                                    [this](double t) { return velocity_at(t); }};
    const double from = layer.range ? layer.range->from : motion().first();
    const double to = layer.range ? layer.range->to : motion().last();
    const analysis::GrazingTrace trace = analysis::trace_grazing(track, edge, from, to, layer.trace_samples);
    for (const Affine2& pose : {pose_at(from), pose_at(to)}) {
      if (!pose.L.allFinite() || !pose.b.allFinite()) fail("the swept edge overflows");
    }
    const auto polyline = [&](const std::vector<Eigen::Vector2d>& points) {
      std::vector<Point> out;
      out.reserve(points.size());
      for (const Eigen::Vector2d& x : points) out.push_back(point(x));
      return out;
    };
    // The size of the swept region, for the dots.
    std::vector<Point> ends[2];
    for (int k = 0; k < 2; ++k) ends[k] = polyline(analysis::edge_point_path(track, edge, k, trace.times));
    Point low = ends[0].front(), high = low;
    for (const auto& path : ends) {
      for (const Point p : path) {
        low = {std::min(low.real(), p.real()), std::min(low.imag(), p.imag())};
        high = {std::max(high.real(), p.real()), std::max(high.imag(), p.imag())};
      }
    }
    const double dot = 0.008 * std::max(std::abs(high - low), 1e-300);
    if (layer.segments) {
      const std::vector<double> ts = times(layer.samples, layer.range);
      for (std::size_t i = 0; i < ts.size(); ++i) {
        const Affine2 pose = pose_at(ts[i]);
        push(static_cast<int>(i),
             Polyline{{pita::apply(pose, layer.edge[0]), pita::apply(pose, layer.edge[1])}, false, *layer.segments});
      }
    }
    if (layer.ends) {
      for (auto& path : ends) push(-1, Polyline{std::move(path), false, *layer.ends});
    }
    if (layer.envelope) {
      for (const auto& run : analysis::envelope(track, edge, trace)) {
        push(-1, Polyline{polyline(run), false, *layer.envelope});
      }
    }
    if (layer.grazing) {
      // The points grazing at instants (k + 1) / (n + 1) of the range, each
      // traced over the whole range, with a dot where it grazes.
      for (int k = 0; k < layer.instants; ++k) {
        const double t = from + (to - from) * (k + 1) / (layer.instants + 1);
        const std::optional<double> s = grazing_parameter(pose_at(t), velocity_at(t), edge);
        if (!s) continue;
        push(k, Polyline{polyline(analysis::edge_point_path(track, edge, *s, trace.times)), false, *layer.grazing});
        const Point at = pita::apply(pose_at(t), point(edge.from + *s * (edge.to - edge.from)));
        push(k, Circle{at, dot, *layer.grazing, layer.grazing->color});
      }
    }
    if (layer.claim_at) {
      push(-1, Label{grazing_claim(analysis::grazing_range(trace)), *layer.claim_at, layer.size, layer.color});
    }
  }

  static std::string grazing_claim(const analysis::GrazingRange& range) {
    if (range.defined == 0) return fmt::format("no grazing point at any of {} times", range.total);
    const std::string none =
        range.defined < range.total ? fmt::format(" (none at {} of {} times)", range.total - range.defined, range.total)
                                    : "";
    if (range.spread() <= analysis::kConstantGrazingSpread) {
      // The spread itself is rounding noise, whose digits vary between compilers: only its bound is printed.
      return fmt::format("grazing parameter s = {:.5f} at all {} times (spread < {:.0e}): constant{}",
                         range.min, range.defined, analysis::kConstantGrazingSpread, none);
    }
    return fmt::format("grazing parameter s ranges from {:.5f} to {:.5f} over {} times: not constant{}", range.min,
                       range.max, range.defined, none);
  }

  const motion::Stage& stage_;
  std::size_t index_;
  const scene::Scene& scene_;
  const scene::Panel& panel_;
  const FrameSelection* selection_ = nullptr;
  const scene::PlanePoseKeys& keys_;
  std::string layer_;
  Drawing drawing_;
};

}  // namespace

Drawing pose_panel_drawing(const motion::Stage& stage, std::size_t index, const FrameSelection* selection) {
  return PoseBuilder(stage, index, selection).build();
}

Drawing pose_panel_drawing(const scene::Scene& scene, const scene::Panel& panel, const FrameSelection* selection) {
  return pose_panel_drawing(motion::Stage(scene, panel), 0, selection);
}

}  // namespace pita::render
