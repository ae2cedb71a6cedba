#include "animate/frame.hpp"

#include <algorithm>
#include <optional>
#include <variant>

#include "core/overloaded.hpp"
#include "core/pose_traits.hpp"
#include "motion/moving_keyframes.hpp"
#include "motion/no_motion.hpp"
#include "motion/scene_motion.hpp"
#include "motion/stage.hpp"
#include "render/label_placement.hpp"
#include "render/panel_drawing.hpp"
#include "scene/arrow_json.hpp"

namespace pita::animate {

namespace {

constexpr int kLayoutSamples = kLayoutFrames;

using Json = nlohmann::ordered_json;
using What = scene::Animation::What;

void append(std::vector<render::Drawing>& into, std::vector<render::Drawing> more) {
  for (std::size_t i = 0; i < into.size() && i < more.size(); ++i) {
    for (render::Item& item : more[i].items) into[i].items.push_back(std::move(item));
  }
}

using scene::point_json;

// An arrow of a frame: scene::arrow_json's members and the tip "q".
Json frame_arrow_json(const Arrow& a) {
  Json arrow = scene::arrow_json(a);
  arrow["q"] = point_json(a.q());
  return arrow;
}

// A pose's matrix as rows [L(r, 0), ..., b(r)], in the plane or in space.
template <class Pose>
Json pose_json(const Pose& A) {
  constexpr int n = PoseTraits<Pose>::dimension;
  Json rows = Json::array();
  for (int r = 0; r < n; ++r) {
    Json row = Json::array();
    for (int c = 0; c < n; ++c) row.push_back(A.L(r, c));
    row.push_back(A.b(r));
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace

std::vector<render::PanelPlacement> animation_layout(const scene::Scene& scene, const Timeline& timeline,
                                                     const motion::Stage* given, render::StaticLayers* layers) {
  std::vector<render::Drawing> cover;
  if (timeline.what == What::pattern) {
    for (int i = 0; i < kLayoutSamples; ++i) {
      const scene::Scene at = motion::scene_at(scene, timeline.tau(static_cast<double>(i) / (kLayoutSamples - 1)));
      if (i == 0) {
        cover = render::frame_drawings(at, nullptr);
      } else {
        append(cover, render::frame_drawings(at, nullptr));
      }
    }
  } else {
    // One stage for the static figure and every cover frame; of each frame
    // only its bounds are kept (33 whole frames of a long track held 1 GB).
    std::optional<motion::Stage> built;
    if (given == nullptr) built.emplace(scene);
    const motion::Stage& stage = given != nullptr ? *given : *built;
    cover = render::build_figure(stage).drawings;
    render::StaticLayers own;
    if (layers == nullptr) layers = &own;
    std::vector<std::optional<scene::Box>> reach(cover.size());
    for (int i = 0; i < kLayoutSamples; ++i) {
      const render::FrameSelection selection{
          timeline.first + (timeline.last - timeline.first) * i / (kLayoutSamples - 1), {}};
      const std::vector<render::Drawing> frame = render::frame_drawings(stage, &selection, layers);
      for (std::size_t p = 0; p < reach.size() && p < frame.size(); ++p) {
        const std::optional<scene::Box> b = render::bounds(frame[p]);
        if (!b) continue;
        reach[p] = reach[p] ? scene::Box{{std::min(reach[p]->min.real(), b->min.real()),
                                          std::min(reach[p]->min.imag(), b->min.imag())},
                                         {std::max(reach[p]->max.real(), b->max.real()),
                                          std::max(reach[p]->max.imag(), b->max.imag())}}
                            : *b;
      }
    }
    // The frames' reach as two invisible corners: the layout sees their bounds.
    for (std::size_t p = 0; p < reach.size(); ++p) {
      if (!reach[p]) continue;
      render::Item corners;
      corners.shape = render::Polyline{{reach[p]->min, reach[p]->max}, false, {}};
      cover[p].items.push_back(std::move(corners));
    }
  }
  return render::checked_layout(scene, cover);
}

render::Figure frame_figure(const scene::Scene& scene, const Timeline& timeline, double t,
                            const std::vector<render::PanelPlacement>& placements, const motion::Stage* stage,
                            render::StaticLayers* layers) {
  render::Figure figure;
  if (timeline.what == What::pattern) {
    figure.drawings = render::frame_drawings(motion::scene_at(scene, timeline.tau(t)), nullptr);
    for (render::Drawing& drawing : figure.drawings) {
      for (render::Item& item : drawing.items) item.moving = !std::holds_alternative<render::Label>(item.shape);
    }
  } else {
    const render::FrameSelection selection{t, timeline.trail_times(t)};
    figure.drawings = stage != nullptr ? render::frame_drawings(*stage, &selection, layers)
                                       : render::frame_drawings(scene, &selection);
  }
  figure.placements = placements;
  render::place_labels(scene, figure.drawings, figure.placements);  // against this frame's data
  return figure;
}

namespace {

// What one panel shows at time t: its keyframes at tau ("pattern"), else D(t),
// A(t) or the point of a curve through timed points.
void add_panel_state(Json& into, const scene::Panel& panel, const motion::Stage* stage, std::size_t index,
                     const Timeline& timeline, double t) {
  if (timeline.what == What::pattern || stage == nullptr) {
    Json keys = Json::array();
    const auto* arrows = std::get_if<scene::KeyframeKeys>(&panel.keys);
    for (const Keyframe& key : arrows != nullptr ? arrows->keyframes : std::vector<Keyframe>{}) {
      Json entry{{"t", key.t}};
      entry.update(frame_arrow_json(key.arrow));
      keys.push_back(std::move(entry));
    }
    into["keyframes"] = std::move(keys);
    return;
  }
  const motion::SceneMotion& motion = stage->motion(index);
  std::visit(overloaded{[&](const motion::ArrowTrack&) { into["D"] = frame_arrow_json(motion.arrow_at(t)); },
                        [&](const motion::PointTrack&) { into["p"] = point_json(motion.point_at(t)); },
                        [&](const motion::PlanePoses&) { into["A"] = pose_json(motion.pose_at<Affine2>(t)); },
                        [&](const motion::SpacePoses&) { into["A"] = pose_json(motion.pose_at<Affine3>(t)); }},
             motion.built());
}

}  // namespace

Json frame_record(const scene::Scene& scene, const Timeline& timeline, int k, const std::string& file,
                  const motion::Stage* shared) {
  const double t = timeline.time(k);
  Json record{{"frame", k + 1}, {"file", file}, {"t", t}};
  const bool pattern = timeline.what == What::pattern;
  if (pattern) record["tau"] = timeline.tau(t);
  const scene::Scene at = pattern ? motion::scene_at(scene, timeline.tau(t)) : scene;
  // A pattern's record holds its keyframes, a motion's the state of each panel's motion.
  std::optional<motion::Stage> stage;
  if (!pattern && shared == nullptr) stage.emplace(at);
  const motion::Stage* motions = pattern ? nullptr : shared != nullptr ? shared : &*stage;
  // The first panel's state at the top level, every panel's under "panels".
  add_panel_state(record, at.panels.front(), motions, 0, timeline, t);
  if (at.panels.size() > 1) {
    Json panels = Json::array();
    for (std::size_t i = 0; i < at.panels.size(); ++i) {
      const scene::Panel& panel = at.panels[i];
      Json entry{{"pointer", panel.pointer}, {"title", panel.title}};
      add_panel_state(entry, panel, motions, i, timeline, t);
      panels.push_back(std::move(entry));
    }
    record["panels"] = std::move(panels);
  }
  return record;
}

}  // namespace pita::animate
