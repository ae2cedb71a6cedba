#include "analysis/comparison.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

#include "core/carrier.hpp"
#include "core/methods.hpp"
#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"

namespace pita::analysis {

namespace {

scene::Panel with_method(scene::Panel panel, Method method) {
  panel.method = method;
  panel.method_name = std::string(entry_of(method).id);
  return panel;
}

}  // namespace

double vector_angle(const scene::Scene& scene, const scene::Panel& panel, Method other, double t) {
  const Arrow mine = motion::build_motion(scene, panel).arrow_at(t);
  const Arrow theirs = motion::build_motion(scene, with_method(panel, other)).arrow_at(t);
  double largest = 0.0;
  for (const Keyframe& k : panel.keyframes) largest = std::max(largest, k.arrow.m);
  const double floor = kAngleVectorFloor * largest;
  if (!(std::abs(mine.vector()) > floor) || !(std::abs(theirs.vector()) > floor)) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return std::arg(theirs.vector() / mine.vector());
}

double handle_shift(const scene::Scene& scene, const scene::Panel& panel) {
  scene::Panel reference = scene::scene_panel(scene);
  reference.method = panel.method;
  reference.method_name = panel.method_name;
  reference.options = panel.options;
  reference.chain = panel.chain;
  reference.timing = panel.timing;
  const motion::SceneMotion own = motion::build_motion(scene, panel);
  const motion::SceneMotion base = motion::build_motion(scene, reference);
  const auto by_knot = [](const Keyframe& a, const Keyframe& b) { return a.t < b.t; };
  const auto [own_first, own_last] = std::minmax_element(panel.keyframes.begin(), panel.keyframes.end(), by_knot);
  const auto [base_first, base_last] =
      std::minmax_element(reference.keyframes.begin(), reference.keyframes.end(), by_knot);
  const double first = std::max(own_first->t, base_first->t);
  const double last = std::min(own_last->t, base_last->t);
  double shift = 0.0;
  for (const double t : motion::uniform_times(first, last, kHandleShiftSamples)) {
    const Affine2 S = carrier(panel.handle, own.arrow_at(t));
    const Affine2 S0 = carrier(reference.handle, base.arrow_at(t));
    for (const scene::ShapeOutline& shape : panel.shapes) {
      for (const Point x : shape.points) shift = std::max(shift, std::abs(apply(S, x) - apply(S0, x)));
    }
  }
  return shift;
}

}  // namespace pita::analysis
