#include "analysis/audit_configs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pita::analysis {

namespace {

Keyframe key(double t, double x, double y, double m, double w) { return {t, Arrow{{x, y}, m, w}}; }

AuditConfig crafted(std::string name, KeyframeTriple k, bool on_cut = false) {
  return {0, ConfigMix::crafted, "crafted: " + std::move(name), k, on_cut};
}

Arrow random_arrow(AuditRandom& r, double log_m, double w) {
  return {{r.uniform(-5.0, 5.0), r.uniform(-5.0, 5.0)}, std::exp(r.uniform(-log_m, log_m)), r.uniform(-w, w)};
}

KeyframeTriple random_knots(AuditRandom& r, Arrow A, Arrow B, Arrow C, bool uneven) {
  const double a = r.uniform(-2.0, 2.0);
  const double span = std::exp(r.uniform(-1.0, 1.0));
  const double beta = uneven ? r.uniform(0.2, 0.8) : 0.5;
  return {{a, A}, {a + beta * span, B}, {a + span, C}};
}

// Tame: magnitudes within e^{+-0.7}, windings in (-pi, pi]; half with uneven knots.
KeyframeTriple tame(AuditRandom& r) {
  const bool uneven = r.uniform(0.0, 1.0) < 0.5;
  const Arrow A = random_arrow(r, 0.7, kPi), B = random_arrow(r, 0.7, kPi), C = random_arrow(r, 0.7, kPi);
  return random_knots(r, A, B, C, uneven);
}

// Wild (Sec. 6.6): magnitude ratios up to 1e4 and windings up to +-20 rad
// (about three turns).
KeyframeTriple wild(AuditRandom& r) {
  const bool uneven = r.uniform(0.0, 1.0) < 0.5;
  const Arrow A = random_arrow(r, 4.6, 20.0), B = random_arrow(r, 4.6, 20.0), C = random_arrow(r, 4.6, 20.0);
  return random_knots(r, A, B, C, uneven);
}

// Near-singular: one of the situations where a construction divides by a
// small number or sits by a branch cut, approached within 1e-7..1e-3.
KeyframeTriple near_singular(AuditRandom& r) {
  const double eps = std::exp(r.uniform(std::log(1e-7), std::log(1e-3))) * r.sign();
  KeyframeTriple k = tame(r);
  switch (static_cast<int>(r.uniform(0.0, 5.0))) {
    case 0: {  // origins almost collinear, C's behind B (P2's cut, Fig. 12)
      const Complex d = k.b.arrow.p - k.a.arrow.p;
      k.c.arrow.p = k.b.arrow.p - r.uniform(0.3, 1.5) * d + Complex{0.0, eps} * d;
      break;
    }
    case 1:  // B's angle relative to A and C near +-pi (principal logs)
      k.a.arrow.w = principal_angle(k.a.arrow.w);
      k.c.arrow.w = k.a.arrow.w;
      k.b.arrow.w = k.a.arrow.w + kPi + eps;
      break;
    case 2:  // B almost a translate of A (twirl near a translation, N18)
      k.b.arrow.m = k.a.arrow.m * (1.0 + eps);
      k.b.arrow.w = k.a.arrow.w + eps;
      break;
    case 3:  // A and B almost the same arrow
      k.b.arrow = {k.a.arrow.p + Complex{eps, -eps}, k.a.arrow.m * (1.0 + eps), k.a.arrow.w + eps};
      break;
    default: {  // the three origins almost coincide
      const Complex c = k.b.arrow.p;
      k.a.arrow.p = c + Complex{eps, 0.3 * eps};
      k.c.arrow.p = c + Complex{-0.7 * eps, eps};
      break;
    }
  }
  return k;
}

}  // namespace

std::uint64_t AuditRandom::next() {
  std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

double AuditRandom::uniform(double lo, double hi) {
  const double u = static_cast<double>(next() >> 11) * 0x1.0p-53;
  return lo + (hi - lo) * u;
}

double AuditRandom::sign() { return (next() >> 63) != 0 ? 1.0 : -1.0; }

std::uint64_t stream_seed(std::uint64_t seed, std::uint64_t purpose, std::uint64_t index) {
  AuditRandom r(seed * 0x2545F4914F6CDD1DULL ^ (purpose << 40) ^ index);
  r.next();
  return r.next();
}

std::string_view mix_name(ConfigMix mix) {
  switch (mix) {
    case ConfigMix::crafted:
      return "crafted";
    case ConfigMix::tame:
      return "tame";
    case ConfigMix::wild:
      return "wild";
    case ConfigMix::near_singular:
      return "near-singular";
  }
  return "?";
}

std::vector<AuditConfig> crafted_configs() {
  std::vector<AuditConfig> out;
  // PITA Fig. 12's pops: exactly on each cut; the pop probe tweaks across it.
  out.push_back(crafted("P2 cut, origins collinear with c behind b",
                        {key(0.0, 0, 0, 1.0, 1.0), key(0.5, 2, 0, 0.8, 1.6), key(1.0, 0.5, 0, 1.2, 2.2)}, true));
  out.push_back(crafted("principal-log cut, B turned by pi",
                        {key(0.0, 0, 0, 1.0, 0.0), key(0.5, 2, 1, 0.8, kPi), key(1.0, 4, 0, 1.2, 0.0)}, true));
  out.push_back(crafted("-Pe cut, (vA + vC)/(2 vB) = -1.5",
                        {key(0.0, 0, 0, 1.5, kPi), key(0.5, 2, 1, 1.0, 0.0), key(1.0, 4, 0, 1.5, kPi)}, true));
  // Keyframes that are translates of one another (every twirl a translation).
  out.push_back(
      crafted("translates", {key(0.0, 0, 0, 1.0, 0.4), key(0.5, 2, 1.5, 1.0, 0.4), key(1.0, 4, 0, 1.0, 0.4)}));
  // Rotations about one point (a circle), with two extra turns in all.
  out.push_back(crafted("rotations about the origin, several turns",
                        {key(0.0, 2, 0, 1.0, 0.5), key(0.5, -1, std::sqrt(3.0), 1.0, 0.5 + 2 * kPi / 3 + 2 * kPi),
                         key(1.0, -1, -std::sqrt(3.0), 1.0, 0.5 + 4 * kPi / 3 + 4 * kPi)}));
  // Uneven knots with a strong middle keyframe.
  out.push_back(
      crafted("uneven knots", {key(0.0, 0, 0, 1.0, 0.3), key(0.2, 1.5, 2.0, 2.0, 1.4), key(1.0, 6, 0, 0.6, -0.8)}));
  // A wild configuration of Sec. 6.6: large winding differences and magnitude ratios.
  out.push_back(crafted("wild, windings -6..9 and magnitudes 0.05..20",
                        {key(0.0, 0, 0, 0.05, -6.0), key(0.4, 3, 2, 20.0, 2.0), key(1.0, 7, -1, 1.0, 9.0)}));
  // Wild windings where P9's Neville step M(X(t), Y(t), s) passes close to a
  // singular steady morph just after b: its frames spike to 40 times the
  // extent within 1e-4 of the span (seed 42's wild #70; docs/paper-notes.md N36).
  out.push_back(
      crafted("wild, P9's Neville step near a singular steady morph",
              {{-0.97198279966561074,
                Arrow{{-3.9447201213883254, -1.3859142052162801}, 0.42658816675212369, -17.610701059432373}},
               {-0.63010701541990588,
                Arrow{{-1.9201251662525176, 2.0951239954909129}, 0.18901055069773637, 19.073163757885197}},
               {0.35239283002170696,
                Arrow{{-3.3103836393360475, -0.080703286568803989}, 0.022066145814316755, 13.093670576051522}}}));
  for (std::size_t i = 0; i < out.size(); ++i) out[i].index = static_cast<int>(i);
  return out;
}

std::vector<AuditConfig> audit_configs(std::uint64_t seed, int random_count) {
  std::vector<AuditConfig> out = crafted_configs();
  const int first = static_cast<int>(out.size());
  for (int i = 0; i < random_count; ++i) {
    AuditRandom r(stream_seed(seed, 1, static_cast<std::uint64_t>(i)));
    const ConfigMix mix = i % 3 == 0 ? ConfigMix::tame : i % 3 == 1 ? ConfigMix::wild : ConfigMix::near_singular;
    const KeyframeTriple k = mix == ConfigMix::tame ? tame(r) : mix == ConfigMix::wild ? wild(r) : near_singular(r);
    out.push_back({first + i, mix, std::string(mix_name(mix)) + " #" + std::to_string(i), k});
  }
  return out;
}

double extent(const KeyframeTriple& k) {
  double e = 0.0;
  for (const Keyframe* x : {&k.a, &k.b, &k.c}) {
    e = std::max({e, std::abs(x->arrow.p - k.b.arrow.p), std::abs(x->arrow.q() - k.b.arrow.p), x->arrow.m});
  }
  return e;
}

}  // namespace pita::analysis
