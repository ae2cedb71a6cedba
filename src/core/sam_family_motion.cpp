#include "core/sam_family_motion.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "core/limits.hpp"

namespace pita {

namespace {

// `steps` four-point subdivisions of timed poses, each new pose at the middle
// time of its span.
template <class Pose>
std::vector<TimedPoseOf<Pose>> subdivided(std::vector<TimedPoseOf<Pose>> poses, int steps) {
  for (int step = 0; step < steps; ++step) {
    std::vector<Pose> affinities;
    for (const TimedPoseOf<Pose>& p : poses) affinities.push_back(p.pose);
    const std::vector<Pose> finer = subdivide_four_point(affinities);
    std::vector<TimedPoseOf<Pose>> next(finer.size());
    for (std::size_t i = 0; i < finer.size(); ++i) {
      const double t = i % 2 == 0 ? poses[i / 2].t : 0.5 * (poses[i / 2].t + poses[i / 2 + 1].t);
      next[i] = {t, finer[i]};
    }
    poses = std::move(next);
  }
  return poses;
}

template <class Pose>
Pose linear_mix(const Pose& A, const Pose& B, double u) {
  return {(1.0 - u) * A.L + u * B.L, (1.0 - u) * A.b + u * B.b};
}

}  // namespace

template <class Pose>
void check_poses(PoseMethod method, const std::vector<TimedPoseOf<Pose>>& poses) {
  const PoseMethodInfo& about = info(method);
  if (poses.size() < static_cast<std::size_t>(about.min_poses) ||
      poses.size() > static_cast<std::size_t>(about.max_poses)) {
    throw std::invalid_argument(std::string(about.id) + ": wrong number of poses");
  }
  for (std::size_t i = 0; i + 1 < poses.size(); ++i) {
    if (!(poses[i].t < poses[i + 1].t)) throw std::invalid_argument("knots must increase");
  }
}

template <class Pose>
SamFamilyMotion<Pose>::SamFamilyMotion(PoseMethod method, std::vector<Timed> poses, int subdivisions)
    : method_(method), poses_(std::move(poses)) {
  if (!info(method).in_space) {
    throw std::invalid_argument(std::string(info(method).id) + " is not a method of the SAM family");
  }
  check_poses(method, poses_);
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
                                    " of the four-point scheme (Sec. 7.3); at most " + std::to_string(step) +
                                    " \"subdivisions\" work here");
      }
    }
    for (std::size_t i = 0; i + 1 < span_poses_.size(); ++i) {
      if (!(span_poses_[i].t < span_poses_[i + 1].t)) {
        throw std::invalid_argument("four-point-SAM: two knots are too close for " + std::to_string(subdivisions) +
                                    " subdivisions (the middle time of a span rounds onto a knot near t = " +
                                    std::to_string(span_poses_[i].t) + ")");
      }
    }
  }
  // Every SAM between consecutive poses, named by its pair when it fails
  // (the pose PITAs build and name their own).
  if (method != PoseMethod::linear && !is_pose_pita(method)) {
    for (std::size_t i = 0; i + 1 < span_poses_.size(); ++i) {
      try {
        spans_.emplace_back(span_poses_[i].pose, span_poses_[i + 1].pose);
      } catch (const NoRealLogarithm& error) {
        if (method == PoseMethod::four_point) {
          throw NoSamBetweenPoses(error, 0,
                                  "between subdivided poses at t = " + std::to_string(span_poses_[i].t) + " and " +
                                      std::to_string(span_poses_[i + 1].t));
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
  if (is_pose_pita(method)) pitas_.emplace(method, poses_);
  if (method == PoseMethod::bezier_sam || method == PoseMethod::biarc_sam) {
    // The SAMs between intermediate poses are found only by evaluating.
    for (int i = 0; i <= 64; ++i) {
      const double u = i / 64.0;
      const double t = poses_.front().t + u * (poses_.back().t - poses_.front().t);
      try {
        (void)at(t);
      } catch (const NoRealLogarithm& error) {
        char where[96];
        std::snprintf(where, sizeof where, "between intermediate poses of the construction at t = %g", t);
        throw NoSamBetweenPoses(error, 0, where);
      }
    }
  }
}

template <class Pose>
double SamFamilyMotion<Pose>::bezier_parameter(double t) const {
  const double u = (t - poses_.front().t) / (poses_.back().t - poses_.front().t);
  return std::clamp(u, 0.0, 1.0);
}

template <class Pose>
Pose SamFamilyMotion<Pose>::at(double t) const {
  // The span holding t, the first and last extrapolating, exact at its ends;
  // `mix` (span, parameter u in [0, 1]) is the method's pose within it.
  const auto in_span = [&](const auto& mix) -> Pose {
    const std::size_t i = span_of(t);
    const Timed& from = span_poses_[i];
    const Timed& to = span_poses_[i + 1];
    if (t == from.t) return from.pose;
    if (t == to.t) return to.pose;
    return mix(i, (t - from.t) / (to.t - from.t));
  };
  switch (method_) {
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
    case PoseMethod::sam:
    case PoseMethod::poly_sam:
    case PoseMethod::four_point:
      return in_span([&](std::size_t i, double u) { return spans_[i].at(u); });
    case PoseMethod::linear:
      return in_span(
          [&](std::size_t i, double u) { return linear_mix(span_poses_[i].pose, span_poses_[i + 1].pose, u); });
    case PoseMethod::p4:
    case PoseMethod::p5:
    case PoseMethod::p6:
    case PoseMethod::p9:
      for (const Timed& key : poses_) {
        if (t == key.t) return key.pose;  // exactly the pose at its knot
      }
      return pitas_->at(t);
    case PoseMethod::rarap:  // the plane's morphs of Fig. 2: PoseMotion; the constructor refuses them
    case PoseMethod::asap:
    case PoseMethod::tsb:
    case PoseMethod::alexa:
      break;
  }
  throw std::invalid_argument(std::string("method ") + std::string(info(method_).id) + " is not of the SAM family");
}

template <class Pose>
std::size_t SamFamilyMotion<Pose>::span_of(double t) const {
  // The last span whose start is <= t (the first when none is).
  const auto after = std::upper_bound(span_poses_.begin() + 1, span_poses_.end() - 1, t,
                                      [](double x, const Timed& p) { return x < p.t; });
  return static_cast<std::size_t>(after - (span_poses_.begin() + 1));
}

template <class Pose>
Pose SamFamilyMotion<Pose>::velocity(double t) const {
  const double first = poses_.front().t, last = poses_.back().t;
  switch (method_) {
    case PoseMethod::linear: {
      const std::size_t i = span_of(t);
      const double duration = span_poses_[i + 1].t - span_poses_[i].t;
      const Pose& A = span_poses_[i].pose;
      const Pose& B = span_poses_[i + 1].pose;
      return {(B.L - A.L) / duration, (B.b - A.b) / duration};
    }
    case PoseMethod::bezier_sam:
    case PoseMethod::biarc_sam:
    case PoseMethod::p4:
    case PoseMethod::p5:
    case PoseMethod::p6:
    case PoseMethod::p9: {
      const double h = limits::kPoseVelocityStep * (last - first);
      const auto difference = [](const Pose& A, const Pose& B, double weight) {
        return Pose{(A.L - B.L) * weight, (A.b - B.b) * weight};
      };
      const auto plus = [](const Pose& A, const Pose& B) { return Pose{A.L + B.L, A.b + B.b}; };
      if (t - 2.0 * h < first || t + 2.0 * h > last) {
        // One-sided, second order: (-3 f(t) + 4 f(t + s) - f(t + 2s)) / (2 s).
        const double s = (t - 2.0 * h < first) ? h : -h;
        const Pose f0 = at(t), f1 = at(t + s), f2 = at(t + 2.0 * s);
        return plus(difference(f1, f0, 4.0 / (2.0 * s)), difference(f0, f2, 1.0 / (2.0 * s)));
      }
      // (f(t - 2h) - 8 f(t - h) + 8 f(t + h) - f(t + 2h)) / (12 h).
      const Pose m2 = at(t - 2.0 * h), m1 = at(t - h), p1 = at(t + h), p2 = at(t + 2.0 * h);
      return plus(difference(p1, m1, 8.0 / (12.0 * h)), difference(m2, p2, 1.0 / (12.0 * h)));
    }
    case PoseMethod::sam:
    case PoseMethod::poly_sam:
    case PoseMethod::four_point: {
      // Exact: (log A_span) A(t) / span duration.
      const std::size_t i = span_of(t);
      const double duration = span_poses_[i + 1].t - span_poses_[i].t;
      const Pose rate = spans_[i].velocity((t - span_poses_[i].t) / duration);
      return {rate.L / duration, rate.b / duration};
    }
    case PoseMethod::rarap:  // not of the SAM family (see at())
    case PoseMethod::asap:
    case PoseMethod::tsb:
    case PoseMethod::alexa:
      break;
  }
  throw std::invalid_argument(std::string("method ") + std::string(info(method_).id) + " is not of the SAM family");
}

template void check_poses(PoseMethod, const std::vector<TimedPoseOf<Affine2>>&);
template void check_poses(PoseMethod, const std::vector<TimedPoseOf<Affine3>>&);
template class SamFamilyMotion<Affine2>;
template class SamFamilyMotion<Affine3>;

}  // namespace pita
