#!/usr/bin/env python3
"""Independent oracle for the scene field "timing" (pure Python 3, standard library only).

Written from the specification of the timing field (pita eval --help, docs/paper-notes.md N16,
N20), without looking at src/core/ease.cpp, src/core/arc_length.cpp or src/core/time_warp.cpp.
The unwarped motion is pita_oracle.evaluate(method, keyframes, tau, options).

Scene field:  "timing": {"ease": E, "arc_length": "p" | "q" | "mid" (optional),
                         "per": "motion" | "span" (default "motion")}

With knots t_0 < ... < t_n, a scene time t inside [t_0, t_n] is mapped to a motion time tau in
the range [from, to] that contains it ([t_0, t_n] for per = motion, [t_i, t_{i+1}] for
per = span): x = (t - from)/(to - from), y = ease(x), and
  - without arc_length: tau = from + y (to - from);
  - with arc_length: tau is the time at which the tracked point of the unwarped motion
    (p: the arrow's start; q: its end p + m e^{iw}; mid: their midpoint) has covered the
    fraction y of its path length over [from, to].  For y outside [0, 1] (eases that
    overshoot) the signed arc length s(tau) = int_from^tau |P'| is continued beyond the range.
Outside [t_0, t_n] the motion is evaluated at t itself.

Eases: "linear"; CSS "ease", "ease-in", "ease-out", "ease-in-out" and
"cubic-bezier(x1, y1, x2, y2)"; "sine"; "cubic"; {"sine": {"k1", "k2"}} (sine cap, chapter
chapter Eq. 3.19 with the normaliser of N16); {"parabolic": {"t1", "t2"}} (chapter Eq. 3.20-3.22 with
v0 = 2/(t2 - t1 + 1), N16).

Arc length: adaptive Gauss-Legendre (12 nodes, panels halved until two levels agree to 1e-14
of the length, or to the differences' rounding noise) of the speed |P'(tau)|, P' by an
8th-order central difference of the oracle's motion with a step of 1/16 of the panel (between
2e-3/64 and 2e-3 of the knot range), one-sided within 4 steps of the knots for P4, P7, P8,
whose knot warp is only C1 there; inverted by safeguarded Newton (bisection fallback) inside
the panel holding the target.  Checked (selfcheck) against closed forms (circle, ellipse, the
log-spiral of SMA) and Richardson-extrapolated polylines, to ~1e-13 of the length.

The overshoot reading (y not clamped) is the specification's; Timing(clamp_overshoot=True) and
Timing(clamp_arc_overshoot=True) give clamped readings, for comparison only
(compare_timing_with_cli.py --clamp-overshoot / --clamp-arc-overshoot).

Run `python3 timing_oracle.py` for the self-check (exit 1 if a check fails).
"""
import cmath
import math
import os
import re
import sys
from fractions import Fraction

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pita_oracle as O  # noqa: E402


# =========================================================================== eases
def ease_linear(x):
    return x


def ease_sine(x):
    """Chapter chapter Eq. 3.18: (sin(pi x - pi/2) + 1)/2."""
    return (math.sin(math.pi * x - math.pi / 2) + 1) / 2


def ease_cubic(x):
    """3x^2 - 2x^3."""
    return 3 * x * x - 2 * x * x * x


class CubicBezier:
    """CSS cubic-bezier(x1, y1, x2, y2): the Bezier curve through (0,0), (x1,y1), (x2,y2),
    (1,1); ease(x) = y(s) where x(s) = x.  x1, x2 in [0, 1] make x(s) increasing, so s is
    found by bisection on [0, 1] to 2^-64 with exact (integer) sign tests, and y(s) is
    evaluated exactly and rounded once."""

    def __init__(self, x1, y1, x2, y2):
        if not (0 <= x1 <= 1 and 0 <= x2 <= 1):
            raise ValueError("cubic-bezier x1, x2 must be in [0, 1]")
        self.c = (x1, y1, x2, y2)

    @staticmethod
    def _b(s, p1, p2):
        r = 1 - s
        return 3 * r * r * s * p1 + 3 * r * s * s * p2 + s * s * s

    @staticmethod
    def _db(s, p1, p2):
        r = 1 - s
        return 3 * r * r * p1 + 6 * r * s * (p2 - p1) + 3 * s * s * (1 - p2)

    def _ints(self, x):
        """x1, x2, x and the y's as integers over one power-of-two denominator D."""
        fs = [Fraction(v) for v in self.c] + [Fraction(x)]
        D = 1
        for f in fs:
            D = max(D, f.denominator)  # all powers of two: the largest is their LCM
        return [f.numerator * (D // f.denominator) for f in fs], D

    def solve_s_exact(self, x, bits=64):
        """s with x(s) = x, as an integer k over 2^bits: bisection whose sign tests are
        exact (integer arithmetic on the doubles x1, x2, x), so that the answer is right to
        2^-bits even where x'(s) = 0 (x1 = 1, x2 = 0 at s = 1/2: there a double-precision
        test x(s) < x would leave s uncertain by ~eps^(1/3))."""
        (a1, _, a2, _, ax), D = self._ints(x)
        N = 1 << bits
        lo, hi = 0, N  # x(lo/N) < x <= x(hi/N)
        while hi - lo > 1:
            k = (lo + hi) >> 1
            r = N - k
            if 3 * r * r * k * a1 + 3 * r * k * k * a2 + k * k * k * D < ax * N * N * N:
                lo = k
            else:
                hi = k
        return hi, N

    def solve_s(self, x):
        if x <= 0:
            return 0.0
        if x >= 1:
            return 1.0
        k, N = self.solve_s_exact(x)
        return k / N

    def __call__(self, x):
        if x <= 0:
            return 0.0
        if x >= 1:
            return 1.0
        k, N = self.solve_s_exact(x)
        (_, b1, _, b2, _), D = self._ints(x)
        r = N - k
        # y(s) = 3 (1-s)^2 s y1 + 3 (1-s) s^2 y2 + s^3, exactly, rounded once
        return float(Fraction(3 * r * r * k * b1 + 3 * r * k * k * b2 + k * k * k * D, D * N * N * N))


CSS_NAMED = {
    "ease": (0.25, 0.1, 0.25, 1.0),
    "ease-in": (0.42, 0.0, 1.0, 1.0),
    "ease-out": (0.0, 0.0, 0.58, 1.0),
    "ease-in-out": (0.42, 0.0, 0.58, 1.0),
}


class SineCap:
    """Chapter chapter Eq. 3.19 (normaliser of N16): sine ease-in on [0, k1], constant speed on
    [k1, k2], sine ease-out on [k2, 1]; ease = s / f."""

    def __init__(self, k1, k2):
        if not (0 <= k1 <= k2 <= 1):
            raise ValueError("sine cap needs 0 <= k1 <= k2 <= 1")
        self.k1, self.k2 = k1, k2
        self.f = 2 * k1 / math.pi + (k2 - k1) + 2 * (1 - k2) / math.pi

    def __call__(self, x):
        k1, k2 = self.k1, self.k2
        if x < k1:
            s = k1 * (2 / math.pi) * (math.sin((x / k1) * math.pi / 2 - math.pi / 2) + 1)
        elif x <= k2:
            s = 2 * k1 / math.pi + x - k1
        else:
            s = 2 * k1 / math.pi + k2 - k1 + (1 - k2) * (2 / math.pi) * math.sin(
                ((x - k2) / (1 - k2)) * math.pi / 2)
        return s / self.f


class Parabolic:
    """Chapter chapter Eq. 3.20-3.22 (v0 of N16): velocity rises linearly from 0 to v0 on [0, t1],
    stays v0 on [t1, t2], falls linearly to 0 on [t2, 1]; v0 = 2/(t2 - t1 + 1) makes the area
    1.  ease is the integral of the velocity (integrated here piece by piece)."""

    def __init__(self, t1, t2):
        if not (0 <= t1 <= t2 <= 1):
            raise ValueError("parabolic needs 0 <= t1 <= t2 <= 1")
        self.t1, self.t2 = t1, t2
        self.v0 = 2 / (t2 - t1 + 1)

    def velocity(self, x):
        t1, t2, v0 = self.t1, self.t2, self.v0
        if x < t1:
            return v0 * x / t1
        if x <= t2:
            return v0
        return v0 * (1 - x) / (1 - t2)

    def __call__(self, x):
        t1, t2, v0 = self.t1, self.t2, self.v0
        if x < t1:  # int_0^x v0 u/t1 du
            return v0 * x * x / (2 * t1)
        if x <= t2:  # area of the first triangle + rectangle
            return v0 * t1 / 2 + v0 * (x - t1)
        r = 1 - x    # 1 - (area of the last triangle still ahead)
        return 1 - v0 * r * r / (2 * (1 - t2))


_NUM = r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*"
_BEZIER = re.compile(r"^\s*cubic-bezier\s*\(" + ",".join([_NUM] * 4) + r"\)\s*$")


def make_ease(spec):
    """The ease of a timing's "ease" value (string or object)."""
    if isinstance(spec, str):
        if spec == "linear":
            return ease_linear
        if spec == "sine":
            return ease_sine
        if spec == "cubic":
            return ease_cubic
        if spec in CSS_NAMED:
            return CubicBezier(*CSS_NAMED[spec])
        m = _BEZIER.match(spec)
        if m:
            return CubicBezier(*(float(g) for g in m.groups()))
        raise ValueError("unknown ease %r" % spec)
    if isinstance(spec, dict) and len(spec) == 1:
        (k, v), = spec.items()
        if k == "sine":
            return SineCap(float(v["k1"]), float(v["k2"]))
        if k == "parabolic":
            return Parabolic(float(v["t1"]), float(v["t2"]))
    raise ValueError("unknown ease %r" % (spec,))


# =========================================================================== arc length
def _gauss_legendre(n):
    """Nodes and weights on [-1, 1] (Newton on P_n from the Chebyshev guesses)."""
    xs, ws = [], []
    for i in range(1, n + 1):
        x = math.cos(math.pi * (i - 0.25) / (n + 0.5))
        for _ in range(100):
            p0, p1 = 1.0, x
            for k in range(2, n + 1):
                p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
            dp = n * (x * p1 - p0) / (x * x - 1)
            dx = p1 / dp
            x -= dx
            if abs(dx) < 1e-16:
                break
        p0, p1 = 1.0, x
        for k in range(2, n + 1):
            p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
        dp = n * (x * p1 - p0) / (x * x - 1)
        xs.append(x)
        ws.append(2 / ((1 - x * x) * dp * dp))
    return xs, ws


GL_X, GL_W = _gauss_legendre(12)
# first derivative, 8th-order central difference (offsets 1..4)
FD8 = (4 / 5, -1 / 5, 4 / 105, -1 / 280)
# first derivative, 8th-order one-sided difference (offsets 0..8)
FD8_ONE_SIDED = (-761 / 280, 8.0, -14.0, 56 / 3, -35 / 2, 56 / 5, -14 / 3, 8 / 7, -1 / 8)


def derivative(f, u, h, breaks=()):
    """f'(u) for a complex-valued f of a real time, by an 8th-order difference with step h;
    where a central stencil would straddle one of the breaks (times where f is only C1, e.g.
    the knots of the P4/P7/P8 knot warp), a one-sided stencil on u's side of it."""
    side = 0
    for b in breaks:
        if abs(u - b) < 4 * h:
            side = 1 if u >= b else -1
            break
    if side == 0:
        d = 0j
        for k, c in enumerate(FD8, 1):
            d += c * (f(u + k * h) - f(u - k * h))
        return d / h
    d = 0j
    for k, c in enumerate(FD8_ONE_SIDED):
        d += c * f(u + side * k * h)
    return side * d / h


class Unreachable(ArithmeticError):
    """An ease value outside [0, 1] asks for more length beyond the range than the path has
    (within the distance searched): the warp is undefined there."""


class ArcLength:
    """Signed arc length s(tau) = int_lo^tau |P'(u)| du of a planar path P (complex-valued
    function of a real time) and its inverse.

    Panels: a panel [a, b] is accepted when its 12-node Gauss-Legendre length agrees with the
    sum over its halves to rtol of the whole length, or to the rounding noise the finite
    differences put into that panel (NOISE * eps * max|P| * width / step), whichever is larger.
    The speed on a panel of width W is taken with the step min(hmax, W * HREL) (not below
    hmax / 64: smaller steps turn the motion's rounding, a few ulps of its largest
    intermediate terms, into a bias of the speed), so that a panel refined around a narrow
    burst of speed also refines its derivative.  breaks: times where P is only C1 (one-sided
    stencils there, and no panel straddles them)."""

    HREL = 1.0 / 16
    NOISE = 16.0
    # beyond the range, steps of 1/8 of its width: at most 32 widths
    MAX_EXTENSION_STEPS = 256

    def __init__(self, P, lo, hi, hmax, breaks=(), rtol=1e-14):
        self.P, self.lo, self.hi, self.hmax = P, lo, hi, hmax
        self.breaks = tuple(breaks)
        self.rtol = rtol
        self.calls = 0
        n0 = 8
        edges = [lo + (hi - lo) * k / n0 for k in range(n0)] + [hi]
        edges = sorted(set(edges + [b for b in self.breaks if lo < b < hi]))
        rough = sum(self.gl(a, b) for a, b in zip(edges, edges[1:]))
        self.atol = max(rough, 1e-300) * rtol
        self.pmax = max(abs(P(lo + (hi - lo) * k / 64)) for k in range(65))
        self.panels = []  # (a, b, s(a), length of [a, b])
        s = 0.0
        for a, b in zip(edges, edges[1:]):
            for pa, pb, pl in self._adapt(a, b, self.gl(a, b), 0):
                self.panels.append((pa, pb, s, pl))
                s += pl
        self.length = s

    def step(self, a, b):
        return min(self.hmax, max(self.hmax / 256, abs(b - a) * self.HREL))

    def speed(self, u, h=None):
        self.calls += 1
        return abs(derivative(self.P, u, self.hmax if h is None else h, self.breaks))

    def gl(self, a, b, h=None):
        """Gauss-Legendre length of [a, b], speeds with step h (default: the panel's own)."""
        if h is None:
            h = self.step(a, b)
        c, r = 0.5 * (a + b), 0.5 * (b - a)
        return r * sum(w * self.speed(c + r * x, h) for x, w in zip(GL_X, GL_W))

    def _adapt(self, a, b, whole, depth):
        m = 0.5 * (a + b)
        left, right = self.gl(a, m), self.gl(m, b)
        noise = self.NOISE * 2.2e-16 * self.pmax * (b - a) / self.step(a, m)
        if abs(left + right - whole) <= max(self.atol, noise) or depth > 30:
            return [(a, m, left), (m, b, right)]
        return self._adapt(a, m, left, depth + 1) + self._adapt(m, b, right, depth + 1)

    def s(self, tau):
        """Arc length from lo to tau (tau in [lo, hi])."""
        for a, b, s0, pl in self.panels:
            if tau <= b:
                return s0 + self.gl(a, tau, self.step(a, b)) if tau > a else s0
        return self.length

    def _solve(self, a, b, base, target):
        """tau in the accepted panel [a, b] with base + int_a^tau |P'| = target (the length
        is nondecreasing in tau): Newton safeguarded by bisection."""
        h = self.step(a, b)
        lo, hi = a, b
        span = b - a
        whole = self.gl(a, b, h)
        tau = a + span * min(1.0, max(0.0, (target - base) / max(whole, 1e-300)))
        for _ in range(200):
            f = base + self.gl(a, tau, h) - target
            if f > 0:
                hi = tau
            else:
                lo = tau
            sp = self.speed(tau, h)
            nt = tau - f / sp if sp > 0 else 0.5 * (lo + hi)
            if not (lo <= nt <= hi):
                nt = 0.5 * (lo + hi)
            if abs(nt - tau) <= 1e-15 * max(abs(tau), span) or hi - lo <= 4e-16 * max(abs(tau), span):
                return nt
            tau = nt
        return tau

    def invert(self, frac):
        """tau where the path has covered frac of its length over [lo, hi] (frac may leave
        [0, 1]: the signed length is continued beyond lo or hi)."""
        target = frac * self.length
        if frac == 0:
            return self.lo
        if frac == 1:
            return self.hi
        if 0 < frac < 1:
            for a, b, s0, pl in self.panels:
                if target <= s0 + pl:
                    return self._solve(a, b, s0, target)
            return self.hi
        # beyond the range: the signed length continued past hi (frac > 1) or lo (frac < 0),
        # in adaptive panels cached per side
        direction = 1 if frac > 1 else -1
        need = (frac - 1) * self.length if frac > 1 else -frac * self.length
        panels = self._extension(direction, need)
        for pa, pb, c0, pl in panels:
            if need <= c0 + pl:
                if direction > 0:  # c0: length from hi to pa
                    return self._solve(pa, pb, c0, need)
                # c0: length from pb to lo; tau in [pa, pb] with int_tau^pb = need - c0
                return self._solve(pa, pb, 0.0, pl - (need - c0))
        raise Unreachable("arc length beyond the range not reached")

    def _extension(self, direction, need):
        """Panels beyond hi (direction 1) or lo (-1), each (a, b, length between the range's
        end and the panel's near side, panel length), covering at least `need`."""
        if not hasattr(self, "_ext"):
            self._ext = {1: [], -1: []}
        panels = self._ext[direction]
        w = (self.hi - self.lo) / 8
        recent = []  # length of the last few steps
        for _ in range(self.MAX_EXTENSION_STEPS):
            covered = panels[-1][2] + panels[-1][3] if panels else 0.0
            if covered >= need:
                return panels
            # a path that slows down geometrically (a spiral closing on its centre) has a
            # finite length beyond the end: the fraction is never reached
            if len(recent) >= 8 and sum(recent[-8:]) < 1e-3 * (need - covered):
                break
            if direction > 0:
                a = panels[-1][1] if panels else self.hi
                parts = self._adapt(a, a + w, self.gl(a, a + w), 0)
            else:
                b = panels[-1][0] if panels else self.lo
                parts = reversed(self._adapt(b - w, b, self.gl(b - w, b), 0))
            step = 0.0
            for pa, pb, pl in parts:
                panels.append((pa, pb, covered, pl))
                covered += pl
                step += pl
            recent.append(step)
        raise Unreachable("the path's length beyond the range stays below %.17g of its length "
                          "over the range" % (need / self.length))


# =========================================================================== the warp
WARPED = {"P4", "P7", "P8"}
TRACKED = {
    "p": lambda D: D[0],
    "q": lambda D: O.endpoint(D),
    "mid": lambda D: D[0] + O.vec(D) / 2,
}


class Timing:
    """The time warp of a scene: tau(t) for the motion (method, keyframes, options) of
    pita_oracle, keyframes = [(t_i, (p, m, w)), ...]."""

    def __init__(self, method, keyframes, options, timing, clamp_overshoot=False,
                 clamp_arc_overshoot=False):
        self.method, self.kf, self.options = method, keyframes, options
        # Alternative readings, for comparison only (the specification clamps nothing):
        # clamp_overshoot clamps y = ease(x) to [0, 1] always, clamp_arc_overshoot only with
        # arc_length (the fraction of the length).
        self.clamp_overshoot = clamp_overshoot
        self.clamp_arc_overshoot = clamp_arc_overshoot
        self.knots = [k for k, _ in keyframes]
        self.ease = make_ease(timing["ease"])
        self.arc = timing.get("arc_length")
        if self.arc is not None and self.arc not in TRACKED:
            raise ValueError("arc_length %r" % self.arc)
        self.per = timing.get("per", "motion")
        if self.per not in ("motion", "span"):
            raise ValueError("per %r" % self.per)
        self._arcs = {}
        # FD step: 2e-3 of the whole knot range
        self.h = 2e-3 * (self.knots[-1] - self.knots[0])
        # P4, P7, P8 go through the knot warp (pita_oracle.warp), only C1 at the knots
        self.breaks = tuple(self.knots) if method in WARPED else ()

    def motion(self, tau):
        return O.evaluate(self.method, self.kf, tau, self.options)

    def tracked(self, tau):
        return TRACKED[self.arc](self.motion(tau))

    def range_of(self, t):
        ks = self.knots
        if self.per == "motion":
            return ks[0], ks[-1]
        for a, b in zip(ks, ks[1:]):
            if t < b:
                return a, b
        return ks[-2], ks[-1]

    def arc_length(self, lo, hi):
        key = (lo, hi)
        if key not in self._arcs:
            self._arcs[key] = ArcLength(self.tracked, lo, hi, self.h, self.breaks)
        return self._arcs[key]

    def tau(self, t):
        ks = self.knots
        if t < ks[0] or t > ks[-1]:
            return t
        lo, hi = self.range_of(t)
        return self.tau_of_x(lo, hi, (t - lo) / (hi - lo))

    def tau_of_x(self, lo, hi, x):
        """The motion time for the fraction x of the range [lo, hi]."""
        y = self.ease(x)
        if self.clamp_overshoot or (self.clamp_arc_overshoot and self.arc is not None):
            y = min(1.0, max(0.0, y))
        if self.arc is None:
            return lo + y * (hi - lo)
        return self.arc_length(lo, hi).invert(y)

    def evaluate(self, t):
        """The arrow (p, m, w) printed for scene time t."""
        return self.motion(self.tau(t))


def evaluate(method, keyframes, t, options=None, timing=None):
    if not timing:
        return O.evaluate(method, keyframes, t, options)
    return Timing(method, keyframes, options, timing).evaluate(t)


# =========================================================================== self-check
class _HalfStep(ArcLength):
    HREL = ArcLength.HREL / 2


def selfcheck():
    """Returns a list of (name, error, tolerance)."""
    import random
    rng = random.Random(11)
    res = []

    def check(name, err, tol):
        res.append((name, err, tol))

    all_eases = ["linear", "ease", "ease-in", "ease-out", "ease-in-out", "sine", "cubic",
                 "cubic-bezier(0.3, 1.4, 0.7, -0.4)", "cubic-bezier(0, 0, 1, 1)",
                 {"sine": {"k1": 0.2, "k2": 0.7}}, {"sine": {"k1": 0.5, "k2": 0.5}},
                 {"parabolic": {"t1": 0.2, "t2": 0.7}}, {"parabolic": {"t1": 0, "t2": 1}},
                 {"parabolic": {"t1": 0.5, "t2": 0.5}}]
    for e in all_eases:
        f = make_ease(e)
        check("ease(0) = 0  %s" % (e,), abs(f(0.0)), 0.0)
        check("ease(1) = 1  %s" % (e,), abs(f(1.0) - 1), 4e-16)
        # continuity near 0 and 1
        check("ease continuous at 0, 1  %s" % (e,),
              max(abs(f(1e-12)), abs(f(1 - 1e-12) - 1)), 1e-5)
    check("sine(0.25) = 0.1464466", abs(ease_sine(0.25) - 0.1464466094067262), 1e-15)
    check("sine(0.5) = 0.5", abs(ease_sine(0.5) - 0.5), 1e-16)
    check("sine(0.75) = 0.8535534", abs(ease_sine(0.75) - 0.8535533905932737), 1e-15)
    check("cubic(0.25) = 0.15625", abs(ease_cubic(0.25) - 0.15625), 0.0)
    sc = SineCap(0.5, 0.5)
    pb = Parabolic(0.5, 0.5)
    lin = make_ease({"parabolic": {"t1": 0, "t2": 1}})
    cb_lin = make_ease("cubic-bezier(0, 0, 1, 1)")
    e_sc, e_pb, e_lin, e_cbl = 0.0, 0.0, 0.0, 0.0
    for i in range(1001):
        x = i / 1000
        e_sc = max(e_sc, abs(sc(x) - ease_sine(x)))
        ref = 2 * x * x if x < 0.5 else 1 - 2 * (1 - x) ** 2
        e_pb = max(e_pb, abs(pb(x) - ref))
        e_lin = max(e_lin, abs(lin(x) - x))
    # cubic-bezier(0, 0, 1, 1): x(s) = y(s), so ease(x) = x
    for i in range(1001):
        x = i / 1000
        e_cbl = max(e_cbl, abs(cb_lin(x) - x))
    check("sine-cap(0.5, 0.5) == sine", e_sc, 1e-15)
    check("parabolic(0.5, 0.5) == 2x^2 | 1 - 2(1-x)^2", e_pb, 2e-16)
    check("parabolic(0, 1) == linear", e_lin, 2e-16)
    check("cubic-bezier(0, 0, 1, 1) == linear", e_cbl, 1e-15)
    # CSS reference values: ease-in-out is symmetric; "ease" at 0.5 is 0.80240338758485699
    # (mpmath.findroot at 30 digits)
    eio = make_ease("ease-in-out")
    check("ease-in-out symmetric", max(abs(eio(x) + eio(1 - x) - 1) for x in (0.1, 0.3, 0.45)), 1e-15)
    check("ease(0.5) = 0.80240338758 (CSS)", abs(make_ease("ease")(0.5) - 0.80240338758485699), 1e-15)
    # bezier: x(s(x)) = x
    for spec in ("ease", "ease-in", "ease-out", "cubic-bezier(0.9, -0.5, 0.1, 1.5)",
                 "cubic-bezier(0, 1, 1, 0)"):
        f = make_ease(spec)
        worst = 0.0
        for i in range(1, 200):
            x = i / 200
            s = f.solve_s(x)
            worst = max(worst, abs(CubicBezier._b(s, f.c[0], f.c[2]) - x))
        check("bezier x(s(x)) = x  %s" % spec, worst, 4e-16)
    # x1 = 1, x2 = 0: x'(s) = 0 at s = 1/2, so ease(1/2) = y(1/2) exactly
    f = make_ease("cubic-bezier(1, -0.203783, 0, 0.631073)")
    check("bezier with x'(1/2) = 0: ease(0.5) = 0.375 (y1 + y2) + 0.125",
          abs(f(0.5) - (0.375 * (-0.203783 + 0.631073) + 0.125)), 1e-16)
    # C1 joins and monotonicity of sine cap / parabolic (numerical derivative across joins)
    for f, joins in ((SineCap(0.2, 0.7), (0.2, 0.7)), (SineCap(0.35, 0.35), (0.35,)),
                     (Parabolic(0.2, 0.7), (0.2, 0.7)), (Parabolic(0.4, 0.4), (0.4,))):
        h = 1e-6
        worst = 0.0
        for j in joins:
            dl = (f(j) - f(j - h)) / h
            dr = (f(j + h) - f(j)) / h
            worst = max(worst, abs(dl - dr))
        check("C1 joins %s%s" % (type(f).__name__, joins), worst, 1e-5)
    # parabolic: area under the velocity is 1 (midpoint rule, piecewise linear -> exact-ish)
    P = Parabolic(0.15, 0.6)
    n = 20000
    area = sum(P.velocity((i + 0.5) / n) for i in range(n)) / n
    check("parabolic velocity area = 1", abs(area - 1), 1e-8)

    # arc length: circle R e^{i u}: length R (hi - lo); inversion: tau = lo + y (hi - lo)
    R = 2.5
    A = ArcLength(lambda u: 3 + 1j + R * cmath.exp(1j * u), -0.3, 4.0, 1e-2)
    check("arc length of a circle (relative)", abs(A.length - R * 4.3) / (R * 4.3), 1e-12)
    worst = 0.0
    for y in (0.0, 0.1, 0.37, 0.5, 0.9, 1.0, 1.3, -0.2):
        worst = max(worst, abs(A.invert(y) - (-0.3 + y * 4.3)))
    check("arc length inverse on a circle (incl. y outside [0,1])", worst, 1e-12)
    # an ellipse quarter against its elliptic integral (arithmetic-geometric mean form)
    a_, b_ = 3.0, 1.2
    E = ArcLength(lambda u: complex(a_ * math.cos(u), b_ * math.sin(u)), 0.0, 2 * math.pi, 1e-2)
    # perimeter = 2 pi (a^2 - sum_n 2^(n-1) c_n^2) / AGM(a, b), c_0^2 = a^2 - b^2
    x0, y0, ssum, pw = a_, b_, 0.0, 0.5
    c2 = a_ * a_ - b_ * b_
    ssum = 0.5 * c2
    for _ in range(30):
        x1, y1 = (x0 + y0) / 2, math.sqrt(x0 * y0)
        c2 = ((x0 - y0) / 2) ** 2
        pw *= 2
        ssum += pw * c2
        x0, y0 = x1, y1
    perim = 2 * math.pi * (a_ * a_ - ssum) / x0
    check("arc length of an ellipse (relative)", abs(E.length - perim) / perim, 1e-12)
    # SMA: the origin moves on a log spiral with |p'| = |L| |d| e^{t Re L} / |e^L - 1|
    for _ in range(20):
        Aa = (complex(rng.uniform(-3, 3), rng.uniform(-3, 3)), math.exp(rng.uniform(-1.5, 1.5)),
              rng.uniform(-4, 4))
        Bb = (complex(rng.uniform(-3, 3), rng.uniform(-3, 3)), math.exp(rng.uniform(-1.5, 1.5)),
              rng.uniform(-4, 4))
        t0, t1 = rng.uniform(-1, 1), 0
        t1 = t0 + rng.uniform(0.2, 3)
        kf = [(t0, Aa), (t1, Bb)]
        T = O.Twirl(Aa, Bb)
        k = abs(T.L) * abs(T.d) / abs(T.den) / (t1 - t0)
        lr = T.lr / (t1 - t0)

        def s_exact(u):  # int_t0^u of k e^{(v - t0) lr} dv
            return k * (u - t0) if abs(lr) < 1e-14 else k * math.expm1((u - t0) * lr) / lr

        tm = Timing("SMA", kf, None, {"ease": "linear", "arc_length": "p"})
        Al = tm.arc_length(t0, t1)
        L = s_exact(t1)
        check("SMA log-spiral arc length (relative)", abs(Al.length - L) / L, 1e-11)
        y = rng.uniform(0.05, 0.95)
        tau = Al.invert(y)
        check("SMA log-spiral arc inverse: s(tau)/L - y", abs(s_exact(tau) / L - y), 1e-11)
    # optional cross-check with mpmath's tanh-sinh quadrature on a P6 path
    try:
        import mpmath
    except ImportError:
        mpmath = None
    if mpmath is not None:
        kf = [(0.0, (0j, 1.0, 0.4)), (0.37, (3 + 1.5j, 0.6, 2.0)), (1.2, (6 + 0j, 1.2, 3.5))]
        for arc in ("p", "q", "mid"):
            tm = Timing("P6", kf, None, {"ease": "linear", "arc_length": arc})
            Al = tm.arc_length(0.0, 1.2)
            # mpmath with its own derivative (mpmath.diff on a float function is not
            # meaningful): Richardson-free 4th-order difference with a different step
            h = 1e-3

            def sp(u, h=h):
                u = float(u)
                d = (-tm.tracked(u + 2 * h) + 8 * tm.tracked(u + h) - 8 * tm.tracked(u - h)
                     + tm.tracked(u - 2 * h)) / (12 * h)
                return abs(d)
            mpmath.mp.dps = 20
            ref = float(mpmath.quad(sp, [0.0, 0.37, 0.8, 1.2]))
            check("P6 arc length %s vs mpmath.quad (4th-order fd, rel.)" % arc,
                  abs(Al.length - ref) / ref, 1e-9)
    # speed by finite differences: halving the step changes the length by < 1e-13
    kf = [(0.0, (0j, 1.0, 0.4)), (0.5, (3 + 1.5j, 0.6, 2.0 + 6.28)), (1.0, (6 + 0j, 1.2, 3.5))]
    for arc in ("p", "q", "mid"):
        tm = Timing("P6", kf, None, {"ease": "linear", "arc_length": arc})
        L1 = ArcLength(tm.tracked, 0.0, 1.0, tm.h).length
        L2 = _HalfStep(tm.tracked, 0.0, 1.0, tm.h / 2).length
        check("fd step h vs h/2, P6 %s (rel.)" % arc, abs(L1 - L2) / L1, 1e-12)
    # P4 (C1 at its middle knot): one-sided differences there; length vs a fine polyline
    # with Richardson extrapolation (chord sums have an error series in h^2, h^4, ... on
    # each smooth piece)
    kfu = [(0.0, (0j, 1.0, 0.4)), (0.3, (3 + 1.5j, 0.6, 2.0)), (1.0, (6 + 0j, 1.2, 3.5))]
    for meth in ("P4", "P7", "P8"):
        tm = Timing(meth, kfu, None, {"ease": "linear", "arc_length": "q"})
        L1 = tm.arc_length(0.0, 1.0).length

        def chords(lo, hi, n):
            pts = [tm.tracked(lo + (hi - lo) * i / n) for i in range(n + 1)]
            return sum(abs(y - x) for x, y in zip(pts, pts[1:]))

        def romberg(lo, hi):
            row = [chords(lo, hi, 64 * 2 ** k) for k in range(6)]
            for j in range(1, 6):
                row = [(4 ** j * row[i + 1] - row[i]) / (4 ** j - 1) for i in range(len(row) - 1)]
            return row[-1]
        ref = romberg(0.0, 0.3) + romberg(0.3, 1.0)
        check("%s arc length q (C1 knot) vs Richardson polyline (rel.)" % meth,
              abs(L1 - ref) / ref, 1e-11)
    # a narrow burst of speed (P9, midpoint path, speed ~50x its mean over ~1% of the range):
    # panels must refine their finite-difference step with their width
    kfb = [(-0.36633230502602787, (7.023321047092342 + 4.626663741312174j, 3.4181310047286506,
                                   10.467103140292604 - 4 * math.pi)),
           (0.9426015482095127, (9.441226174668213 + 4.478595012657974j, 1.4557645975659819,
                                 4.05372235475599 - 2 * math.pi)),
           (1.497209479123986, (9.435061406598933 + 9.429802497570588j, 1.1005130578067275,
                                1.3949336661382823))]
    tm = Timing("P9", kfb, None, {"ease": "linear", "arc_length": "mid"})
    lo, hi = kfb[0][0], kfb[-1][0]
    Lb = tm.arc_length(lo, hi).length
    pts = [tm.tracked(lo + (hi - lo) * i / 65536) for i in range(65537)]
    row = [sum(abs(pts[(i + 1) * st] - pts[i * st]) for i in range(65536 // st))
           for st in (32, 16, 8, 4, 2, 1)]
    for j in range(1, 6):
        row = [(4 ** j * row[i + 1] - row[i]) / (4 ** j - 1) for i in range(len(row) - 1)]
    check("P9 narrow burst of speed: length vs Richardson polyline (rel.)",
          abs(Lb - row[-1]) / row[-1], 1e-10)
    # warp: at knots tau = t; per span: knots are fixed points; outside: identity
    kf = [(0.0, (0j, 1.0, 0.4)), (0.3, (3 + 1.5j, 0.6, 2.0)), (1.0, (6 + 0j, 1.2, 3.5))]
    worst = 0.0
    for per in ("motion", "span"):
        for arc in (None, "p", "q", "mid"):
            tmg = {"ease": "ease-in-out", "per": per}
            if arc:
                tmg["arc_length"] = arc
            tm = Timing("P6", kf, None, tmg)
            for t in (0.0, 1.0, -0.5, 1.7) + ((0.3,) if per == "span" else ()):
                worst = max(worst, abs(tm.tau(t) - t))
    check("warp fixes the end knots (span: every knot), identity outside", worst, 1e-13)
    # arc-length warp with a linear ease: equal scene-time steps cover equal lengths
    tm = Timing("P6", kf, None, {"ease": "linear", "arc_length": "mid"})
    Al = tm.arc_length(0.0, 1.0)
    worst = 0.0
    for t in (0.1, 0.25, 0.5, 0.8):
        worst = max(worst, abs(Al.s(tm.tau(t)) / Al.length - t))
    check("linear + arc length: s(tau(t)) = t L", worst, 1e-12)
    return res


if __name__ == "__main__":
    results = selfcheck()
    bad = 0
    for name, err, tol in results:
        ok = err <= tol
        bad += not ok
        print("%-4s %-62s %.2e (tol %.0e)" % ("ok" if ok else "FAIL", name[:62], err, tol))
    print("%d checks, %d failing" % (len(results), bad))
    sys.exit(1 if bad else 0)
