#include "analysis/pose_properties.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <Eigen/LU>

#include "core/sam_family_motion.hpp"

namespace pita::analysis {

namespace pose_probes {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The one table of the pose properties (docs/reference/audit.md "What
// carries over to affine poses" says why these and not the other rows of
// Fig. 10).
constexpr std::array<PosePropertyInfo, 7> kPoseProperties{{
    {PoseProperty::exists, "exists", "4.1",
     "share of the random triples where the motion is built and every frame at 33 times in [a, c] is a real, finite "
     "pose",
     PoseVerdict::share, 1.0},
    {PoseProperty::interpolates, "interpolates", "Sec. 1 (interpolation)",
     "largest distance between D(a), D(b), D(c) and A, B, C, over the extent", PoseVerdict::deviation, 1e-7},
    {PoseProperty::symmetric, "symmetric", "4.4, PITA Eq. 41",
     "largest distance between D(a, A, b, B, c, C; t) and D(a, C, a + c - b, B, c, A; a + c - t), over the extent",
     PoseVerdict::deviation, 1e-4},
    {PoseProperty::left_affine_invariant, "left-affine-invariant", "4.3, 4.10 A",
     "largest distance between D(G A, G B, G C; t) and G D(A, B, C; t) for a random affinity G of the world "
     "(det > 0), over the extent of the moved triple",
     PoseVerdict::deviation, 1e-4},
    {PoseProperty::right_affine_invariant, "right-affine-invariant", "4.5 H",
     "largest distance between D(A H, B H, C H; t) and D(A, B, C; t) H for a random change of handle H, an "
     "affinity of the body (det > 0), over the extent of the moved triple",
     PoseVerdict::deviation, 1e-4},
    {PoseProperty::knot_controlled, "knot-controlled", "4.8 K",
     "how far the poses move off the path of the original when the knot ratio (b - a)/(c - a) changes by 0.2: the "
     "largest distance from a new D(t) to the curve of poses D([a, c]), over the extent",
     PoseVerdict::reaction, 1e-6},
    {PoseProperty::steady, "steady", "4.11 L; SAM 2.4",
     "the SAM paper's ARA over [a, c] (time as u in [0, 1], the vertices of the reference simplex): the mean "
     "|dw/du| of the velocity in the moving frame w = L^-1 (L' p + b'); the cell shows the median over the triples; "
     "steady when every triple's ARA is at most 1e-6 times max(1, its mean |w|)",
     PoseVerdict::steadiness, 1e-6},
}};

template <class Pose>
using Motion = SamFamilyMotion<Pose>;
template <class Pose>
using Vec = typename Pose::Vector;

template <class Pose>
std::vector<TimedPoseOf<Pose>> listed(const PoseTriple<Pose>& k) {
  return {k.begin(), k.end()};
}

// The motion, or nullopt when it cannot be built; `why` gets the reason.
template <class Pose>
std::optional<Motion<Pose>> try_motion(PoseMethod m, const PoseTriple<Pose>& k, std::string* why = nullptr) {
  try {
    return Motion<Pose>(m, listed(k));
  } catch (const std::exception& e) {
    if (why != nullptr) *why = e.what();
    return std::nullopt;
  }
}

template <class Pose>
bool is_finite(const Pose& P) {
  return P.L.allFinite() && P.b.allFinite();
}

// The frame at t, or nullopt when a power it needs is not real (a refusal)
// or it is not finite.
template <class Pose>
std::optional<Pose> frame(const Motion<Pose>& D, double t) {
  try {
    const Pose P = D.at(t);
    if (is_finite(P)) return P;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

// Times in [a, c]: 17 uniform ones and the middle knot.
template <class Pose>
std::vector<double> sample_times(const PoseTriple<Pose>& k) {
  std::vector<double> ts;
  const double lo = k[0].t, hi = k[2].t;
  for (int i = 0; i <= 16; ++i) ts.push_back(lo + (hi - lo) * i / 16.0);
  ts.push_back(k[1].t);
  return ts;
}

// The frames at the sample times, or nullopt if one does not exist.
template <class Pose>
std::optional<std::vector<Pose>> sampled(const Motion<Pose>& D, const PoseTriple<Pose>& k) {
  std::vector<Pose> out;
  for (double t : sample_times(k)) {
    const std::optional<Pose> P = frame(D, t);
    if (!P) return std::nullopt;
    out.push_back(*P);
  }
  return out;
}

// The unit of distances: the triple's extent, or the motion's own reach from
// B's centre when its frames go further (rounding grows with them).
template <class Pose>
double motion_scale(const std::vector<Pose>& frames, const PoseTriple<Pose>& k) {
  const Vec<Pose> centre = pose_centre(k[1].pose);
  double scale = pose_extent(k);
  for (const Pose& P : frames) scale = std::max(scale, pose_reach(P, centre));
  return scale;
}

PoseProbe not_measured(const std::string& why) {
  PoseProbe p;
  p.value = kNaN;
  p.note = why;
  return p;
}

template <class Pose>
PoseTriple<Pose> mapped(const PoseTriple<Pose>& k, const std::function<Pose(const Pose&)>& f) {
  return {{{k[0].t, f(k[0].pose)}, {k[1].t, f(k[1].pose)}, {k[2].t, f(k[2].pose)}}};
}

template <class Pose>
PoseProbe probe_exists(PoseMethod m, const PoseTriple<Pose>& k) {
  PoseProbe p;
  p.relation = "the motion is built and every frame at 33 times in [a, c] is a real, finite pose";
  std::string why;
  const auto D = try_motion(m, k, &why);
  if (!D) {
    p.value = 1.0, p.note = why;
    return p;
  }
  for (int i = 0; i <= 32; ++i) {
    const double t = k[0].t + (k[2].t - k[0].t) * i / 32.0;
    try {
      if (!is_finite(D->at(t))) {
        p.value = 1.0, p.t = t, p.note = "a frame is not finite";
        return p;
      }
    } catch (const std::exception& e) {
      p.value = 1.0, p.t = t, p.note = e.what();
      return p;
    }
  }
  return p;
}

template <class Pose>
PoseProbe probe_interpolates(PoseMethod m, const PoseTriple<Pose>& k) {
  const auto D = try_motion(m, k);
  if (!D) return not_measured("no motion");
  PoseProbe p;
  p.relation = "D(a) = A, D(b) = B, D(c) = C";
  const double ext = pose_extent(k);
  for (const TimedPoseOf<Pose>& key : k) {
    const std::optional<Pose> P = frame(*D, key.t);
    if (!P) return not_measured("no frame at a knot");
    const double d = pose_distance(*P, key.pose) / ext;
    if (!(d <= p.value)) p.value = d, p.t = key.t;
  }
  return p;
}

// max over the sample times of |expect(X(t)) - Y(y_time(t))| / scale, or
// nullopt where a frame of either motion does not exist.
template <class Pose>
std::optional<std::pair<double, double>> compare(const Motion<Pose>& X, const Motion<Pose>& Y,
                                                 const PoseTriple<Pose>& k, double scale,
                                                 const std::function<Pose(const Pose&)>& expect,
                                                 const std::function<double(double)>& y_time) {
  double worst = -1.0, at = kNaN;
  for (double t : sample_times(k)) {
    const std::optional<Pose> x = frame(X, t), y = frame(Y, y_time(t));
    if (!x || !y) return std::nullopt;
    const double d = pose_distance(expect(*x), *y) / scale;
    if (!(d <= worst)) worst = d, at = t;
  }
  return std::pair{worst, at};
}

template <class Pose>
PoseProbe probe_symmetric(PoseMethod m, const PoseTriple<Pose>& k) {
  const double a = k[0].t, c = k[2].t;
  const PoseTriple<Pose> r{{{a, k[2].pose}, {a + c - k[1].t, k[1].pose}, {c, k[0].pose}}};
  const auto D = try_motion(m, k), R = try_motion(m, r);
  if (!D || !R) return not_measured("no motion");
  const auto frames = sampled(*D, k);
  if (!frames) return not_measured("a frame does not exist");
  const auto w = compare<Pose>(
      *D, *R, k, motion_scale(*frames, k), [](const Pose& P) { return P; }, [&](double t) { return a + c - t; });
  if (!w) return not_measured("a frame of the reversed motion does not exist");
  return {w->first, 1.0, w->second, "frame of the original at t = frame of the reversed triple at a + c - t", {}, ""};
}

template <class Pose>
std::vector<std::pair<std::string, double>> matrix_parameters(const std::string& name, const Pose& G) {
  std::vector<std::pair<std::string, double>> out;
  for (int i = 0; i < G.L.rows(); ++i) {
    for (int j = 0; j < G.L.cols(); ++j)
      out.emplace_back(name + ".L" + std::to_string(i) + std::to_string(j), G.L(i, j));
  }
  for (int i = 0; i < G.b.size(); ++i) out.emplace_back(name + ".b" + std::to_string(i), G.b[i]);
  return out;
}

// Left (G o X: a change of the world's frame) or right (X o H: a change of
// handle) invariance, G and H random affinities with det > 0.
template <class Pose>
PoseProbe probe_affine(PoseMethod m, const PoseTriple<Pose>& k, AuditRandom& r, bool left) {
  const Pose G = left ? random_affinity<Pose>(r, std::numbers::pi, 1.0, 10.0)
                      : random_affinity<Pose>(r, std::numbers::pi, 0.5, 1.0);
  const auto move = [&](const Pose& X) { return left ? compose(G, X) : compose(X, G); };
  const PoseTriple<Pose> kg = mapped<Pose>(k, move);
  const auto D = try_motion(m, k), DG = try_motion(m, kg);
  if (!D || !DG) return not_measured("no motion");
  const auto frames = sampled(*DG, kg);
  if (!frames) return not_measured("a frame does not exist");
  const auto w = compare<Pose>(*D, *DG, k, motion_scale(*frames, kg), move, [](double t) { return t; });
  if (!w) return not_measured("a frame does not exist");
  return {w->first,
          1.0,
          w->second,
          left ? "frames of the triple G o X = G o frames of the original, at the same t"
               : "frames of the triple X o H = frames of the original o H, at the same t",
          matrix_parameters(left ? "G" : "H", G),
          ""};
}

// The distance from X to the curve of poses D([lo, hi]): dense samples, then
// golden-section search around the nearest one; nullopt where a frame does
// not exist.
template <class Pose>
std::optional<double> distance_to_curve(const Motion<Pose>& D, const std::vector<Pose>& samples, double lo, double hi,
                                        const Pose& X) {
  const int n = static_cast<int>(samples.size()) - 1;
  int best = 0;
  for (int i = 1; i <= n; ++i) {
    if (pose_distance(samples[i], X) < pose_distance(samples[best], X)) best = i;
  }
  const double step = (hi - lo) / n;
  double l = lo + step * std::max(best - 1, 0), r = lo + step * std::min(best + 1, n);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  const auto f = [&](double t) -> std::optional<double> {
    const std::optional<Pose> P = frame(D, t);
    if (!P) return std::nullopt;
    return pose_distance(*P, X);
  };
  double m1 = r - g * (r - l), m2 = l + g * (r - l);
  std::optional<double> f1 = f(m1), f2 = f(m2);
  for (int it = 0; it < 40 && f1 && f2; ++it) {
    if (*f1 < *f2) {
      r = m2, m2 = m1, f2 = f1, m1 = r - g * (r - l), f1 = f(m1);
    } else {
      l = m1, m1 = m2, f1 = f2, m2 = l + g * (r - l), f2 = f(m2);
    }
  }
  if (!f1 || !f2) return std::nullopt;
  return std::min({*f1, *f2, pose_distance(samples[best], X)});
}

template <class Pose>
PoseProbe probe_knots(PoseMethod m, const PoseTriple<Pose>& k) {
  const double a = k[0].t, c = k[2].t, span = c - a, beta = (k[1].t - a) / span;
  PoseTriple<Pose> moved = k;
  moved[1].t = a + span * (beta < 0.5 ? beta + 0.2 : beta - 0.2);
  const auto D = try_motion(m, k), M = try_motion(m, moved);
  if (!D || !M) return not_measured("no motion");
  std::vector<Pose> samples;
  for (int i = 0; i <= 200; ++i) {
    const std::optional<Pose> P = frame(*D, a + span * i / 200.0);
    if (!P) return not_measured("a frame does not exist");
    samples.push_back(*P);
  }
  PoseProbe p;
  p.value = -1.0;
  for (int i = 1; i < 10; ++i) {
    const double t = a + span * i / 10.0;
    const std::optional<Pose> X = frame(*M, t);
    if (!X) return not_measured("a frame with the moved knot does not exist");
    const std::optional<double> d = distance_to_curve(*D, samples, a, c, *X);
    if (!d) return not_measured("a frame does not exist");
    if (*d / pose_extent(k) > p.value) p.value = *d / pose_extent(k), p.t = t;
  }
  p.relation = "the poses of the triple with b moved by 0.2 of the span lie on the curve of poses of the original";
  p.parameters = {{"knot ratio", beta}, {"moved knot ratio", (moved[1].t - a) / span}};
  return p;
}

// The velocity in the moving frame, w = L^-1 (L' p + b') per unit of
// u = (t - a)/(c - a), at the vertices of the reference simplex.
template <class Pose>
std::optional<std::vector<Vec<Pose>>> relative_velocities(const Motion<Pose>& D, const PoseTriple<Pose>& k, double u) {
  const double span = k[2].t - k[0].t, t = k[0].t + u * span;
  try {
    const Pose P = D.at(t), V = D.velocity(t);
    const typename Pose::Linear inverse = P.L.inverse();
    std::vector<Vec<Pose>> out;
    Vec<Pose> v = Vec<Pose>::Zero();
    out.push_back(Vec<Pose>(inverse * V.b * span));
    for (int i = 0; i < v.size(); ++i) out.push_back(Vec<Pose>(inverse * (V.L.col(i) + V.b) * span));
    for (const Vec<Pose>& w : out) {
      if (!w.allFinite()) return std::nullopt;
    }
    return out;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// ARA (SAM Sec. 2.4) over [a, c] at 16 times u = (i + 1/2)/16: the mean of
// |dw/du| over the simplex's vertices. dw/du is the smaller of the two
// one-sided differences, so that a knot within the step (where a polySAM's
// w jumps from one SAM to the next) is not read as an acceleration.
template <class Pose>
PoseProbe probe_steady(PoseMethod m, const PoseTriple<Pose>& k) {
  const auto D = try_motion(m, k);
  if (!D) return not_measured("no motion");
  constexpr int kTimes = 16;
  constexpr double kStep = 1e-5;
  double acceleration = 0.0, speed = 0.0;
  int count = 0;
  for (int i = 0; i < kTimes; ++i) {
    const double u = (i + 0.5) / kTimes;
    const auto before = relative_velocities(*D, k, u - kStep), now = relative_velocities(*D, k, u),
               after = relative_velocities(*D, k, u + kStep);
    if (!before || !now || !after) return not_measured("a frame does not exist");
    for (std::size_t j = 0; j < now->size(); ++j) {
      const double back = ((*now)[j] - (*before)[j]).norm() / kStep, ahead = ((*after)[j] - (*now)[j]).norm() / kStep;
      acceleration += std::min(back, ahead);
      speed += (*now)[j].norm();
      ++count;
    }
  }
  PoseProbe p;
  p.value = acceleration / count;
  p.scale = std::max(1.0, speed / count);
  p.relation = "the velocity in the moving frame, w = L^-1 (L' p + b'), is constant over [a, c] (a SAM)";
  p.parameters = {{"ARA", p.value}, {"mean |w|", speed / count}};
  return p;
}

}  // namespace pose_probes

std::span<const PosePropertyInfo> all_pose_properties() { return pose_probes::kPoseProperties; }

const PosePropertyInfo& info(PoseProperty property) {
  for (const PosePropertyInfo& p : pose_probes::kPoseProperties) {
    if (p.property == property) return p;
  }
  throw std::logic_error("pose property missing from the table");
}

const PosePropertyInfo* find_pose_property(std::string_view id) {
  for (const PosePropertyInfo& p : pose_probes::kPoseProperties) {
    if (p.id == id) return &p;
  }
  return nullptr;
}

template <class Pose>
PoseProbe probe_pose(PoseProperty property, PoseMethod method, const PoseTriple<Pose>& poses, std::uint64_t seed) {
  using namespace pose_probes;
  AuditRandom r(seed);
  switch (property) {
    case PoseProperty::exists:
      return probe_exists(method, poses);
    case PoseProperty::interpolates:
      return probe_interpolates(method, poses);
    case PoseProperty::symmetric:
      return probe_symmetric(method, poses);
    case PoseProperty::left_affine_invariant:
      return probe_affine(method, poses, r, true);
    case PoseProperty::right_affine_invariant:
      return probe_affine(method, poses, r, false);
    case PoseProperty::knot_controlled:
      return probe_knots(method, poses);
    case PoseProperty::steady:
      return probe_steady(method, poses);
  }
  throw std::logic_error("unknown pose property");
}

template PoseProbe probe_pose(PoseProperty, PoseMethod, const PoseTriple<Affine2>&, std::uint64_t);
template PoseProbe probe_pose(PoseProperty, PoseMethod, const PoseTriple<Affine3>&, std::uint64_t);

}  // namespace pita::analysis
