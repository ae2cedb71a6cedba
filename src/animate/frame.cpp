#include "animate/frame.hpp"

#include "motion/moving_keyframes.hpp"
#include "motion/no_motion.hpp"
#include "motion/scene_motion.hpp"
#include "render/panel_drawing.hpp"

namespace pita::animate {

namespace {

constexpr int kLayoutSamples = 33;

using Json = nlohmann::ordered_json;
using What = scene::Animation::What;

void append(std::vector<render::Drawing>& into, std::vector<render::Drawing> more) {
  for (std::size_t i = 0; i < into.size() && i < more.size(); ++i) {
    for (render::Item& item : more[i].items) into[i].items.push_back(std::move(item));
  }
}

Json point(Point p) { return Json::array({p.real(), p.imag()}); }

Json arrow_json(const Arrow& a) {
  return Json{{"p", point(a.p)}, {"m", a.m}, {"w", a.w}, {"q", point(a.q())}};
}

}  // namespace

std::vector<render::PanelPlacement> animation_layout(const scene::Scene& scene, const Timeline& timeline) {
  std::vector<render::Drawing> cover;
  if (timeline.what == What::pattern) {
    for (int i = 0; i < kLayoutSamples; ++i) {
      const scene::Scene at = motion::scene_at(scene, static_cast<double>(i) / (kLayoutSamples - 1));
      if (i == 0) {
        cover = render::frame_drawings(at, nullptr);
      } else {
        append(cover, render::frame_drawings(at, nullptr));
      }
    }
  } else {
    cover = render::build_figure(scene).drawings;
    for (int i = 0; i < kLayoutSamples; ++i) {
      const render::FrameSelection selection{
          timeline.first + (timeline.last - timeline.first) * i / (kLayoutSamples - 1), {}};
      append(cover, render::frame_drawings(scene, &selection));
    }
  }
  return render::checked_layout(scene, cover);
}

render::Figure frame_figure(const scene::Scene& scene, const Timeline& timeline, double t,
                            const std::vector<render::PanelPlacement>& placements) {
  render::Figure figure;
  if (timeline.what == What::pattern) {
    figure.drawings = render::frame_drawings(motion::scene_at(scene, t), nullptr);
    for (render::Drawing& drawing : figure.drawings) {
      for (render::Item& item : drawing.items) item.moving = !std::holds_alternative<render::Label>(item.shape);
    }
  } else {
    const render::FrameSelection selection{t, timeline.trail_times(t)};
    figure.drawings = render::frame_drawings(scene, &selection);
  }
  figure.placements = placements;
  return figure;
}

Json frame_record(const scene::Scene& scene, const Timeline& timeline, int k, const std::string& file) {
  const double t = timeline.time(k);
  Json record{{"frame", k + 1}, {"file", file}, {"t", t}};
  const scene::Panel& panel = scene.panels.front();
  if (timeline.what == What::pattern) {
    const scene::Scene at = motion::scene_at(scene, t);
    Json keys = Json::array();
    for (const Keyframe& key : at.panels.front().keyframes) {
      Json entry{{"t", key.t}};
      // Named: a range-for over arrow_json(...).items() would iterate a
      // destroyed temporary (only the items() proxy lives on).
      const Json arrow = arrow_json(key.arrow);
      for (const auto& [name, value] : arrow.items()) entry[name] = value;
      keys.push_back(std::move(entry));
    }
    record["keyframes"] = std::move(keys);
    return record;
  }
  const motion::SceneMotion motion = motion::build_motion(scene, panel);
  if (scene.kind == scene::SceneKind::poses) {
    const Affine2 A = motion.pose_at(t);
    record["A"] = Json::array({Json::array({A.L(0, 0), A.L(0, 1), A.b(0)}), Json::array({A.L(1, 0), A.L(1, 1), A.b(1)})});
  } else if (motion.has_points()) {
    record["p"] = point(motion.point_at(t));
  } else {
    record["D"] = arrow_json(motion.arrow_at(t));
  }
  return record;
}

}  // namespace pita::animate
