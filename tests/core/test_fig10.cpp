// Fig. 10 reproduced, not assumed. For each property of Sec. 4.5-4.11, one
// test measures it on every PITA: it must hold (to rounding) for the PITAs
// that have it and be measurably violated, on some configuration, by each that
// does not. The expected sets are the paper's table as docs/paper-notes.md N8
// corrects it, plus what we measured for P4's windings and for the PITAs the
// table does not list (P5S, P9, P10); see the issue note and docs/reference/methods.md.
#include <set>

#include "test_support.hpp"

namespace pita::test {
namespace {

using MethodSet = std::set<Method>;
constexpr double kHolds = 1e-8;     // relative deviation allowed where a property holds
constexpr double kViolated = 1e-3;  // relative deviation that counts as a measurable violation

struct Measure {
  double worst_holding = 0.0;   // largest deviation seen (should be ~0 if the property holds)
  double best_violation = 0.0;  // largest deviation seen on any configuration
};

// Runs `deviation(method, config)` over random configurations plus extra
// crafted ones, and checks the holds/violated split.
void check_property(const char* property, const MethodSet& holding,
                    const std::function<double(Method, const KeyframeTriple&)>& deviation,
                    const std::vector<KeyframeTriple>& crafted = {}, Config c = Config::tame) {
  for (Method m : pitas()) {
    Sampler s(1000);
    std::vector<KeyframeTriple> configs = crafted;
    for (int i = 0; i < 40; ++i) configs.push_back(s.triple(c));
    double worst = 0.0;
    for (const KeyframeTriple& k : configs) worst = std::max(worst, deviation(m, k));
    if (holding.count(m)) {
      EXPECT_LT(worst, kHolds) << property << " should hold for " << name(m);
    } else {
      EXPECT_GT(worst, kViolated) << property << " should be measurably violated by " << name(m);
    }
  }
}

double max_frame_change(const Motion& x, const Motion& y, const KeyframeTriple& k) {
  double d = 0.0;
  for (double t : sample_times(k, 17, 0.0)) d = std::max(d, frame_distance(x.at(t), y.at(t)));
  return d / extent(k);
}

// Right composition X o G, G given as an arrow (the handle's placement in the
// shape's frame): origin X.p + X.vec G.p, magnitude X.m G.m, winding X.w + G.w.
Arrow compose_handle(const Arrow& X, const Arrow& G) { return {X.p + X.vector() * G.p, X.m * G.m, X.w + G.w}; }

TEST(Fig10, HandleInvariant) {
  // Sec. 4.5: moving the handle within the shape (A o G, B o G, C o G) moves
  // every frame the same way: P(A o G, ...) = P(A, ...) o G.
  const MethodSet H{Method::P1, Method::P4, Method::P5S, Method::P6, Method::P7, Method::P8, Method::P9};
  Sampler g(1);
  check_property("handle-invariance", H, [&](Method m, const KeyframeTriple& k) {
    const Arrow G{g.point(0.8), std::exp(g.uniform(-0.5, 0.5)), g.uniform(-2.5, 2.5)};
    const KeyframeTriple kg{{k.a.t, compose_handle(k.a.arrow, G)},
                            {k.b.t, compose_handle(k.b.arrow, G)},
                            {k.c.t, compose_handle(k.c.arrow, G)}};
    const auto D = motion(m, k), DG = motion(m, kg);
    double d = 0.0;
    for (double t : sample_times(k, 17, 0.0)) {
      d = std::max(d, frame_distance(DG->at(t), compose_handle(D->at(t), G)));
    }
    return d / extent(kg);
  });
}

TEST(Fig10, WindingAware) {
  // Sec. 4.6: a whole turn added to any one keyframe changes the motion. The
  // deviation from "winding-aware" is how little the frames change.
  const MethodSet W{Method::P2, Method::P3, Method::P4, Method::P6, Method::P9};
  for (Method m : pitas()) {
    Sampler s(2);
    double smallest_change = 1e300;  // over keyframes and configurations
    double largest_change = 0.0;
    for (int i = 0; i < 40; ++i) {
      const KeyframeTriple k = s.triple(Config::tame);
      const auto D = motion(m, k);
      for (int which = 0; which < 3; ++which) {
        KeyframeTriple kt = k;
        Keyframe* kf[3] = {&kt.a, &kt.b, &kt.c};
        kf[which]->arrow = with_turns(kf[which]->arrow, 1.0);
        const double change = max_frame_change(*D, *motion(m, kt), k);
        smallest_change = std::min(smallest_change, change);
        largest_change = std::max(largest_change, change);
      }
    }
    if (W.count(m)) {
      EXPECT_GT(smallest_change, kViolated) << name(m) << " should react to every keyframe's turns";
    } else {
      EXPECT_LT(smallest_change, kHolds) << name(m) << " should ignore some keyframe's turns";
    }
    if (m == Method::P5S) {
      // P5S's frame M(A, C) sees the turns between A and C, not B's.
      EXPECT_GT(largest_change, kViolated);
    } else if (!W.count(m)) {
      EXPECT_LT(largest_change, kHolds) << name(m) << " should ignore windings entirely";
    }
  }
}

// Configurations where a principal angle or a branch cut sits exactly at the
// edge, with the tweak parameter eps moving across it (Fig. 12).
KeyframeTriple pop_config(int kind, double eps) {
  switch (kind) {
    case 0:  // P2: a, b, c collinear with c behind b, Arg((c-b)/(b-a)) = +-pi.
      return {{0.0, {{0, 0}, 1.0, 1.0}}, {0.5, {{2, 0}, 0.8, 1.6}}, {1.0, {{0.5, eps}, 1.2, 2.2}}};
    case 1:  // P5, P5S, P10: B's angle crosses +pi (A, C turned by 0).
      return {{0.0, {{0, 0}, 1.0, 0.0}}, {0.5, {{2, 1}, 0.8, kPi + eps}}, {1.0, {{4, 0}, 1.2, 0.0}}};
    default:  // P7, P8: kappa = (vA + vC)/(2 vB) = -1.5, on the real cut of acosh.
      return {{0.0, {{0, 0}, 1.5, kPi + eps}}, {0.5, {{2, 1}, 1.0, 0.0}}, {1.0, {{4, 0}, 1.5, kPi}}};
  }
}

TEST(Fig10, PopFree) {
  // Sec. 4.7: every frame is a continuous function of the keyframes. The
  // deviation is the jump of the frames for a tweak of 2e-9 across each edge.
  const MethodSet P{Method::P1, Method::P3, Method::P4, Method::P6, Method::P9};
  for (Method m : pitas()) {
    double jump = 0.0;
    for (int kind = 0; kind < 3; ++kind) {
      const KeyframeTriple lo = pop_config(kind, -1e-9), hi = pop_config(kind, 1e-9);
      jump = std::max(jump, max_frame_change(*motion(m, lo), *motion(m, hi), lo));
    }
    // And a tiny tweak of random configurations moves frames by O(tweak).
    Sampler s(3);
    for (int i = 0; i < 40; ++i) {
      const KeyframeTriple k = s.triple(Config::tame);
      KeyframeTriple kt = k;
      kt.b.arrow.p += Complex{1e-9, -1e-9};
      kt.c.arrow.w += 1e-9;
      jump = std::max(jump, max_frame_change(*motion(m, k), *motion(m, kt), k));
    }
    if (P.count(m)) {
      EXPECT_LT(jump, 1e-6) << name(m) << " should be pop-free";
    } else {
      EXPECT_GT(jump, kViolated) << name(m) << " should pop";
    }
  }
}

// The smallest distance from point x to the curve p(t), t in [lo, hi]: dense
// sampling, then golden-section refinement around every sampled local minimum
// (curves may pass near themselves).
double distance_to_curve(const Motion& D, Point x, double lo, double hi) {
  const int n = 2000;
  const double step = (hi - lo) / n;
  std::vector<double> d(n + 1);
  for (int i = 0; i <= n; ++i) d[i] = std::abs(D.at(lo + step * i).p - x);
  double best = *std::min_element(d.begin(), d.end());
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int i = 1; i < n; ++i) {
    if (!(d[i] <= d[i - 1] && d[i] <= d[i + 1])) continue;
    double l = lo + step * (i - 1), r = lo + step * (i + 1);
    for (int it = 0; it < 60; ++it) {
      const double m1 = r - g * (r - l), m2 = l + g * (r - l);
      if (std::abs(D.at(m1).p - x) < std::abs(D.at(m2).p - x))
        r = m2;
      else
        l = m1;
    }
    best = std::min(best, std::abs(D.at(0.5 * (l + r)).p - x));
  }
  return best;
}

TEST(Fig10, KnotControlled) {
  // Sec. 4.8: changing (b - a)/(c - a) changes the curve traced by D(t).p. The
  // deviation from "knot-controlled" is how far the curve for ratio 0.3 stays
  // from the curve for ratio 0.5 (zero when b only warps time: P2, P4, P7, P8).
  const MethodSet K{Method::P1, Method::P3, Method::P5, Method::P5S, Method::P6, Method::P9, Method::P10};
  Sampler s(4);
  std::vector<KeyframeTriple> configs;
  for (int i = 0; i < 12; ++i) configs.push_back(s.triple(Config::tame));
  for (Method m : pitas()) {
    double moved = 0.0;
    for (KeyframeTriple k : configs) {  // copy: knots reset below
      k.a.t = 0.0, k.b.t = 0.5, k.c.t = 1.0;
      KeyframeTriple k3 = k;
      k3.b.t = 0.3;
      const auto even = motion(m, k), uneven = motion(m, k3);
      for (int i = 1; i < 20; ++i) {
        moved = std::max(moved, distance_to_curve(*even, uneven->at(i / 20.0).p, -0.5, 1.5) / extent(k));
      }
    }
    if (K.count(m)) {
      EXPECT_GT(moved, kViolated) << name(m) << " should be knot-controlled";
    } else {
      EXPECT_LT(moved, 1e-9) << name(m) << ": b should only warp time";
    }
  }
}

TEST(Fig10, OrderIndependent) {
  // Sec. 4.9, PITA Eq. 42: swapping (a, A) and (b, B) changes nothing.
  const MethodSet O{Method::P1, Method::P3, Method::P5, Method::P10};
  check_property("order-independence", O, [](Method m, const KeyframeTriple& k) {
    const KeyframeTriple swapped{k.b, k.a, k.c};
    return max_frame_change(*motion(m, k), *motion(m, swapped), k);
  });
}

TEST(Fig10, AffineInvariantOnArrows) {
  // Sec. 4.10, PITA Eq. 43: an affinity applied to the keyframes' start and end
  // points moves every frame's start and end points the same way. P8 is
  // affine-invariant only when the affinity also moves its key triangles' tips
  // (tests/core/test_pam.cpp); on arrows alone it is violated, like the rest.
  const MethodSet A{Method::P1};
  const auto U = [](Point x) {
    return Point{1.3 * x.real() + 0.4 * x.imag() + 0.7, -0.2 * x.real() + 0.8 * x.imag() - 0.3};
  };
  check_property("affine invariance", A, [&](Method m, const KeyframeTriple& k) {
    const auto moved = [&](const Keyframe& x) { return Keyframe{x.t, zero_turn_arrow(U(x.arrow.p), U(x.arrow.q()))}; };
    const KeyframeTriple zk{
        {k.a.t, zero_turn(k.a.arrow)}, {k.b.t, zero_turn(k.b.arrow)}, {k.c.t, zero_turn(k.c.arrow)}};
    const auto D = motion(m, zk), DU = motion(m, {moved(zk.a), moved(zk.b), moved(zk.c)});
    double d = 0.0;
    for (double t : sample_times(k, 17, 0.0)) {
      const Arrow x = D->at(t), y = DU->at(t);
      d = std::max({d, std::abs(y.p - U(x.p)), std::abs(y.q() - U(x.q()))});
    }
    return d / extent(k);
  });
}

// Perseverance (Sec. 3.3, 4.11), by finite differences on even knots.
enum class Perseverance { global, radial, local };

double perseverance_deviation(Method m, const KeyframeTriple& k, Perseverance kind) {
  const auto D = motion(m, k);
  const double h = 2e-3;
  const auto second = [&](double t, Point (*pick)(const Arrow&)) {
    return (pick(D->at(t + h)) - 2.0 * pick(D->at(t)) + pick(D->at(t - h))) / (h * h);
  };
  const auto P = +[](const Arrow& x) { return x.p; };
  const auto Q = +[](const Arrow& x) { return x.q(); };
  const std::vector<double> ts{0.1, 0.3, 0.5, 0.7, 0.9};
  double dev = 0.0;
  for (auto pick : {P, Q}) {
    std::vector<Complex> acc, pos, vec;
    for (double t : ts) {
      acc.push_back(second(t, pick));
      pos.push_back(pick(D->at(t)));
      vec.push_back(D->at(t).vector());
    }
    double scale = 0.0;
    for (const Complex& a : acc) scale = std::max(scale, std::abs(a));
    scale += extent(k);
    if (kind == Perseverance::global) {  // x'' constant
      for (const Complex& a : acc) dev = std::max(dev, std::abs(a - acc[0]) / scale);
    } else if (kind == Perseverance::local) {  // x'' / vector constant
      for (std::size_t i = 0; i < ts.size(); ++i) {
        dev = std::max(dev, std::abs(acc[i] / vec[i] - acc[0] / vec[0]) * std::abs(vec[0]) / scale);
      }
    } else {  // x'' = K (x - f): fit K and K f from two samples, test the rest
      const Complex K = (acc[1] - acc[0]) / (pos[1] - pos[0]);
      const Complex Kf = K * pos[0] - acc[0];
      for (std::size_t i = 0; i < ts.size(); ++i) dev = std::max(dev, std::abs(K * pos[i] - Kf - acc[i]) / scale);
    }
  }
  return dev;
}

TEST(Fig10, Perseverant) {
  // P1 is globally, P7 radially and P8 locally perseverant; the finite
  // differences (h = 2e-3) leave ~1e-6 where a property holds. Global
  // perseverance is radial perseverance with f at infinity (x'' = K (x - f)
  // with K -> 0, K f fixed; Sec. 4.11), so P1 passes the radial test too.
  Sampler s(6);
  std::vector<KeyframeTriple> configs;
  for (int i = 0; i < 20; ++i) {
    KeyframeTriple k = s.triple(Config::tame);
    k.a.t = 0.0, k.b.t = 0.5, k.c.t = 1.0;
    configs.push_back(k);
  }
  const std::pair<Perseverance, Method> owners[] = {
      {Perseverance::global, Method::P1}, {Perseverance::radial, Method::P7}, {Perseverance::local, Method::P8}};
  for (const auto& [kind, owner] : owners) {
    for (Method m : pitas()) {
      double worst = 0.0;
      for (const KeyframeTriple& k : configs) worst = std::max(worst, perseverance_deviation(m, k, kind));
      const bool holds = m == owner || (kind == Perseverance::radial && m == Method::P1);
      if (holds) {
        EXPECT_LT(worst, 1e-5) << name(m) << " kind " << static_cast<int>(kind);
      } else {
        EXPECT_GT(worst, 1e-2) << name(m) << " kind " << static_cast<int>(kind);
      }
    }
  }
}

}  // namespace
}  // namespace pita::test
