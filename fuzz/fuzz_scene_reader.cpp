// Bytes -> the scene reader (scene::parse_scene: JSON text, checks, defaults,
// panels, layers, timing). A scene it accepts must be as documented (docs/reference/scene-format.md
// "Scene format"); anything it refuses must be a SceneError naming the file.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/overloaded.hpp"
#include "fuzz_support.hpp"
#include "scene/scene.hpp"

namespace {

constexpr const char* kFile = "fuzz.json";

bool finite(const pita::Keyframe& k) {
  return std::isfinite(k.t) && std::isfinite(k.arrow.p.real()) && std::isfinite(k.arrow.p.imag()) &&
         std::isfinite(k.arrow.m) && std::isfinite(k.arrow.w);
}

// Knots increase, unless "knots": "as-given" (docs/paper-notes.md N41) hands
// three keyframes over in the order written: then they are distinct.
void check_keyframes(const std::vector<pita::Keyframe>& keyframes, pita::KnotOrder order) {
  for (std::size_t i = 0; i < keyframes.size(); ++i) {
    PITA_FUZZ_CHECK(finite(keyframes[i]));
    PITA_FUZZ_CHECK(keyframes[i].arrow.m > 0.0);
    if (order == pita::KnotOrder::increasing) {
      if (i > 0) PITA_FUZZ_CHECK(keyframes[i - 1].t < keyframes[i].t);
    } else {
      PITA_FUZZ_CHECK(keyframes.size() == 3);
      for (std::size_t j = 0; j < i; ++j) PITA_FUZZ_CHECK(keyframes[j].t != keyframes[i].t);
    }
  }
}

void check_poses(const std::vector<pita::TimedPose>& poses) {
  PITA_FUZZ_CHECK(poses.size() <= static_cast<std::size_t>(pita::scene::kMaxPoses));
  for (std::size_t i = 0; i < poses.size(); ++i) {
    PITA_FUZZ_CHECK(std::isfinite(poses[i].t));
    PITA_FUZZ_CHECK(poses[i].pose.L.allFinite() && poses[i].pose.b.allFinite());
    if (i > 0) PITA_FUZZ_CHECK(poses[i - 1].t < poses[i].t);
  }
}

// The keys of a scene or panel, of whichever kind.
void check_keys(const pita::scene::MotionKeys& keys) {
  using namespace pita;
  std::visit(overloaded{[](const scene::KeyframeKeys& given) { check_keyframes(given.keyframes, given.options.knots); },
                        [](const scene::PointKeys& given) {
                          for (const TimedPoint& point : given.points) PITA_FUZZ_CHECK(std::isfinite(point.t));
                        },
                        [](const scene::PlanePoseKeys& given) { check_poses(given.poses); },
                        [](const scene::SpacePoseKeys& given) {
                          PITA_FUZZ_CHECK(given.poses.size() <= static_cast<std::size_t>(scene::kMaxPoses));
                        }},
             keys);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pita;
  try {
    const scene::Scene s = scene::parse_scene(fuzz::text_of(data, size), kFile);
    PITA_FUZZ_CHECK(s.path == kFile);
    PITA_FUZZ_CHECK(!s.panels.empty() && s.panels.size() <= static_cast<std::size_t>(scene::kMaxPanels));
    if (s.samples) PITA_FUZZ_CHECK(*s.samples >= scene::kMinSamples && *s.samples <= scene::kMaxSamples);
    check_keys(s.keys);
    for (const scene::Panel& panel : s.panels) {
      check_keys(panel.keys);
    }
  } catch (const scene::SceneError& error) {
    PITA_FUZZ_CHECK(error.file() == kFile);  // every refusal names the file
  }
  return 0;
}
