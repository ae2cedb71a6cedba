// A parsed scene -> what `pita eval` does with it (src/cli/eval.cpp), through
// the library: the method override (--method, chosen by a hash of the input),
// every panel's motion, the uniform frames (the scene's "samples") written as
// JSON and CSV, and frames at extrapolated times (--t). Refusals are
// SceneError and motion::NoMotion; a frame that is returned must be finite.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/methods.hpp"
#include "core/overloaded.hpp"
#include "fuzz_support.hpp"
#include "motion/no_motion.hpp"
#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"
#include "motion/stage.hpp"
#include "scene/frames.hpp"
#include "scene/scene.hpp"

namespace {

using namespace pita;

constexpr const char* kFile = "fuzz.json";

void check_frames(const std::vector<scene::Frame>& frames, std::size_t count) {
  PITA_FUZZ_CHECK(frames.size() == count);
  for (const scene::Frame& f : frames) {
    PITA_FUZZ_CHECK(std::isfinite(f.t) && std::isfinite(f.arrow.p.real()) && std::isfinite(f.arrow.p.imag()) &&
                    std::isfinite(f.arrow.m) && std::isfinite(f.arrow.w));
  }
}

void check_frames(const std::vector<scene::PoseFrame<Affine2>>& frames, std::size_t count) {
  PITA_FUZZ_CHECK(frames.size() == count);
  for (const scene::PoseFrame<Affine2>& f : frames) {
    PITA_FUZZ_CHECK(std::isfinite(f.t) && f.pose.L.allFinite() && f.pose.b.allFinite());
  }
}

// The frames at `times`, written as `pita eval` writes them: frames of arrows
// and of poses of the plane are checked finite one by one; points and poses
// of space through the text eval prints.
void evaluate(const scene::Scene& s, const motion::SceneMotion& motion, std::span<const double> times) {
  const scene::Panel own = scene::scene_panel(s);
  const auto text = [&] {
    PITA_FUZZ_CHECK(!motion::frames_text(own, motion, times, motion::FramesFormat::json).empty());
    PITA_FUZZ_CHECK(!motion::frames_text(own, motion, times, motion::FramesFormat::csv).empty());
  };
  std::visit(overloaded{[&](const scene::KeyframeKeys&) {
                          const std::vector<scene::Frame> frames = motion::sample_arrows(motion, times);
                          check_frames(frames, times.size());
                          PITA_FUZZ_CHECK(!scene::frames_to_json(scene::method_id(s.keys), frames).empty());
                          PITA_FUZZ_CHECK(!scene::frames_to_csv(frames).empty());
                        },
                        [&](const scene::PointKeys&) { text(); },
                        [&](const scene::PlanePoseKeys&) {
                          const std::vector<scene::PoseFrame<Affine2>> frames =
                              motion::sample_poses<Affine2>(motion, times);
                          check_frames(frames, times.size());
                          PITA_FUZZ_CHECK(!scene::pose_frames_to_json(scene::method_id(s.keys), frames).empty());
                          PITA_FUZZ_CHECK(!scene::pose_frames_to_csv(frames).empty());
                        },
                        [&](const scene::SpacePoseKeys&) { text(); }},
             s.keys);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = fuzz::text_of(data, size);
  try {
    scene::Scene s = scene::parse_scene(text, kFile);
    // --method: one input in four overrides the scene's method.
    const std::uint64_t choice = fuzz::hash_of(text);
    const std::span<const MethodEntry> methods = every_method();
    if (choice % 4 == 0 && !methods.empty()) {
      const MethodEntry& entry = methods[(choice / 4) % methods.size()];
      s = scene::with_method(std::move(s), entry.method);
    }
    if (!scene::has_motion_keys(s.keys)) return 0;  // eval prints no frames
    motion::Stage(s).check();
    const motion::SceneMotion motion = motion::build_motion(s);
    const std::vector<double> uniform = motion::uniform_times(motion, s.samples.value_or(scene::kDefaultSamples));
    PITA_FUZZ_CHECK(uniform.size() == static_cast<std::size_t>(s.samples.value_or(scene::kDefaultSamples)));
    evaluate(s, motion, uniform);
    // --t: times outside the knots extrapolate; a frame that is not finite is NoMotion.
    const double first = motion.first(), span = motion.last() - motion.first();
    for (const double x : {-1.0, -1e-3, 0.37, 1.0 + 1e-3, 3.0}) {
      const double t = first + x * span;
      try {
        evaluate(s, motion, std::span<const double>(&t, 1));
      } catch (const motion::NoMotion& error) {
        PITA_FUZZ_CHECK(error.file() == kFile);
      }
    }
  } catch (const scene::SceneError& error) {
    PITA_FUZZ_CHECK(error.file() == kFile);
  } catch (const motion::NoMotion& error) {
    PITA_FUZZ_CHECK(error.file() == kFile);
  }
  return 0;
}
