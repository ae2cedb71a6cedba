#include "analysis/properties.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "analysis/arrow_distance.hpp"
#include "analysis/audit_configs.hpp"
#include "core/finite_difference.hpp"
#include "core/limits.hpp"

namespace pita::analysis {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The one table of properties (Fig. 10's rows, Sec. 4.1-4.11). Thresholds:
// docs/paper-notes.md N36 says how they were chosen from the measured gaps.
constexpr std::array<PropertyInfo, 13> kProperties{{
    {Property::exists, "exists", "", "4.1",
     "share of the configurations where the motion cannot be built or a frame is not finite", false, 0.0},
    {Property::smooth, "smooth", "", "4.2",
     "largest jump of the second derivative of p or q across a time in (a, c) (the knot b and two others), "
     "one-sided differences, relative to the second derivative plus the extent",
     false, 1e-2},
    {Property::similarity_invariant, "similarity-invariant", "", "4.3, PITA Eq. 40",
     "largest distance between P(S A, S B, S C, t) and S P(A, B, C, t), over the extent of the moved keyframes", false,
     1e-7},
    {Property::symmetric, "symmetric", "", "4.4, PITA Eq. 41",
     "largest distance between P(a, A, b, B, c, C, t) and P(a, C, a + c - b, B, c, A, a + c - t), over the extent",
     false, 1e-7},
    {Property::handle_invariant, "handle-invariant", "H", "4.5",
     "largest distance between P(A G, B G, C G, t) and P(A, B, C, t) G for a handle G placed in the shape's frame, "
     "over the extent",
     false, 1e-7},
    {Property::winding_aware, "winding-aware", "W", "4.6",
     "smallest reaction, over the three keyframes, to a whole turn added to one of them: the largest change of a "
     "frame's direction (radians, modulo 2 pi) plus the largest move of its ends over the extent",
     true, 1e-6},
    {Property::pop_free, "pop-free", "P", "4.7",
     "largest jump of a frame (over the extent) that does not shrink with the tweak: its move between tweaks of "
     "-1e-10 and +1e-10 of one keyframe parameter (positions in units of the extent, magnitudes relative, "
     "windings, knots in units of the span) less a tenth of its move for +-1e-9",
     false, 1e-6},
    {Property::knot_controlled, "knot-controlled", "K", "4.8",
     "how far the curve traced by D(t).p moves when the knot ratio (b - a)/(c - a) changes by 0.2 (Fig. 13): the "
     "largest distance from a new D(t).p to the old curve (extrapolated over half the span each side), over the "
     "extent",
     true, 1e-6},
    {Property::order_independent, "order-independent", "O", "4.9, PITA Eq. 42",
     "largest distance between P(b, B, a, A, c, C, t) and P(a, A, b, B, c, C, t), over the extent", false, 1e-7},
    {Property::affine_invariant, "affine-invariant", "A", "4.10, PITA Eq. 43",
     "largest distance between the ends of P(U A, U B, U C, t) and U applied to the ends of P(A, B, C, t) for an "
     "affinity U (zero-turn keyframes), over the extent",
     false, 1e-7},
    {Property::globally_perseverant, "globally-perseverant", "L", "3.3, 4.11",
     "largest change of the acceleration of p or q (global frame) over s = (t - a)/(c - a) in [0.1, 0.9], even "
     "knots, relative to the largest acceleration plus the extent",
     false, 1e-5},
    {Property::radially_perseverant, "radially-perseverant", "L", "3.3, PITA Eq. 35",
     "largest residual of p'' = K (p - f) (and the same for q) fitted by least squares over five times, even knots, "
     "relative to the largest acceleration plus the extent",
     false, 1e-5},
    {Property::locally_perseverant, "locally-perseverant", "L", "3.3, 4.11",
     "largest change of the acceleration of p or q expressed in the frame D(t) (divided by D(t)'s vector), even "
     "knots, relative to the largest acceleration plus the extent",
     false, 1e-5},
}};

// Times in [a, c]: 17 uniform ones and the middle knot.
std::vector<double> sample_times(const KeyframeTriple& k) {
  std::vector<double> ts;
  const double lo = std::min({k.a.t, k.b.t, k.c.t}), hi = std::max({k.a.t, k.b.t, k.c.t});
  for (int i = 0; i <= 16; ++i) ts.push_back(lo + (hi - lo) * i / 16.0);
  ts.push_back(k.b.t);
  return ts;
}

// The motion, or nullptr when it cannot be built (the property is then not
// measured on this configuration; "exists" counts it).
std::unique_ptr<Motion> try_motion(Method m, const KeyframeTriple& k) {
  try {
    return make_pita(m, k);
  } catch (const std::exception&) {
    return nullptr;
  }
}

// The largest value seen and where; a NaN, once seen, stays the worst.
struct Worst {
  double value = 0.0;
  double t = kNaN;
  bool any = false;
  void take(double v, double at) {
    if (!any || std::isnan(v) || (!std::isnan(value) && v > value)) value = v, t = at;
    any = true;
  }
};

// The size distances are divided by: the configuration's extent, or the
// motion's own reach from B's origin when it goes further (near a singular
// configuration a frame may be far out, and rounding grows with it).
double motion_scale(const Motion& D, const KeyframeTriple& k) {
  double scale = extent(k);
  for (double t : sample_times(k)) {
    const Arrow x = D.at(t);
    const double reach = std::max(std::abs(x.p - k.b.arrow.p), std::abs(x.q() - k.b.arrow.p));
    if (std::isfinite(reach)) scale = std::max(scale, reach);
  }
  return scale;
}

// max_t |X(t) - map(Y)(t')| over `scale`; `y_time` maps the original's t.
Worst compare(const Motion& X, const Motion& Y, const KeyframeTriple& k, double scale,
              const std::function<Arrow(const Arrow&)>& expect = nullptr,
              const std::function<double(double)>& y_time = nullptr) {
  Worst w;
  for (double t : sample_times(k)) {
    const Arrow x = expect ? expect(X.at(t)) : X.at(t);
    const Arrow y = Y.at(y_time ? y_time(t) : t);
    w.take(endpoint_distance(x, y) / scale, t);
  }
  return w;
}

Probe not_built(const KeyframeTriple& k, const std::string& why) {
  Probe p;
  p.value = kNaN;
  p.original = k;
  p.note = why;
  return p;
}

KeyframeTriple map_arrows(const KeyframeTriple& k, const std::function<Arrow(const Arrow&)>& f) {
  return {{k.a.t, f(k.a.arrow)}, {k.b.t, f(k.b.arrow)}, {k.c.t, f(k.c.arrow)}};
}

Probe probe_exists(Method m, const KeyframeTriple& k) {
  Probe p;
  p.original = k;
  p.relation = "the motion is built and every frame at 33 times in [a, c] is finite";
  try {
    const auto D = make_pita(m, k);
    const double a = k.a.t, c = k.c.t;
    for (int i = 0; i <= 32; ++i) {
      const double t = a + (c - a) * i / 32.0;
      if (!is_finite(D->at(t))) {
        p.value = 1.0, p.t = t, p.note = "a frame is not finite";
        return p;
      }
    }
  } catch (const std::exception& e) {
    p.value = 1.0, p.note = e.what();
  }
  return p;
}

// The jump of the second derivative of p and q at t: one-sided second-order
// differences from the left and the right. Where the motion is smooth their
// difference shrinks like h^3, at a kink it stays: Richardson's step on h and
// h/2 keeps the jump and cancels the h^3 term. In s = (t - a)/(c - a) units.
Probe probe_smooth(Method m, const KeyframeTriple& k) {
  const auto D = try_motion(m, k);
  if (!D) return not_built(k, "no motion");
  const double span = k.c.t - k.a.t, ext = motion_scale(*D, k);
  Probe p;
  p.original = k;
  p.relation = "second derivatives of p and q from the left and from the right agree";
  Worst w;
  for (double t : {k.b.t, k.a.t + 0.3 * span, k.a.t + 0.7 * span}) {
    for (int which = 0; which < 2; ++which) {
      const auto x = [&](double u) {
        const Arrow f = D->at(u);
        return which == 0 ? f.p : f.q();
      };
      const auto jump = [&](double h, double& size) {
        const Complex left = one_sided_second_derivative(x, t, -h) * (span * span);
        const Complex right = one_sided_second_derivative(x, t, h) * (span * span);
        size = std::max({size, std::abs(left), std::abs(right)});
        return left - right;
      };
      double size = 0.0;
      const double h = 2e-4 * span;
      const Complex j1 = jump(h, size), j2 = jump(0.5 * h, size);
      w.take(std::abs((8.0 * j2 - j1) / 7.0) / (size + ext), t);
    }
  }
  p.value = w.value, p.t = w.t;
  return p;
}

Probe probe_similarity(Method m, const KeyframeTriple& k, AuditRandom& r) {
  const Similarity S{
      {r.uniform(-10, 10), r.uniform(-10, 10)}, std::exp(r.uniform(-2.0, 2.0)), r.uniform(-4 * kPi, 4 * kPi)};
  const KeyframeTriple ks = map_arrows(k, [&](const Arrow& A) { return apply(S, A); });
  const auto D = try_motion(m, k), DS = try_motion(m, ks);
  if (!D || !DS) return not_built(k, "no motion");
  const Worst w = compare(*D, *DS, k, motion_scale(*DS, ks), [&](const Arrow& A) { return apply(S, A); });
  Probe p{w.value,
          w.t,
          k,
          ks,
          "frames of the counterpart = S applied to frames of the original, at the same t",
          {{"translation.x", S.translation.real()},
           {"translation.y", S.translation.imag()},
           {"scale", S.scale},
           {"rotation", S.rotation}},
          ""};
  return p;
}

KeyframeTriple mirrored_in_time(const KeyframeTriple& k) {
  return {{k.a.t, k.c.arrow}, {k.c.t + k.a.t - k.b.t, k.b.arrow}, {k.c.t, k.a.arrow}};
}

Probe probe_symmetric(Method m, const KeyframeTriple& k) {
  const KeyframeTriple r = mirrored_in_time(k);
  const auto D = try_motion(m, k), R = try_motion(m, r);
  if (!D || !R) return not_built(k, "no motion");
  const double a = k.a.t, c = k.c.t;
  const Worst w = compare(*D, *R, k, motion_scale(*D, k), nullptr, [&](double t) { return a + c - t; });
  return {w.value, w.t, k, r, "frame of the original at t = frame of the counterpart at a + c - t", {}, ""};
}

// Right composition X o G, G an arrow in the shape's frame (Sec. 4.5).
Arrow compose_handle(const Arrow& X, const Arrow& G) { return {X.p + X.vector() * G.p, X.m * G.m, X.w + G.w}; }

Probe probe_handle(Method m, const KeyframeTriple& k, AuditRandom& r) {
  const Arrow G{{r.uniform(-0.8, 0.8), r.uniform(-0.8, 0.8)}, std::exp(r.uniform(-0.5, 0.5)), r.uniform(-2.5, 2.5)};
  const KeyframeTriple kg = map_arrows(k, [&](const Arrow& A) { return compose_handle(A, G); });
  const auto D = try_motion(m, k), DG = try_motion(m, kg);
  if (!D || !DG) return not_built(k, "no motion");
  const Worst w = compare(*D, *DG, k, motion_scale(*DG, kg), [&](const Arrow& A) { return compose_handle(A, G); });
  return {w.value,
          w.t,
          k,
          kg,
          "frames of the counterpart (keyframes X o G) = frames of the original composed with G: "
          "p + vector(p_G), magnitude m m_G, winding w + w_G",
          {{"handle.p.x", G.p.real()}, {"handle.p.y", G.p.imag()}, {"handle.m", G.m}, {"handle.w", G.w}},
          ""};
}

Probe probe_winding(Method m, const KeyframeTriple& k) {
  const auto D = try_motion(m, k);
  if (!D) return not_built(k, "no motion");
  const double ext = extent(k);
  Probe best;
  best.value = std::numeric_limits<double>::infinity();
  for (int which = 0; which < 3; ++which) {
    KeyframeTriple kt = k;
    Keyframe* kf[3] = {&kt.a, &kt.b, &kt.c};
    kf[which]->arrow = with_turns(kf[which]->arrow, 1.0);
    const auto T = try_motion(m, kt);
    if (!T) continue;
    Worst w;
    for (double t : sample_times(k)) {
      const Arrow x = D->at(t), y = T->at(t);
      const double turn = std::abs(std::arg(y.vector() / x.vector()));
      w.take(turn + endpoint_distance(x, y) / ext, t);
    }
    if (w.value < best.value) {
      best = {w.value,
              w.t,
              k,
              kt,
              "frames change when a whole turn is added to keyframe " + std::string(1, "ABC"[which]),
              {{"keyframe", which}, {"turns", 1.0}},
              ""};
    }
  }
  if (!std::isfinite(best.value)) return not_built(k, "no motion");
  return best;
}

// Tweaks one parameter of one keyframe by `d` (a fraction: positions in
// units of the extent, magnitudes relative, angles in radians, knots in
// units of the span).
KeyframeTriple tweaked(const KeyframeTriple& k, int which, int parameter, double d) {
  KeyframeTriple out = k;
  Keyframe* kf[3] = {&out.a, &out.b, &out.c};
  Keyframe& x = *kf[which];
  const double ext = extent(k), span = k.c.t - k.a.t;
  switch (parameter) {
    case 0:
      x.arrow.p += Complex{d * ext, 0.0};
      break;
    case 1:
      x.arrow.p += Complex{0.0, d * ext};
      break;
    case 2:
      x.arrow.m *= 1.0 + d;
      break;
    case 3:
      x.arrow.w += d;
      break;
    default:
      x.t += d * span;
      break;
  }
  return out;
}

constexpr std::array<const char*, 5> kKeyframeParameterNames{"p.x", "p.y", "m", "w", "t"};

// A pop is a jump that does not shrink with the tweak: the frames' move for a
// tweak of +-1e-10 less a tenth of their move for +-1e-9 (zero, to rounding,
// where the frames depend smoothly on the parameter however steeply).
Probe probe_pop(Method m, const KeyframeTriple& k) {
  constexpr double kTweak = 1e-9;
  Probe best;
  best.value = -1.0;
  bool any = false;
  for (int which = 0; which < 3; ++which) {
    for (int parameter = 0; parameter < 5; ++parameter) {
      const KeyframeTriple lo = tweaked(k, which, parameter, -kTweak), hi = tweaked(k, which, parameter, kTweak);
      const KeyframeTriple lo10 = tweaked(k, which, parameter, -0.1 * kTweak),
                           hi10 = tweaked(k, which, parameter, 0.1 * kTweak);
      const auto L = try_motion(m, lo), H = try_motion(m, hi), L10 = try_motion(m, lo10), H10 = try_motion(m, hi10);
      if (!L || !H || !L10 || !H10) continue;
      any = true;
      Worst w;
      const double scale = motion_scale(*L, k);
      for (double t : sample_times(k)) {
        const double big = endpoint_distance(L->at(t), H->at(t)), small = endpoint_distance(L10->at(t), H10->at(t));
        w.take(std::max(0.0, small - 0.1 * big) / scale, t);
      }
      if (w.value > best.value) {
        best = {w.value,
                w.t,
                lo,
                hi,
                std::string("frames barely move when ") + "ABC"[which] + "." + kKeyframeParameterNames[parameter] +
                    " changes by 2e-9 (original: -1e-9, counterpart: +1e-9)",
                {{"keyframe", which}, {"parameter", parameter}, {"tweak", 2 * kTweak}},
                ""};
        best.relation = std::string("frames barely move when ") + "ABC"[which] + "." +
                        kKeyframeParameterNames[parameter] +
                        " changes by 2e-9 (original: -1e-9, counterpart: +1e-9); the jump does not shrink for 2e-10";
      }
    }
  }
  if (!any) return not_built(k, "no motion");
  return best;
}

// The distance from x to the curve of D(t).p over [lo, hi]: dense samples,
// then golden-section search around the nearest one.
double distance_to_curve(const Motion& D, const std::vector<Point>& samples, double lo, double hi, Point x) {
  const int n = static_cast<int>(samples.size()) - 1;
  int best = 0;
  for (int i = 1; i <= n; ++i) {
    if (std::abs(samples[i] - x) < std::abs(samples[best] - x)) best = i;
  }
  const double step = (hi - lo) / n;
  double l = lo + step * std::max(best - 1, 0), r = lo + step * std::min(best + 1, n);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double m1 = r - g * (r - l), m2 = l + g * (r - l);
  double f1 = std::abs(D.at(m1).p - x), f2 = std::abs(D.at(m2).p - x);
  for (int it = 0; it < 50; ++it) {
    if (f1 < f2) {
      r = m2, m2 = m1, f2 = f1, m1 = r - g * (r - l), f1 = std::abs(D.at(m1).p - x);
    } else {
      l = m1, m1 = m2, f1 = f2, m2 = l + g * (r - l), f2 = std::abs(D.at(m2).p - x);
    }
  }
  return std::min({f1, f2, std::abs(samples[best] - x)});
}

Probe probe_knots(Method m, const KeyframeTriple& k) {
  const double span = k.c.t - k.a.t, beta = (k.b.t - k.a.t) / span;
  KeyframeTriple moved = k;
  moved.b.t = k.a.t + span * (beta < 0.5 ? beta + 0.2 : beta - 0.2);
  const auto D = try_motion(m, k), M = try_motion(m, moved);
  if (!D || !M) return not_built(k, "no motion");
  const double lo = k.a.t - 0.5 * span, hi = k.c.t + 0.5 * span;
  std::vector<Point> samples;
  for (int i = 0; i <= 800; ++i) samples.push_back(D->at(lo + (hi - lo) * i / 800.0).p);
  Worst w;
  for (int i = 1; i < 10; ++i) {
    const double t = k.a.t + span * i / 10.0;
    w.take(distance_to_curve(*D, samples, lo, hi, M->at(t).p) / extent(k), t);
  }
  return {w.value,
          w.t,
          k,
          moved,
          "the path of p of the counterpart (b moved by 0.2 of the span) lies on the path of p of the original",
          {{"knot ratio", beta}, {"moved knot ratio", (moved.b.t - k.a.t) / span}},
          ""};
}

Probe probe_order(Method m, const KeyframeTriple& k) {
  const KeyframeTriple swapped{k.b, k.a, k.c};
  const auto D = try_motion(m, k), S = try_motion(m, swapped);
  if (!D || !S) return not_built(k, "no motion");
  const Worst w = compare(*D, *S, k, std::max(motion_scale(*D, k), motion_scale(*S, k)));
  return {w.value, w.t, k, swapped, "P(b, B, a, A, c, C, t) = P(a, A, b, B, c, C, t): the same frames at the same t",
          {},      ""};
}

Probe probe_affine(Method m, const KeyframeTriple& k, AuditRandom& r) {
  const double a = std::exp(r.uniform(-0.5, 0.5)), b = r.uniform(-0.6, 0.6), c = r.uniform(-0.6, 0.6),
               d = std::exp(r.uniform(-0.5, 0.5));
  const Complex u{r.uniform(-3, 3), r.uniform(-3, 3)};
  const auto U = [&](Point x) { return Point{a * x.real() + b * x.imag(), c * x.real() + d * x.imag()} + u; };
  const KeyframeTriple zk = map_arrows(k, [](const Arrow& A) { return zero_turn(A); });
  const KeyframeTriple uk = map_arrows(zk, [&](const Arrow& A) { return zero_turn_arrow(U(A.p), U(A.q())); });
  const auto D = try_motion(m, zk), DU = try_motion(m, uk);
  if (!D || !DU) return not_built(k, "no motion");
  Worst w;
  const double ext = motion_scale(*DU, uk);
  for (double t : sample_times(k)) {
    const Arrow x = D->at(t), y = DU->at(t);
    w.take(std::max(std::abs(y.p - U(x.p)), std::abs(y.q() - U(x.q()))) / ext, t);
  }
  return {w.value,
          w.t,
          zk,
          uk,
          "ends of the counterpart's frames (keyframes' ends mapped by U) = U applied to the ends of the original's "
          "frames",
          {{"U.xx", a}, {"U.xy", b}, {"U.yx", c}, {"U.yy", d}, {"U.tx", u.real()}, {"U.ty", u.imag()}},
          ""};
}

Probe probe_perseverant(Property kind, Method m, const KeyframeTriple& k) {
  KeyframeTriple even = k;
  even.b.t = 0.5 * (k.a.t + k.c.t);
  const auto D = try_motion(m, even);
  if (!D) return not_built(even, "no motion");
  const double a = even.a.t, span = even.c.t - even.a.t, h = limits::kPerseveranceStep, ext = extent(even);
  const std::array<double, 5> ss{0.1, 0.3, 0.5, 0.7, 0.9};
  const auto at = [&](double s) { return D->at(a + s * span); };
  double dev = 0.0;
  for (int which = 0; which < 2; ++which) {
    const auto pick = [&](const Arrow& x) { return which == 0 ? x.p : x.q(); };
    std::array<Complex, 5> acc, pos, vec;
    double scale = ext;
    for (std::size_t i = 0; i < ss.size(); ++i) {
      const double s = ss[i];
      acc[i] = central_second_derivative4([&](double v) { return pick(at(v)); }, s, h);
      pos[i] = pick(at(s));
      vec[i] = at(s).vector();
      scale = std::max(scale, std::abs(acc[i]) + ext);
    }
    if (kind == Property::globally_perseverant) {
      for (const Complex& x : acc) dev = std::max(dev, std::abs(x - acc[0]) / scale);
    } else if (kind == Property::locally_perseverant) {
      for (std::size_t i = 0; i < ss.size(); ++i) {
        dev = std::max(dev, std::abs(acc[i] / vec[i] - acc[0] / vec[0]) * std::abs(vec[0]) / scale);
      }
    } else {
      // Least squares for acc = K pos + L (L = -K f) over the five samples.
      Complex sp = 0, sa = 0;
      for (std::size_t i = 0; i < ss.size(); ++i) sp += pos[i], sa += acc[i];
      sp /= 5.0, sa /= 5.0;
      Complex num = 0;
      double den = 0;
      for (std::size_t i = 0; i < ss.size(); ++i)
        num += std::conj(pos[i] - sp) * (acc[i] - sa), den += std::norm(pos[i] - sp);
      const Complex K = den > 0 ? num / den : Complex{};
      const Complex L = sa - K * sp;
      for (std::size_t i = 0; i < ss.size(); ++i) dev = std::max(dev, std::abs(K * pos[i] + L - acc[i]) / scale);
    }
  }
  const std::string what = kind == Property::globally_perseverant   ? "constant in the global frame"
                           : kind == Property::radially_perseverant ? "K (x - f) for one K and f"
                                                                    : "constant in the frame D(t)";
  return {dev,
          std::nullopt,
          even,
          std::nullopt,
          "the accelerations of p and q at s = 0.1, 0.3, 0.5, 0.7, 0.9 (even knots) are " + what,
          {},
          ""};
}

}  // namespace

std::span<const PropertyInfo> all_properties() { return kProperties; }

const PropertyInfo& info(Property property) {
  for (const PropertyInfo& p : kProperties) {
    if (p.property == property) return p;
  }
  throw std::logic_error("property missing from the table");
}

const PropertyInfo* find_property(std::string_view id) {
  for (const PropertyInfo& p : kProperties) {
    if (p.id == id) return &p;
  }
  return nullptr;
}

Arrow apply(const Similarity& S, const Arrow& A) {
  return {S.scale * std::polar(1.0, S.rotation) * A.p + S.translation, S.scale * A.m, A.w + S.rotation};
}

Probe probe(Property property, Method method, const KeyframeTriple& k, std::uint64_t seed) {
  AuditRandom r(seed);
  switch (property) {
    case Property::exists:
      return probe_exists(method, k);
    case Property::smooth:
      return probe_smooth(method, k);
    case Property::similarity_invariant:
      return probe_similarity(method, k, r);
    case Property::symmetric:
      return probe_symmetric(method, k);
    case Property::handle_invariant:
      return probe_handle(method, k, r);
    case Property::winding_aware:
      return probe_winding(method, k);
    case Property::pop_free:
      return probe_pop(method, k);
    case Property::knot_controlled:
      return probe_knots(method, k);
    case Property::order_independent:
      return probe_order(method, k);
    case Property::affine_invariant:
      return probe_affine(method, k, r);
    case Property::globally_perseverant:
    case Property::radially_perseverant:
    case Property::locally_perseverant:
      return probe_perseverant(property, method, k);
  }
  throw std::logic_error("unknown property");
}

}  // namespace pita::analysis
