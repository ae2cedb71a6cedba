#include "core/ease.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace pita {

namespace {

// CSS Easing Functions Level 1, Sec. 2.2: the named cubic Bezier easings.
constexpr std::array<NamedEase, 7> kNamedEases{{
    {"linear", Ease{EaseKind::linear}, "constant speed, y = x (the default)"},
    {"ease", Ease{EaseKind::cubic_bezier, 0.25, 0.1, 0.25, 1.0}, "CSS ease: cubic-bezier(0.25, 0.1, 0.25, 1)"},
    {"ease-in", Ease{EaseKind::cubic_bezier, 0.42, 0.0, 1.0, 1.0}, "CSS ease-in: cubic-bezier(0.42, 0, 1, 1)"},
    {"ease-out", Ease{EaseKind::cubic_bezier, 0.0, 0.0, 0.58, 1.0}, "CSS ease-out: cubic-bezier(0, 0, 0.58, 1)"},
    {"ease-in-out", Ease{EaseKind::cubic_bezier, 0.42, 0.0, 0.58, 1.0},
     "CSS ease-in-out: cubic-bezier(0.42, 0, 0.58, 1)"},
    {"sine", Ease{EaseKind::sine},
     "the chapter's sinusoidal ease-in/ease-out, (sin(pi x - pi/2) + 1)/2 (chapter Eq. 3.18)"},
    {"cubic", Ease{EaseKind::cubic}, "the chapter's cubic ease-in/ease-out, 3x^2 - 2x^3 (chapter Eq. 3.20)"},
}};

constexpr std::array<EaseFamily, 3> kFamilies{{
    {"cubic-bezier", "\"cubic-bezier(x1, y1, x2, y2)\"", "CSS cubic Bezier timing, x1 and x2 in [0, 1], y1 and y2 any"},
    {"sine", "{\"sine\": {\"k1\": K1, \"k2\": K2}}",
     "sine ease-in until k1, constant speed until k2, sine ease-out (chapter Eq. 3.19), 0 <= k1 <= k2 <= 1"},
    {"parabolic", "{\"parabolic\": {\"t1\": T1, \"t2\": T2}}",
     "constant acceleration until t1, constant speed until t2, constant deceleration "
     "(chapter Eq. 3.21-3.22), 0 <= t1 <= t2 <= 1"},
}};

std::string number(double x) {
  std::string text = std::to_string(x);
  // Trim the zeros std::to_string pads with: 0.420000 -> 0.42.
  if (text.find('.') != std::string::npos) {
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
  }
  return text;
}

void require_unit(double value, const char* name) {
  if (!(value >= 0.0 && value <= 1.0)) {
    throw std::invalid_argument(std::string(name) + " must be in [0, 1] (got " + number(value) + ")");
  }
}

// The Bezier coordinate B(s) = 3(1-s)^2 s p1 + 3(1-s) s^2 p2 + s^3 and its derivative.
double bezier(double p1, double p2, double s) {
  const double r = 1.0 - s;
  return 3.0 * r * r * s * p1 + 3.0 * r * s * s * p2 + s * s * s;
}
double bezier_slope(double p1, double p2, double s) {
  const double r = 1.0 - s;
  return 3.0 * r * r * p1 + 6.0 * r * s * (p2 - p1) + 3.0 * s * s * (1.0 - p2);
}

// chapter Eq. 3.19 as the chapter's Fig. 3.13 computes it (the printed equation
// misplaces a parenthesis in f; docs/paper-notes.md N16).
double sine_cap(double k1, double k2, double x) {
  const double f = 2.0 * k1 / kPi + (k2 - k1) + 2.0 * (1.0 - k2) / kPi;
  double s = 0.0;
  if (x < k1) {
    s = k1 * (2.0 / kPi) * (std::sin((x / k1) * kPi / 2.0 - kPi / 2.0) + 1.0);
  } else if (x < k2) {
    s = 2.0 * k1 / kPi + x - k1;
  } else if (k2 < 1.0) {
    s = 2.0 * k1 / kPi + k2 - k1 + (1.0 - k2) * (2.0 / kPi) * std::sin((x - k2) / (1.0 - k2) * kPi / 2.0);
  } else {
    return 1.0;  // k2 = 1 and x = 1: no ease-out part
  }
  return s / f;
}

// chapter Eq. 3.21-3.22 integrated: v0 = 2/(t2 - t1 + 1) (the print has t2 - t2;
// docs/paper-notes.md N16). The ease-out part is written from the end,
// 1 - v0 (1 - x)^2 / (2 (1 - t2)), so that ease(1) = 1 exactly.
double parabolic(double t1, double t2, double x) {
  const double v0 = 2.0 / (t2 - t1 + 1.0);
  if (x < t1) return v0 * x * x / (2.0 * t1);
  if (x <= t2) return v0 * (x - t1 / 2.0);
  const double r = 1.0 - x;
  return 1.0 - v0 * r * r / (2.0 * (1.0 - t2));
}

}  // namespace

std::span<const NamedEase> named_eases() { return kNamedEases; }
std::span<const EaseFamily> ease_families() { return kFamilies; }

std::optional<Ease> find_named_ease(std::string_view name) {
  for (const NamedEase& named : kNamedEases) {
    if (named.name == name) return named.ease;
  }
  return std::nullopt;
}

Ease cubic_bezier_ease(double x1, double y1, double x2, double y2) {
  require_unit(x1, "x1");
  require_unit(x2, "x2");
  if (!std::isfinite(y1)) throw std::invalid_argument("y1 must be a finite number");
  if (!std::isfinite(y2)) throw std::invalid_argument("y2 must be a finite number");
  return Ease{EaseKind::cubic_bezier, x1, y1, x2, y2};
}

Ease sine_cap_ease(double k1, double k2) {
  require_unit(k1, "k1");
  require_unit(k2, "k2");
  if (k1 > k2) {
    throw std::invalid_argument("k1 must not exceed k2 (got k1 = " + number(k1) + ", k2 = " + number(k2) + ")");
  }
  return Ease{EaseKind::sine_cap, k1, k2};
}

Ease parabolic_ease(double t1, double t2) {
  require_unit(t1, "t1");
  require_unit(t2, "t2");
  if (t1 > t2) {
    throw std::invalid_argument("t1 must not exceed t2 (got t1 = " + number(t1) + ", t2 = " + number(t2) + ")");
  }
  return Ease{EaseKind::parabolic, t1, t2};
}

double cubic_bezier_parameter(double x1, double x2, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  double lo = 0.0, hi = 1.0;
  double s = x;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double error = bezier(x1, x2, s) - x;
    if (std::abs(error) <= 1e-15) return s;
    if (error > 0.0)
      hi = s;
    else
      lo = s;
    const double slope = bezier_slope(x1, x2, s);
    double next = slope > 0.0 ? s - error / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket
    if (hi - lo <= 1e-16) return next;
    s = next;
  }
  return s;
}

double ease(const Ease& e, double x) {
  x = std::clamp(x, 0.0, 1.0);
  if (x == 0.0) return 0.0;
  if (x == 1.0) return 1.0;
  switch (e.kind) {
    case EaseKind::linear:
      return x;
    case EaseKind::cubic_bezier: {
      const double s = cubic_bezier_parameter(e.a, e.c, x);
      return bezier(e.b, e.d, s);
    }
    case EaseKind::sine:
      return 0.5 * (std::sin(kPi * x - kPi / 2.0) + 1.0);
    case EaseKind::sine_cap:
      return sine_cap(e.a, e.b, x);
    case EaseKind::parabolic:
      return parabolic(e.a, e.b, x);
    case EaseKind::cubic:
      return x * x * (3.0 - 2.0 * x);
  }
  return x;
}

std::string ease_label(const Ease& e) {
  for (const NamedEase& named : kNamedEases) {
    if (named.ease == e) return std::string(named.name);
  }
  switch (e.kind) {
    case EaseKind::cubic_bezier:
      return "cubic-bezier(" + number(e.a) + ", " + number(e.b) + ", " + number(e.c) + ", " + number(e.d) + ")";
    case EaseKind::sine_cap:
      return "sine(k1 " + number(e.a) + ", k2 " + number(e.b) + ")";
    case EaseKind::parabolic:
      return "parabolic(t1 " + number(e.a) + ", t2 " + number(e.b) + ")";
    default:
      return "linear";
  }
}

}  // namespace pita
