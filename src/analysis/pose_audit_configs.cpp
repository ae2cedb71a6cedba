#include "analysis/pose_audit_configs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace pita::analysis {

namespace pose_triples {

constexpr double kTurn = std::numbers::pi;

template <class Pose>
using Linear = typename Pose::Linear;
template <class Pose>
using Vec = typename Pose::Vector;

// A rotation by `angle`: of the plane, or of space about `axis`.
template <class Pose>
Linear<Pose> rotation(double angle, const Eigen::Vector3d& axis) {
  if constexpr (in_space_v<Pose>) {
    return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  } else {
    (void)axis;
    return Eigen::Rotation2Dd(angle).toRotationMatrix();
  }
}

template <class Pose>
Eigen::Vector3d random_axis(AuditRandom& r) {
  Eigen::Vector3d axis;
  do {
    axis = {r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
  } while (axis.norm() < 0.1 || axis.norm() > 1.0);
  return axis;
}

template <class Pose>
Vec<Pose> random_vector(AuditRandom& r, double half) {
  Vec<Pose> v;
  for (int i = 0; i < v.size(); ++i) v[i] = r.uniform(-half, half);
  return v;
}

template <class Pose>
Pose pose_of(const Linear<Pose>& L, const Vec<Pose>& b) {
  Pose P;
  P.L = L;
  P.b = b;
  return P;
}

template <class Pose>
PoseTriple<Pose> timed(double a, double b, double c, const Pose& A, const Pose& B, const Pose& C) {
  return {{{a, A}, {b, B}, {c, C}}};
}

// Knots a < b < c: a in [-2, 2], a span e^(+-1), b at the middle or, half
// the time, anywhere in [0.2, 0.8] of the span.
template <class Pose>
PoseTriple<Pose> random_knots(AuditRandom& r, const Pose& A, const Pose& B, const Pose& C) {
  const bool uneven = r.uniform(0.0, 1.0) < 0.5;
  const double a = r.uniform(-2.0, 2.0), span = std::exp(r.uniform(-1.0, 1.0));
  const double beta = uneven ? r.uniform(0.2, 0.8) : 0.5;
  return timed(a, a + beta * span, a + span, A, B, C);
}

// Tame: rotations within +-1 rad of the reference (neighbours turn by less
// than 2 < pi), log stretches within +-0.3, translations within +-3.
template <class Pose>
PoseTriple<Pose> tame(AuditRandom& r) {
  const Pose A = random_affinity<Pose>(r, 1.0, 0.3, 3.0), B = random_affinity<Pose>(r, 1.0, 0.3, 3.0),
             C = random_affinity<Pose>(r, 1.0, 0.3, 3.0);
  return random_knots(r, A, B, C);
}

// Wild: any rotation (neighbours may turn by more than pi: no SAM), log
// stretches within +-1.5 (singular value ratios up to e^6), translations
// within +-10.
template <class Pose>
PoseTriple<Pose> wild(AuditRandom& r) {
  const Pose A = random_affinity<Pose>(r, kTurn, 1.5, 10.0), B = random_affinity<Pose>(r, kTurn, 1.5, 10.0),
             C = random_affinity<Pose>(r, kTurn, 1.5, 10.0);
  return random_knots(r, A, B, C);
}

// The identity plus eps times a random matrix (entries within +-1).
template <class Pose>
Linear<Pose> near_identity(AuditRandom& r, double eps) {
  Linear<Pose> N;
  for (int i = 0; i < N.rows(); ++i) {
    for (int j = 0; j < N.cols(); ++j) N(i, j) = r.uniform(-1.0, 1.0);
  }
  return Linear<Pose>::Identity() + eps * N;
}

// Near-singular: a tame triple brought within 1e-7..1e-3 of a situation where
// a construction divides by a small number or a power is about to fail.
template <class Pose>
PoseTriple<Pose> near_singular(AuditRandom& r) {
  // Every draw in a statement of its own: the order of a call's arguments or
  // of an operator's operands is the compiler's, and the triples must be the
  // same whatever builds them.
  const double magnitude = std::exp(r.uniform(std::log(1e-7), std::log(1e-3)));
  const double eps = magnitude * r.sign();
  PoseTriple<Pose> k = tame<Pose>(r);
  Pose &A = k[0].pose, &B = k[1].pose, &C = k[2].pose;
  switch (static_cast<int>(r.uniform(0.0, 5.0))) {
    case 0:  // B almost A
    {
      const Vec<Pose> shift = random_vector<Pose>(r, 1.0);
      B = pose_of<Pose>(A.L * near_identity<Pose>(r, eps), A.b + eps * shift);
      break;
    }
    case 1:  // B turned from A by almost pi: the edge of the SAM's existence
    {
      const Vec<Pose> shift = random_vector<Pose>(r, 3.0);
      const auto axis = random_axis<Pose>(r);
      B = compose(pose_of<Pose>(rotation<Pose>(kTurn - std::abs(eps), axis), shift), A);
      break;
    }
    case 2: {  // B almost flat: a singular value in 1e-3..1e-1
      const double small = std::exp(r.uniform(std::log(1e-3), std::log(1e-1)));
      Linear<Pose> S = Linear<Pose>::Identity();
      S(0, 0) = small;
      const auto axis = random_axis<Pose>(r);
      const Linear<Pose> Q = rotation<Pose>(r.uniform(-kTurn, kTurn), axis);
      B.L = A.L * Q * S * Q.transpose();
      break;
    }
    case 3:  // almost translates of one another
      B.L = A.L * near_identity<Pose>(r, eps);
      C.L = A.L * near_identity<Pose>(r, eps);
      break;
    default:  // C almost B
    {
      const Vec<Pose> shift = random_vector<Pose>(r, 1.0);
      C = pose_of<Pose>(B.L * near_identity<Pose>(r, eps), B.b + eps * shift);
      break;
    }
  }
  return k;
}

template <class Pose>
PoseAuditConfig<Pose> crafted(std::string name, const PoseTriple<Pose>& poses) {
  return {0, ConfigMix::crafted, "crafted: " + std::move(name), poses};
}

// A linear part from the plane's 2x2 block (the identity elsewhere in space).
template <class Pose>
Linear<Pose> planar(double a, double b, double c, double d) {
  Linear<Pose> L = Linear<Pose>::Identity();
  L(0, 0) = a, L(0, 1) = b, L(1, 0) = c, L(1, 1) = d;
  return L;
}

template <class Pose>
Vec<Pose> vec(double x, double y) {
  Vec<Pose> v = Vec<Pose>::Zero();
  v[0] = x, v[1] = y;
  if constexpr (in_space_v<Pose>) v[2] = 0.5 * x - 0.25 * y;
  return v;
}

}  // namespace pose_triples

template <class Pose>
Pose random_affinity(AuditRandom& r, double turn, double stretch, double shift) {
  using namespace pose_triples;
  const auto r_axis = random_axis<Pose>(r);
  const Linear<Pose> R = rotation<Pose>(r.uniform(-turn, turn), r_axis);
  const auto q_axis = random_axis<Pose>(r);
  const Linear<Pose> Q = rotation<Pose>(r.uniform(-kTurn, kTurn), q_axis);
  Vec<Pose> logs;
  for (int i = 0; i < logs.size(); ++i) logs[i] = r.uniform(-stretch, stretch);
  const Linear<Pose> S = Q * logs.array().exp().matrix().asDiagonal() * Q.transpose();
  return pose_of<Pose>(R * S, random_vector<Pose>(r, shift));
}

template <class Pose>
std::vector<PoseAuditConfig<Pose>> crafted_pose_configs() {
  using namespace pose_triples;
  std::vector<PoseAuditConfig<Pose>> out;
  const Eigen::Vector3d axis{1.0, 2.0, 3.0};
  const Linear<Pose> L0 = rotation<Pose>(0.4, axis) * planar<Pose>(1.3, 0.2, 0.2, 0.8);
  // Translates: every relative motion a translation.
  out.push_back(
      crafted<Pose>("translates", timed(0.0, 0.5, 1.0, pose_of<Pose>(L0, vec<Pose>(0, 0)),
                                        pose_of<Pose>(L0, vec<Pose>(2, 1.5)), pose_of<Pose>(L0, vec<Pose>(4, 0)))));
  // Similarities turning about the origin by 1.5 rad between neighbours.
  out.push_back(crafted<Pose>("similarities about one point",
                              timed(0.0, 0.5, 1.0, pose_of<Pose>(rotation<Pose>(0.0, axis), vec<Pose>(0, 0)),
                                    pose_of<Pose>(1.2 * rotation<Pose>(1.5, axis), vec<Pose>(0, 0)),
                                    pose_of<Pose>(0.9 * rotation<Pose>(3.0, axis), vec<Pose>(0, 0)))));
  // Three poses on one SAM, B at its knot's place: every steady construction is that SAM.
  {
    const Pose A = pose_of<Pose>(L0, vec<Pose>(1, -1));
    const Pose C = pose_of<Pose>(rotation<Pose>(1.2, axis) * planar<Pose>(0.7, 0.4, -0.1, 1.6), vec<Pose>(3, 2));
    const Pose B = SteadyAffineMorph<Pose>(A, C).at(0.3);
    out.push_back(crafted<Pose>("three poses on one SAM, uneven knots", timed(0.0, 0.3, 1.0, A, B, C)));
  }
  // Stretches along the axes with the middle knot near the first.
  out.push_back(crafted<Pose>("stretches, uneven knots",
                              timed(0.0, 0.15, 1.0, pose_of<Pose>(planar<Pose>(1, 0, 0, 1), vec<Pose>(0, 0)),
                                    pose_of<Pose>(planar<Pose>(2, 0, 0, 0.5), vec<Pose>(1, 1)),
                                    pose_of<Pose>(planar<Pose>(0.3, 0, 0, 3), vec<Pose>(3, 0)))));
  // Growing shears.
  out.push_back(crafted<Pose>("shears", timed(0.0, 0.5, 1.0, pose_of<Pose>(planar<Pose>(1, 0, 0, 1), vec<Pose>(0, 0)),
                                              pose_of<Pose>(planar<Pose>(1, 1, 0, 1), vec<Pose>(1, 0.5)),
                                              pose_of<Pose>(planar<Pose>(1, 2.5, 0, 1), vec<Pose>(2, 0)))));
  for (std::size_t i = 0; i < out.size(); ++i) out[i].index = static_cast<int>(i);
  return out;
}

template <class Pose>
std::vector<PoseAuditConfig<Pose>> pose_audit_configs(std::uint64_t seed, int random_count) {
  using namespace pose_triples;
  std::vector<PoseAuditConfig<Pose>> out = crafted_pose_configs<Pose>();
  const int first = static_cast<int>(out.size());
  // A purpose of their own per dimension (the arrow audit uses 1 and 2 + its properties).
  const std::uint64_t purpose = 100 + static_cast<std::uint64_t>(PoseTraits<Pose>::dimension);
  for (int i = 0; i < random_count; ++i) {
    AuditRandom r(stream_seed(seed, purpose, static_cast<std::uint64_t>(i)));
    const ConfigMix mix = i % 3 == 0 ? ConfigMix::tame : i % 3 == 1 ? ConfigMix::wild : ConfigMix::near_singular;
    const PoseTriple<Pose> k = mix == ConfigMix::tame   ? tame<Pose>(r)
                               : mix == ConfigMix::wild ? wild<Pose>(r)
                                                        : near_singular<Pose>(r);
    out.push_back({first + i, mix, std::string(mix_name(mix)) + " #" + std::to_string(i), k});
  }
  return out;
}

template <class Pose>
typename PoseTraits<Pose>::Simplex reference_simplex() {
  typename PoseTraits<Pose>::Simplex s{};
  if constexpr (in_space_v<Pose>) {
    s = {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()};
  } else {
    s = {Point{0, 0}, Point{1, 0}, Point{0, 1}};
  }
  return s;
}

namespace pose_triples {

template <class Pose>
std::array<Vec<Pose>, PoseTraits<Pose>::simplex_vertices> simplex_vectors() {
  std::array<Vec<Pose>, PoseTraits<Pose>::simplex_vertices> out{};
  out[0] = Vec<Pose>::Zero();
  for (int i = 1; i < PoseTraits<Pose>::simplex_vertices; ++i) out[i] = Vec<Pose>::Unit(i - 1);
  return out;
}

}  // namespace pose_triples

template <class Pose>
double pose_distance(const Pose& X, const Pose& Y) {
  using namespace pose_triples;
  double d = 0.0;
  for (const Vec<Pose>& v : simplex_vectors<Pose>()) d = std::max(d, (apply(X, v) - apply(Y, v)).norm());
  return d;
}

template <class Pose>
typename PoseTraits<Pose>::Vector pose_centre(const Pose& pose) {
  using namespace pose_triples;
  Vec<Pose> centroid = Vec<Pose>::Zero();
  for (const Vec<Pose>& v : simplex_vectors<Pose>()) centroid += v;
  return apply(pose, Vec<Pose>(centroid / PoseTraits<Pose>::simplex_vertices));
}

template <class Pose>
double pose_reach(const Pose& pose, const typename PoseTraits<Pose>::Vector& from) {
  using namespace pose_triples;
  double e = 0.0;
  for (const Vec<Pose>& v : simplex_vectors<Pose>()) e = std::max(e, (apply(pose, v) - from).norm());
  return e;
}

template <class Pose>
double pose_extent(const PoseTriple<Pose>& poses) {
  using namespace pose_triples;
  const Vec<Pose> centre = pose_centre(poses[1].pose);
  double e = 0.0;
  for (const TimedPoseOf<Pose>& p : poses) e = std::max(e, pose_reach(p.pose, centre));
  return e;
}

#define PITA_POSE_AUDIT_CONFIGS(Pose)                                                       \
  template std::vector<PoseAuditConfig<Pose>> crafted_pose_configs<Pose>();                 \
  template std::vector<PoseAuditConfig<Pose>> pose_audit_configs<Pose>(std::uint64_t, int); \
  template PoseTraits<Pose>::Simplex reference_simplex<Pose>();                             \
  template double pose_distance<Pose>(const Pose&, const Pose&);                            \
  template PoseTraits<Pose>::Vector pose_centre<Pose>(const Pose&);                         \
  template double pose_extent<Pose>(const PoseTriple<Pose>&);                               \
  template double pose_reach<Pose>(const Pose&, const PoseTraits<Pose>::Vector&);           \
  template Pose random_affinity<Pose>(AuditRandom&, double, double, double);
PITA_POSE_AUDIT_CONFIGS(Affine2)
PITA_POSE_AUDIT_CONFIGS(Affine3)
#undef PITA_POSE_AUDIT_CONFIGS

}  // namespace pita::analysis
