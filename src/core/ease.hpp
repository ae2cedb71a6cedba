// Ease functions: distance-time maps y = ease(x) of the unit interval onto
// itself with ease(0) = 0 and ease(1) = 1 (the chapter's speed control,
// Sec. 3.2.3; docs/paper-notes.md N20). Every ease shares one signature, as
// CSS's and easings.net's do, and one value type names it.
//
//   linear                      y = x
//   CSS "ease", "ease-in", "ease-out", "ease-in-out", "cubic-bezier(x1, y1, x2, y2)":
//                               the CSS Easing Functions Level 1 cubic Bezier
//                               through (0, 0), (x1, y1), (x2, y2), (1, 1), y as
//                               a function of x (x1, x2 in [0, 1]; y1, y2 any)
//   sine                        y = (sin(pi x - pi/2) + 1) / 2            (chapter Eq. 3.18)
//   sine-cap k1, k2             sine ease-in on [0, k1], constant speed on
//                               [k1, k2], sine ease-out on [k2, 1]        (chapter Eq. 3.19, N16)
//   parabolic t1, t2            constant acceleration on [0, t1], constant
//                               speed v0 = 2/(t2 - t1 + 1) on [t1, t2],
//                               constant deceleration on [t2, 1]          (chapter Eq. 3.20-3.22, N16)
//   cubic                       y = -2x^3 + 3x^2                          (chapter Eq. 3.20)
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace pita {

enum class EaseKind { linear, cubic_bezier, sine, sine_cap, parabolic, cubic };

struct Ease {
  EaseKind kind = EaseKind::linear;
  // cubic_bezier: x1, y1, x2, y2; sine_cap: k1, k2; parabolic: t1, t2.
  double a = 0.0, b = 0.0, c = 0.0, d = 0.0;
  friend bool operator==(const Ease&, const Ease&) = default;
};

// The named eases a scene may write as a bare string, in the order help and
// messages list them: "linear", "ease", "ease-in", "ease-out", "ease-in-out",
// "sine", "cubic". The parameterised families ("cubic-bezier(...)",
// {"sine": {...}}, {"parabolic": {...}}) are listed by ease_families().
struct NamedEase {
  std::string_view name;
  Ease ease;
  std::string_view meaning;
};
std::span<const NamedEase> named_eases();
std::optional<Ease> find_named_ease(std::string_view name);  // exact (lower-case) name

struct EaseFamily {
  std::string_view name;    // "cubic-bezier", "sine", "parabolic"
  std::string_view syntax;  // how a scene writes it
  std::string_view meaning;
};
std::span<const EaseFamily> ease_families();

// The eases with their parameters checked. Each throws std::invalid_argument
// naming the parameter that is out of range.
Ease cubic_bezier_ease(double x1, double y1, double x2, double y2);  // x1, x2 in [0, 1]
Ease sine_cap_ease(double k1, double k2);                            // 0 <= k1 <= k2 <= 1
Ease parabolic_ease(double t1, double t2);                           // 0 <= t1 <= t2 <= 1

// ease(x) for x in [0, 1] (x is clamped to it). Exact at 0 and 1.
double ease(const Ease& e, double x);

// "linear", "ease-in-out", "cubic-bezier(0.1, 0.2, 0.3, 0.4)",
// "sine-cap(0.3, 0.75)", "parabolic(0.2, 0.8)": for titles and legends.
std::string ease_label(const Ease& e);

// The x in [0, 1] of the cubic Bezier x(s) = 3(1-s)^2 s x1 + 3(1-s) s^2 x2 + s^3
// with x(s) = x, to 1e-14: Newton from the linear guess, safeguarded by
// bisection (x(s) is non-decreasing for x1, x2 in [0, 1]).
double cubic_bezier_parameter(double x1, double x2, double x);

}  // namespace pita
