#include "core/pose_motion.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace pita {

namespace {

constexpr std::array<PoseMethodInfo, 10> kPoseMethods = {{
    {PoseMethod::sam, "SAM", "Steady Affine Morph", 2, 2},
    {PoseMethod::poly_sam, "polySAM", "polySAM (a SAM per span)", 2, 1000},
    {PoseMethod::bezier_sam, "bezier-SAM", "Bezier SAM", 3, 4},
    {PoseMethod::biarc_sam, "biarc-SAM", "SAM bi-arc retrofit", 3, 3},
    {PoseMethod::linear, "linear", "linear interpolation of the matrices", 2, 1000},
    {PoseMethod::four_point, "four-point-SAM", "polySAM of the four-point subdivision", 3, 1000},
    {PoseMethod::rarap, "rARAP", "ARAP with the barycentre moved on a line (Fig. 2b)", 2, 2},
    {PoseMethod::asap, "ASAP", "log spiral with a linear residue (Fig. 2c)", 2, 2},
    {PoseMethod::tsb, "TSB", "blend of the triangle sides' log spirals (Fig. 2d)", 2, 2},
    {PoseMethod::alexa, "Alexa", "Alexa's log-matrix blend e^((1-u) log B + u log C) (Figs. 4, 5)", 2, 2},
}};

// `steps` four-point subdivisions of timed poses, each new pose at the middle
// time of its span.
std::vector<TimedPose> subdivided(std::vector<TimedPose> poses, int steps) {
  for (int step = 0; step < steps; ++step) {
    std::vector<Affine2> affinities;
    for (const TimedPose& p : poses) affinities.push_back(p.pose);
    const std::vector<Affine2> finer = subdivide_four_point(affinities);
    std::vector<TimedPose> next(finer.size());
    for (std::size_t i = 0; i < finer.size(); ++i) {
      const double t = i % 2 == 0 ? poses[i / 2].t : 0.5 * (poses[i / 2].t + poses[i / 2 + 1].t);
      next[i] = {t, finer[i]};
    }
    poses = std::move(next);
  }
  return poses;
}

Affine2 linear_mix(const Affine2& A, const Affine2& B, double u) {
  return {(1.0 - u) * A.L + u * B.L, (1.0 - u) * A.b + u * B.b};
}

bool is_fig2_morph(PoseMethod method) {
  return method == PoseMethod::rarap || method == PoseMethod::asap || method == PoseMethod::tsb;
}

}  // namespace

std::array<Point, 3> default_reference_triangle() { return {Point{0.0, 0.0}, Point{1.0, 0.0}, Point{0.0, 1.0}}; }

std::span<const PoseMethodInfo> all_pose_methods() { return kPoseMethods; }

const PoseMethodInfo& info(PoseMethod method) {
  for (const PoseMethodInfo& entry : kPoseMethods) {
    if (entry.method == method) return entry;
  }
  return kPoseMethods[0];
}

PoseMotion::PoseMotion(PoseMethod method, std::vector<TimedPose> poses, int subdivisions,
                       const std::array<Point, 3>& reference)
    : method_(method), poses_(std::move(poses)) {
  const PoseMethodInfo& about = info(method);
  if (poses_.size() < static_cast<std::size_t>(about.min_poses) ||
      poses_.size() > static_cast<std::size_t>(about.max_poses)) {
    throw std::invalid_argument(std::string(about.id) + ": wrong number of poses");
  }
  for (std::size_t i = 0; i + 1 < poses_.size(); ++i) {
    if (!(poses_[i].t < poses_[i + 1].t)) throw std::invalid_argument("knots must increase");
  }
  span_poses_ = poses_;
  if (method == PoseMethod::four_point) {
    if (subdivisions < 0 || subdivisions > kMaxSubdivisions) {
      throw std::invalid_argument("four-point-SAM: subdivisions out of range");
    }
    // Each step needs the SAMs between the poses of the step before.
    for (int step = 0; step < subdivisions; ++step) {
      try {
        span_poses_ = subdivided(std::move(span_poses_), 1);
      } catch (const NoRealLogarithm& error) {
        throw NoSamBetweenPoses(error, 0,
                                "between poses made by subdivision step " + std::to_string(step + 1) +
                                    " of the four-point scheme (Sec. 7.3); at most " +
                                    std::to_string(step) + " \"subdivisions\" work here");
      }
    }
    for (std::size_t i = 0; i + 1 < span_poses_.size(); ++i) {
      if (!(span_poses_[i].t < span_poses_[i + 1].t)) {
        throw std::invalid_argument(
            "four-point-SAM: two knots are too close for " + std::to_string(subdivisions) +
            " subdivisions (the middle time of a span rounds onto a knot near t = " +
            std::to_string(span_poses_[i].t) + ")");
      }
    }
  }
  if (method == PoseMethod::alexa) {
    try {
      morph_.emplace(LogMatrixBlend(poses_[0].pose, poses_[1].pose));
    } catch (const NoRealLogarithm& error) {
      throw NoSamBetweenPoses(error, 0);
    }
    return;
  }
  if (is_fig2_morph(method)) {
    const Affine2& from = poses_[0].pose;
    const Affine2& to = poses_[1].pose;
    const Point centre = (reference[0] + reference[1] + reference[2]) / 3.0;
    const Eigen::Vector2d c(centre.real(), centre.imag());
    // All three need C o B^-1 to preserve orientation (ARAP interpolates no
    // reflection; TSB's triangle would flatten on the way).
    const double det = compose(to, inverse(from)).L.determinant();
    if (!(det > 0.0)) {
      char reason[200];
      std::snprintf(reason, sizeof reason,
                    "%s: one pose is mirrored and the other is not (C o B^-1 has determinant %g <= 0); "
                    "the morph interpolates no reflection: mirror both poses or neither",
                    std::string(about.id).c_str(), det);
      throw std::invalid_argument(reason);
    }
    if (method == PoseMethod::rarap) morph_.emplace(RarapMorph(from, to, c));
    if (method == PoseMethod::asap) morph_.emplace(SpiralResidueMorph(from, to, c));
    if (method == PoseMethod::tsb) morph_.emplace(TriangleSpiralBlend(from, to, reference));
    return;
  }
  // Every SAM between consecutive poses, named by its pair when it fails.
  if (method != PoseMethod::linear) {
    for (std::size_t i = 0; i + 1 < span_poses_.size(); ++i) {
      try {
        spans_.emplace_back(span_poses_[i].pose, span_poses_[i + 1].pose);
      } catch (const NoRealLogarithm& error) {
        if (method == PoseMethod::four_point) {
          throw NoSamBetweenPoses(error, 0,
                                  "between subdivided poses at t = " + std::to_string(span_poses_[i].t) +
                                      " and " + std::to_string(span_poses_[i + 1].t));
        }
        throw NoSamBetweenPoses(error, i);
      }
    }
  }
  if (method == PoseMethod::biarc_sam) {
    try {
      biarc_.emplace(poses_[0].pose, poses_[1].pose, poses_[2].pose);
    } catch (const NoRealLogarithm& error) {
      throw NoSamBetweenPoses(error, 0, "between the control poses of the bi-arc (Sec. 5.3)");
    }
  }
  if (method == PoseMethod::bezier_sam || method == PoseMethod::biarc_sam) {
    // The SAMs between intermediate poses are found only by evaluating.
    for (int i = 0; i <= 64; ++i) {
      const double u = i / 64.0;
      const double t = poses_.front().t + u * (poses_.back().t - poses_.front().t);
      try {
        (void)evaluate(t);
      } catch (const NoRealLogarithm& error) {
        char where[96];
        std::snprintf(where, sizeof where, "between intermediate poses of the construction at t = %g",
                      t);
        throw NoSamBetweenPoses(error, 0, where);
      }
    }
  }
}

double PoseMotion::bezier_parameter(double t) const {
  const double u = (t - poses_.front().t) / (poses_.back().t - poses_.front().t);
  return std::clamp(u, 0.0, 1.0);
}

Affine2 PoseMotion::evaluate(double t) const {
  switch (method_) {
    case PoseMethod::sam:
    case PoseMethod::poly_sam:
    case PoseMethod::four_point:
    case PoseMethod::linear: {
      // The span holding t; the first and last extrapolate.
      const std::size_t i = span_of(t);
      const TimedPose& from = span_poses_[i];
      const TimedPose& to = span_poses_[i + 1];
      if (t == from.t) return from.pose;
      if (t == to.t) return to.pose;
      const double u = (t - from.t) / (to.t - from.t);
      if (method_ == PoseMethod::linear) return linear_mix(from.pose, to.pose, u);
      return spans_[i].at(u);
    }
    case PoseMethod::bezier_sam: {
      const double u = bezier_parameter(t);
      if (poses_.size() == 3) return bezier_sam(poses_[0].pose, poses_[1].pose, poses_[2].pose, u);
      return bezier_sam(poses_[0].pose, poses_[1].pose, poses_[2].pose, poses_[3].pose, u);
    }
    case PoseMethod::biarc_sam: {
      const double a = poses_[0].t, b = poses_[1].t, c = poses_[2].t;
      const double tc = std::clamp(t, a, c);
      const double u = tc <= b ? 0.5 * (tc - a) / (b - a) : 0.5 + 0.5 * (tc - b) / (c - b);
      if (tc == b) return poses_[1].pose;
      return biarc_->at(u);
    }
    case PoseMethod::rarap:
    case PoseMethod::asap:
    case PoseMethod::tsb:
    case PoseMethod::alexa: {
      if (t == poses_[0].t) return poses_[0].pose;
      if (t == poses_[1].t) return poses_[1].pose;
      const double u = (t - poses_[0].t) / (poses_[1].t - poses_[0].t);
      return std::visit([u](const auto& morph) { return morph.at(u); }, *morph_);
    }
  }
  return poses_.front().pose;
}

Affine2 PoseMotion::at(double t) const { return evaluate(t); }

std::size_t PoseMotion::span_of(double t) const {
  // The last span whose start is <= t (the first when none is).
  const auto after = std::upper_bound(span_poses_.begin() + 1, span_poses_.end() - 1, t,
                                      [](double x, const TimedPose& p) { return x < p.t; });
  return static_cast<std::size_t>(after - (span_poses_.begin() + 1));
}

Affine2 PoseMotion::velocity(double t) const {
  const double first = poses_.front().t, last = poses_.back().t;
  switch (method_) {
    case PoseMethod::sam:
    case PoseMethod::poly_sam:
    case PoseMethod::four_point: {
      const std::size_t i = span_of(t);
      const double duration = span_poses_[i + 1].t - span_poses_[i].t;
      const Affine2 rate = spans_[i].velocity((t - span_poses_[i].t) / duration);
      return {rate.L / duration, rate.b / duration};
    }
    case PoseMethod::linear: {
      const std::size_t i = span_of(t);
      const double duration = span_poses_[i + 1].t - span_poses_[i].t;
      const Affine2& A = span_poses_[i].pose;
      const Affine2& B = span_poses_[i + 1].pose;
      return {(B.L - A.L) / duration, (B.b - A.b) / duration};
    }
    case PoseMethod::rarap:
    case PoseMethod::asap:
    case PoseMethod::tsb:
    case PoseMethod::alexa: {
      const double duration = poses_[1].t - poses_[0].t;
      const double u = (t - poses_[0].t) / duration;
      const Affine2 rate = std::visit([u](const auto& morph) { return morph.velocity(u); }, *morph_);
      return {rate.L / duration, rate.b / duration};
    }
    case PoseMethod::bezier_sam:
    case PoseMethod::biarc_sam: {
      const double h = 1e-3 * (last - first);
      const auto difference = [](const Affine2& A, const Affine2& B, double weight) {
        return Affine2{(A.L - B.L) * weight, (A.b - B.b) * weight};
      };
      const auto plus = [](const Affine2& A, const Affine2& B) { return Affine2{A.L + B.L, A.b + B.b}; };
      if (t - 2.0 * h < first || t + 2.0 * h > last) {
        // One-sided, second order: (-3 f(t) + 4 f(t + s) - f(t + 2s)) / (2 s).
        const double s = (t - 2.0 * h < first) ? h : -h;
        const Affine2 f0 = evaluate(t), f1 = evaluate(t + s), f2 = evaluate(t + 2.0 * s);
        return plus(difference(f1, f0, 4.0 / (2.0 * s)), difference(f0, f2, 1.0 / (2.0 * s)));
      }
      // (f(t - 2h) - 8 f(t - h) + 8 f(t + h) - f(t + 2h)) / (12 h).
      const Affine2 m2 = evaluate(t - 2.0 * h), m1 = evaluate(t - h), p1 = evaluate(t + h),
                    p2 = evaluate(t + 2.0 * h);
      return plus(difference(p1, m1, 8.0 / (12.0 * h)), difference(m2, p2, 1.0 / (12.0 * h)));
    }
  }
  return {};
}

}  // namespace pita
