#!/usr/bin/env python3
"""Independent oracle of the pose PITAs P4, P5, P6 and P9 (affine poses of the plane and of space).

Written from the papers (PITA Sec. 2.3-2.6, PITA Eqs. 9-14, 27-34, appendices C and D; SAM Sec. 2.2),
not from src/core: poses are homogeneous matrices H = [[L, b], [0, 1]] (3x3 in the plane, 4x4 in
space) in numpy, and every real power is the principal one, H^s = expm(s log H), with scipy's
expm, and log H = [[log L, v], [0, 0]] from scipy's logm of L (real_log).

    M(A, B, s)    = (B o A^-1)^s o A       steady morph (PITA Eq. 20, SAM Sec. 2.2)
    T(X, A, B, s) = (B o A^-1)^s o X       steady transport (PITA Eq. 24)

    P6  L = T(M(A, B, y + z), B, C, z),  R = T(M(C, B, x + y), B, A, x),  D = M(L, R, 1/2)
        (PITA Eq. 34; R takes the knots in the order c, b, a: docs/paper-notes.md N4)
    P9  D = M(M(A, B, q), M(B, C, r), s)                                  (PITA Eq. D.2)
    P4  Lc = T(M(A, B, 3/4), C, B, 1/4),  Rc = T(M(C, B, 3/4), A, B, 1/4)  (PITA Eq. 30-32, docs/paper-notes.md N3)
        Bezier(P0, P1, P2, s) = M(M(P0, P1, s), M(P1, P2, s), s)        (PITA Eq. 29)
        u = knot_warp(a, b, c, t); D = Bezier(A, Lc, B, 2u) if u <= 1/2
                                     else Bezier(B, Rc, C, 2u - 1)      (PITA Eq. 27-28; warp: N11, N17)
    P5  g = centroid of the poses' translations, G = translation by g;
        D = G o exp(x log(G^-1 o A) + y log(G^-1 o B) + z log(G^-1 o C))   (PITA Eq. 33, appendix C)

x, y, z are the Lagrange weights of t (PITA Eq. 10), q, r, s the Neville ratios (PITA Eq. 14).

A principal real power of H exists iff its linear part L has no eigenvalue on the closed
negative real axis (det L > 0 throughout: every pose here preserves orientation). `margin(L)`
measures how far L is from that boundary, signed: for each eigenvalue with a negative real part,
|Im l| / |l| when it is complex, minus half the relative gap to its partner when it is real
(real negative eigenvalues come in pairs when det L > 0; the two meet at the boundary). It is 1
when no eigenvalue has a negative real part. A power is refused (NoRealPower, naming the step and
the time) when margin <= 0. Within NEAR of 0 the answer depends on rounding (an eigenvalue pair
moves by ~sqrt(eps) near a double one; pita takes a half turn -rho I as the rotation by +pi,
docs/paper-notes.md N58): callers see every motion's smallest margin and may leave such cases
out. A power at exactly s = 0 or s = 1 is I or H whatever H is (A^0 = I, A^1 = A), so it is
never refused: the knots always interpolate.

A pose a construction forms at t may be lost to rounding: far outside [a, c] with close knots,
the exponents reach 70 and its small singular values fall below the rounding of the large ones.
Its determinant is known exactly (det is multiplicative: log det M(A, B, s) = (1 - s) log det A
+ s log det B), so where doubles give another one (sign, or by more than LOST relative), or the
pose cannot be inverted, the frame is refused with margin 0: a case where rounding decides.

The powers between given neighbours (and P4's controls, P5's own logs) are needed at every time:
they are checked when the motion is built (`Motion(...)` raises). The powers between poses a
construction forms (from P6's L(t) to R(t); between P9's two inner morphs; between the two inner
morphs of P4's Bezier arc) are checked at each time (`Motion.at(t)` raises).

Usage:
  pose_pita_oracle.py PITA [--count N] [--seed S]
      self-check: (a) D(a) = A, D(b) = B, D(c) = C on random affine triples in 2D and 3D;
      scipy's power against fractional_matrix_power; symmetry under time reversal (P4, P5, P6,
      P9) and affine invariance on both sides (P4, P6, P9); refusals on triples with no SAM;
      (b) on similarity triples each construction equals the ARROW PITA of the same name of the
      binary PITA (`pita eval` of arrow scenes), in the plane and embedded in space.
      Exit 0 when every check holds, 1 otherwise.
"""
import argparse
import json
import math
import os
import sys
import tempfile

import numpy as np
from scipy.linalg import expm, expm_frechet, fractional_matrix_power, logm

NEAR = 1e-6          # |margin| below this: a boundary case (rounding decides)
SINGULAR = 1e14      # a pose whose linear part has a larger condition number cannot be inverted
LOST = 1e-3          # a formed pose whose determinant doubles miss by more (relative) is lost
METHODS = ("P4", "P5", "P6", "P9")


class NoRealPower(ValueError):
    """A power the construction needs has no real principal value."""

    def __init__(self, step, t=None, margin=0.0):
        self.step, self.t, self.margin = step, t, margin
        at = "" if t is None else " at t = %r" % t
        super().__init__("no real power %s%s (margin %.3g)" % (step, at, margin))


# --------------------------------------------------------------------------- poses
def hom(P):
    """The homogeneous (n+1)x(n+1) matrix of an n x (n+1) pose [L | b]."""
    P = np.asarray(P, dtype=float)
    n = P.shape[0]
    return np.vstack([P, np.eye(n + 1)[n]])


def pose(H):
    return H[:-1, :].copy()


def translation(g):
    n = len(g)
    H = np.eye(n + 1)
    H[:n, n] = g
    return H


def margin(L):
    """Signed distance of L from having no principal real logarithm (see the module doc)."""
    ev = np.linalg.eigvals(L)
    m = 1.0
    for i, l in enumerate(ev):
        if l.real >= 0:
            continue
        if l.imag != 0:
            m = min(m, abs(l.imag) / abs(l))
        else:
            gaps = [abs(l - mu) for j, mu in enumerate(ev) if j != i and mu.imag == 0 and mu.real < 0]
            m = min(m, -min(gaps) / (2 * abs(l)) if gaps else -1.0)
    return m


def log_linear(L):
    """The principal log X of L (n x n): scipy's logm, then Newton steps on expm(X) = L with
    scipy's Frechet derivative of expm, while they shrink the residual (logm alone leaves up to
    1e-7 on non-normal L)."""
    X = logm(L, disp=False)[0]
    if np.iscomplexobj(X):
        if np.abs(X.imag).max() > 1e-9 * max(1.0, np.abs(X).max()):
            return None
        X = X.real
    n = L.shape[0]
    res = L - expm(X)
    for _ in range(3):
        r = np.abs(res).max() / np.abs(L).max()
        if r < 1e-15:
            break
        J = np.column_stack([expm_frechet(X, np.eye(n * n)[k].reshape(n, n), compute_expm=False).ravel()
                             for k in range(n * n)])
        Y = X + np.linalg.solve(J, res.ravel()).reshape(n, n)
        res_y = L - expm(Y)
        if not np.abs(res_y).max() / np.abs(L).max() < r:
            break
        X, res = Y, res_y
    return X


def real_log(H, step, t=None):
    """The principal logarithm [[X, v], [0, 0]] of H = [[L, b], [0, 1]], refused when it is not
    real: X = log L (log_linear), and v from b = phi(X) v, phi(X) = sum X^k / (k + 1)! (the
    top right block of exp([[X, I], [0, 0]])), so that exp([[X, v], [0, 0]]) = H."""
    n = H.shape[0] - 1
    L, b = H[:n, :n], H[:n, n]
    m = margin(L)
    X = None if m <= 0 else log_linear(L)
    if X is None:
        raise NoRealPower(step, t, m)
    phi = expm(np.block([[X, np.eye(n)], [np.zeros((n, 2 * n))]]))[:n, n:]
    out = np.zeros_like(H)
    out[:n, :n], out[:n, n] = X, np.linalg.solve(phi, b)
    return out, m


class Power:
    """s -> X^s for X = B o A^-1, the power of one pair of poses (SAM Sec. 2.2, SAM Eq. 1-2).

    With body=True the same morph and transport are computed in A's body frame, from
    Y = A^-1 o B: X^s = A o Y^s o A^-1 (the principal power commutes with conjugation). Both are
    the same in exact arithmetic; in doubles they round differently, which estimates the
    oracle's own error (compare_pose_pitas_with_cli.py)."""

    def __init__(self, A, B, step, t=None, body=False):
        self.A, self.body = A, body
        self.log, self.margin = None, 1.0
        n = A.shape[0] - 1
        if not np.all(np.isfinite(A)) or np.linalg.cond(A[:n, :n]) > SINGULAR:
            # a pose formed far outside [a, c] that doubles cannot invert: margin 0 marks it
            # as a case where rounding decides
            self.X, self.margin = None, 0.0
            self.error = NoRealPower(step + " (a pose numerically singular)", t, 0.0)
            return
        self.X = np.linalg.solve(A, B) if body else B @ np.linalg.inv(A)
        try:
            self.log, self.margin = real_log(self.X, step, t)
        except NoRealPower as e:
            self.error = e

    def check(self):
        if self.log is None:
            raise self.error
        return self

    def __call__(self, s):
        if s == 0:
            return np.eye(self.X.shape[0])
        if s == 1:
            return self.X
        return expm(s * self.check().log)

    def morph(self, s):                         # M(A, B, s), PITA Eq. 20
        return self.A @ self(s) if self.body else self(s) @ self.A

    def transport(self, Y, s):                  # T(Y, A, B, s), PITA Eq. 24
        return self.A @ self(s) @ np.linalg.solve(self.A, Y) if self.body else self(s) @ Y


def formed_morph(P, Q, s, step, t, trace, body=False, log_dets=None):
    """M(P, Q, s) for poses a construction formed at time t: checked at t (unless s is 0 or 1).
    trace["margin"] collects the power's margin, trace["cond"] the larger condition number of
    P's and Q's linear parts (X = Q o P^-1 is known to about eps cond), trace["norm"] the product of the sizes of
    the two factors of the morph, X^s and P (max norms). log_dets: the exact log det of P and Q
    (det is multiplicative: a formed pose's is the same combination of the given poses'); where
    doubles give P or Q another determinant (sign, or by more than LOST relative), the pose is
    lost to rounding, and the frame is refused with margin 0, a case where rounding decides."""
    n = P.shape[0] - 1
    for X, ld in zip((P, Q), log_dets or ()):
        sign, computed = np.linalg.slogdet(X[:n, :n])
        if not (sign > 0 and abs(computed - ld) <= LOST):
            raise NoRealPower(step + " (a pose lost to rounding: det %.3g, exactly %.3g)" % (
                sign * math.exp(computed) if sign else 0.0, math.exp(ld)), t, 0.0)
    if s == 0:
        return P
    if s == 1:
        return Q
    trace["cond"].append(max(np.linalg.cond(P[:n, :n]), np.linalg.cond(Q[:n, :n])))
    pw = Power(P, Q, step, t, body).check()
    trace["margin"].append(pw.margin)
    Xs = pw(s)
    trace["norm"].append(np.abs(Xs).max() * np.abs(P).max())
    return pw.A @ Xs if body else Xs @ P


def log_det(H):
    n = H.shape[0] - 1
    return np.linalg.slogdet(H[:n, :n])[1]


# --------------------------------------------------------------------------- weights
def lagrange(a, b, c, t):
    """x, y, z of PITA Eq. 10."""
    return ((t - b) * (t - c) / ((a - b) * (a - c)),
            (t - a) * (t - c) / ((b - a) * (b - c)),
            (t - a) * (t - b) / ((c - a) * (c - b)))


def neville(a, b, c, t):
    """q, r, s of PITA Eq. 14."""
    return (t - a) / (b - a), (t - b) / (c - b), (t - a) / (c - a)


def knot_warp(a, b, c, t):
    """u(a) = 0, u(b) = 1/2, u(c) = 1: quadratic on each side of b with du/ds = 1 there, linear
    beyond the ends (docs/paper-notes.md N11, N17; s = (t - a)/(c - a), beta = (b - a)/(c - a))."""
    s, beta = (t - a) / (c - a), (b - a) / (c - a)
    kappa = 2 * beta - 1

    def h(sig):
        return sig + kappa * sig * (sig - 1)

    if s < 0:
        return s * (1 - beta) / beta
    if s > 1:
        return 1 + (s - 1) * beta / (1 - beta)
    if s <= beta:
        return 0.5 * h(s / beta)
    return 0.5 + 0.5 * h((s - beta) / (1 - beta))


# --------------------------------------------------------------------------- the four PITAs
class Motion:
    """One pose PITA through poses A, B, C (n x (n+1) arrays) at knots a < b < c.

    Motion(method, poses, knots) raises NoRealPower when a power needed at every time is not
    real; at(t) returns the n x (n+1) pose or raises NoRealPower for a power formed at t.
    `margin` is the smallest margin of the powers built once, `last_margin` that of the last
    at(t) (both included); `last_growth` is how much the last at(t) magnifies rounding errors,
    for the morph M(P, Q, s) = X^s o P it formed: the larger condition number of P and Q
    (X = Q o P^-1 is known to about eps cond) times max(1, |X^s| |P| / max(1, |D|)) (max norms:
    cancellation in X^s o P); the condition number alone when the power is refused."""

    def __init__(self, method, poses, knots, body=False):
        self.body = body
        if method not in METHODS:
            raise ValueError("method %r" % method)
        self.method = method
        self.A, self.B, self.C = (hom(P) for P in poses)
        self.a, self.b, self.c = (float(k) for k in knots)
        if not self.a < self.b < self.c:
            raise ValueError("knots must increase")
        self.build_margins = []
        self.ld = [log_det(H) for H in (self.A, self.B, self.C)]
        getattr(self, "_build_" + method.lower())()
        self.margin = min(self.build_margins, default=1.0)
        self.last_margin, self.last_growth = self.margin, 1.0

    def _power(self, P, Q, step):
        pw = Power(P, Q, step, body=self.body).check()
        self.build_margins.append(pw.margin)
        return pw

    def at(self, t):
        trace, D = {"margin": [self.margin], "norm": [], "cond": []}, None
        try:
            D = pose(getattr(self, "_at_" + self.method.lower())(float(t), trace))
            return D
        finally:
            self.last_margin = min(trace["margin"])
            size = 1.0 if D is None else max(1.0, np.abs(D).max())
            self.last_growth = max(1.0, max(trace["norm"], default=1.0) / size) * max(trace["cond"], default=1.0)

    # P6, PITA Eq. 34 -------------------------------------------------------------------------------
    def _build_p6(self):
        A, B, C = self.A, self.B, self.C
        self.ab = self._power(A, B, "A to B")
        self.bc = self._power(B, C, "B to C")
        self.cb = self._power(C, B, "C to B")
        self.ba = self._power(B, A, "B to A")

    def _at_p6(self, t, trace):
        x, y, z = lagrange(self.a, self.b, self.c, t)
        L = self.bc.transport(self.ab.morph(y + z), z)       # T(M(A, B, y + z), B, C, z)
        R = self.ba.transport(self.cb.morph(x + y), x)       # T(M(C, B, x + y), B, A, x)
        ld = x * self.ld[0] + y * self.ld[1] + z * self.ld[2]   # log det of L and of R
        return formed_morph(L, R, 0.5, "between L(t) and R(t)", t, trace, self.body, (ld, ld))  # M(L, R), PITA Eq. 23

    # P9, PITA Eq. D.2 ------------------------------------------------------------------------------
    def _build_p9(self):
        self.ab = self._power(self.A, self.B, "A to B")
        self.bc = self._power(self.B, self.C, "B to C")

    def _at_p9(self, t, trace):
        q, r, s = neville(self.a, self.b, self.c, t)
        lds = ((1 - q) * self.ld[0] + q * self.ld[1], (1 - r) * self.ld[1] + r * self.ld[2])
        return formed_morph(self.ab.morph(q), self.bc.morph(r), s,
                            "between M(A, B, q) and M(B, C, r)", t, trace, self.body, lds)

    # P4, PITA Eq. 27-32 ----------------------------------------------------------------------------
    def _build_p4(self):
        A, B, C = self.A, self.B, self.C
        ab, cb = self._power(A, B, "A to B"), self._power(C, B, "C to B")
        self.Lc = cb.transport(ab.morph(0.75), 0.25)          # T(M(A, B, 3/4), C, B, 1/4)
        self.Rc = ab.transport(cb.morph(0.75), 0.25)          # T(M(C, B, 3/4), A, B, 1/4)
        la, lb, lc = self.ld
        self.arc_lds = ((la, la / 4 + lb - lc / 4, lb), (lb, lc / 4 + lb - la / 4, lc))
        self.arcs = ((self._power(A, self.Lc, "A to the control L"),
                      self._power(self.Lc, B, "the control L to B")),
                     (self._power(B, self.Rc, "B to the control R"),
                      self._power(self.Rc, C, "the control R to C")))

    def _at_p4(self, t, trace):
        u = knot_warp(self.a, self.b, self.c, t)
        arc = 0 if u <= 0.5 else 1
        (first, second), (l0, l1, l2) = self.arcs[arc], self.arc_lds[arc]
        s = 2 * u if u <= 0.5 else 2 * u - 1
        return formed_morph(first.morph(s), second.morph(s), s,      # Bezier, PITA Eq. 29
                            "between the Bezier arc's inner morphs", t, trace, self.body,
                            ((1 - s) * l0 + s * l1, (1 - s) * l1 + s * l2))

    # P5, PITA Eq. 33 and appendix C ----------------------------------------------------------------
    def _build_p5(self):
        n = self.A.shape[0] - 1
        g = (self.A[:n, n] + self.B[:n, n] + self.C[:n, n]) / 3
        self.to_g, self.from_g = translation(g), translation(-g)
        self.logs = []
        for name, P in zip("ABC", (self.A, self.B, self.C)):
            X, m = real_log(self.from_g @ P, "the log of pose " + name)
            self.logs.append(X)
            self.build_margins.append(m)

    def _at_p5(self, t, trace):
        x, y, z = lagrange(self.a, self.b, self.c, t)
        return self.to_g @ expm(x * self.logs[0] + y * self.logs[1] + z * self.logs[2])


def evaluate(method, poses, knots, times, body=False):
    """[(pose or NoRealPower, margin, growth)] at each time (Motion's last_margin, last_growth);
    the construction's refusal at every time."""
    try:
        mo = Motion(method, poses, knots, body)
    except NoRealPower as e:
        return [(e, e.margin, 1.0) for _ in times]
    out = []
    for t in times:
        try:
            out.append((mo.at(t), mo.last_margin, mo.last_growth))
        except NoRealPower as e:
            out.append((e, min(mo.margin, e.margin), mo.last_growth))
    return out


# --------------------------------------------------------------------------- random poses
def rot2(a):
    return np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])


def rot3(axis, a):
    """Rodrigues' rotation about a unit axis."""
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(a) * K + (1 - math.cos(a)) * (K @ K)


KINDS = {  # max turn of a neighbour (rad), max stretch, max shear, knot spacing range
    "tame": (1.0, 1.5, 0.2, (0.2, 2.0)),
    "wild": (math.pi, 4.0, 1.5, (0.2, 2.0)),
    "stretch": (2.0, 12.0, 0.5, (0.2, 2.0)),
    "uneven": (1.5, 2.0, 0.5, (0.02, 2.0)),
}


def random_linear(rng, n, kind, turn=None):
    """An orientation-preserving linear map R S U e^k: a rotation by at most the kind's turn (or
    by `turn`), a symmetric stretch, a unit upper triangular shear, a scale."""
    amax, smax, shear, _ = KINDS[kind]
    a = rng.uniform(-amax, amax) if turn is None else turn
    if n == 2:
        Q, R = rot2(rng.uniform(-math.pi, math.pi)), rot2(a)
    else:
        Q, R = rot3(rng.normal(size=3), rng.uniform(-math.pi, math.pi)), rot3(rng.normal(size=3), a)
    S = Q @ np.diag([math.exp(rng.uniform(-1, 1) * math.log(smax)) for _ in range(n)]) @ Q.T
    U = np.eye(n) + np.triu(rng.uniform(-shear, shear, size=(n, n)), 1)
    return math.exp(rng.uniform(-0.5, 0.5)) * R @ S @ U


def random_pose(rng, n, kind, turn=None):
    return np.hstack([random_linear(rng, n, kind, turn), rng.uniform(-3, 3, size=(n, 1))])


def random_triple(rng, n, kind, turns=(None, None)):
    """Poses A, B = A o X, C = B o Y with X, Y random poses of the kind (so a tame triple turns
    little between neighbours; `turns` fixes the turns of X and Y), and knots a < b < c."""
    A = random_pose(rng, n, "tame")
    B = pose(hom(A) @ hom(random_pose(rng, n, kind, turns[0])))
    C = pose(hom(B) @ hom(random_pose(rng, n, kind, turns[1])))
    lo, hi = KINDS[kind][3]
    a = rng.uniform(-1, 1)
    b = a + rng.uniform(lo, hi)
    c = b + rng.uniform(lo, hi)
    return [A, B, C], (a, b, c)


def sample_times(rng, knots, k=4):
    """The knots, some times inside [a, c] and a few outside (within half the span)."""
    a, b, c = knots
    w = c - a
    ts = [a, b, c, a - 0.5 * w, c + 0.5 * w, a - 0.1 * w, c + 0.2 * w]
    ts += [rng.uniform(a, c) for _ in range(k)]
    return ts


# --------------------------------------------------------------------------- self-check (a)
def rel_err(X, Y):
    return float(np.abs(np.asarray(X) - np.asarray(Y)).max() / max(1.0, np.abs(np.asarray(Y)).max()))


class Checks:
    def __init__(self):
        self.failures, self.count, self.worst = [], 0, {}

    def close(self, name, X, Y, tol, what):
        e = rel_err(X, Y)
        self.count += 1
        self.worst[name] = max(self.worst.get(name, 0.0), e)
        if not e <= tol:
            self.failures.append("%s: %s: error %.3g > %.1g" % (name, what, e, tol))

    def true(self, name, cond, what):
        self.count += 1
        if not cond:
            self.failures.append("%s: %s" % (name, what))


def check_interpolation(ck, rng, count):
    """D(a) = A, D(b) = B, D(c) = C (PITA's first property); scipy's power against
    fractional_matrix_power."""
    for n in (2, 3):
        for i in range(count):
            poses, knots = random_triple(rng, n, ("tame", "wild")[i % 2])
            for method in METHODS:
                try:
                    mo = Motion(method, poses, knots)
                except NoRealPower:
                    continue
                for P, k in zip(poses, knots):
                    try:
                        ck.close("interpolation", mo.at(k), P, 1e-10, "%s %dD at t = %r" % (method, n, k))
                    except NoRealPower as e:
                        ck.true("interpolation", False, "%s %dD refused at the knot %r: %s" % (method, n, k, e))
            H, s = hom(poses[1]) @ np.linalg.inv(hom(poses[0])), rng.uniform(-1.5, 2.5)
            try:
                pw = Power(hom(poses[0]), hom(poses[1]), "A to B").check()
            except NoRealPower:
                continue
            ck.close("power", pw(s), np.real(fractional_matrix_power(H, s)), 1e-9, "%dD s = %r" % (n, s))


def check_symmetry_and_invariance(ck, rng, count):
    """Time reversal (a, A) <-> (c, C) with t -> a + c - t for all four (the knots mirrored);
    G o D o H for G o A o H, ... for P4, P6 and P9 (the SAM's affine invariance, SAM Sec. 2.3)."""
    for n in (2, 3):
        done = 0
        while done < count:
            poses, (a, b, c) = random_triple(rng, n, "tame")
            G, Hh = hom(random_pose(rng, n, "wild")), hom(random_pose(rng, n, "wild"))
            moved = [pose(G @ hom(P) @ Hh) for P in poses]
            try:
                mos = {m: Motion(m, poses, (a, b, c)) for m in METHODS}
                rev = {m: Motion(m, poses[::-1], (-c, -b, -a)) for m in METHODS}
                inv = {m: Motion(m, moved, (a, b, c)) for m in ("P4", "P6", "P9")}
                for t in sample_times(rng, (a, b, c), 2):
                    for m in METHODS:
                        D = mos[m].at(t)
                        if mos[m].last_margin < 1e-3:
                            continue
                        ck.close("symmetry", rev[m].at(-t), D, 1e-9, "%s %dD t = %r" % (m, n, t))
                        if m in inv:
                            ck.close("invariance", inv[m].at(t), pose(G @ hom(D) @ Hh), 1e-8,
                                     "%s %dD t = %r" % (m, n, t))
            except NoRealPower:
                continue
            done += 1


def check_refusals(ck):
    """B o A^-1 = diag(-2, -1/2) (two negative eigenvalues: no SAM, SAM Sec. 5.1) refuses P4, P6,
    P9 when built; a pose with such a linear part refuses P5; R(pi - 1e-3) diag(3, 1/3) too."""
    I2 = np.hstack([np.eye(2), np.zeros((2, 1))])
    bad = np.array([[-2.0, 0, 1], [0, -0.5, 0]])
    ok = np.array([[1.0, 0.3, 2], [0, 1, 1]])
    for m in METHODS:
        poses = [I2, bad, ok] if m != "P5" else [I2, ok, bad]
        try:
            Motion(m, poses, (0, 1, 2))
            ck.true("refusal", False, "%s built through a pair with no real power" % m)
        except NoRealPower as e:
            ck.true("refusal", e.t is None and e.margin < 0, "%s: %s" % (m, e))
    near = rot2(math.pi - 1e-3) @ np.diag([3.0, 1 / 3])
    ck.true("refusal", margin(near) < 0, "R(pi - 1e-3) diag(3, 1/3) has real negative eigenvalues")
    ck.true("refusal", margin(rot2(math.pi - 1e-3)) > 0, "R(pi - 1e-3) has a real power")
    ck.true("refusal", abs(margin(-np.eye(2))) <= NEAR, "-I is on the boundary")


# --------------------------------------------------------------------------- self-check (b)
def arrow_pose(p, m, w, n):
    """The similarity x -> p + m R(w) x of an arrow; in space, rotating about z and scaling z by m."""
    if n == 2:
        return np.hstack([m * rot2(w), np.reshape(p, (2, 1))])
    L = np.zeros((3, 3))
    L[:2, :2], L[2, 2] = m * rot2(w), m
    return np.hstack([L, np.reshape([p[0], p[1], 0.0], (3, 1))])


def random_similarity_triple(rng):
    """Arrows whose neighbours turn by less than 2.5 rad, any scale ratio up to e^+-1."""
    w0 = rng.uniform(-3, 3)
    ws = [w0, w0 + rng.uniform(-2.5, 2.5)]
    ws.append(ws[1] + rng.uniform(-2.5, 2.5))
    arrows = [(rng.uniform(-4, 4, size=2), math.exp(rng.uniform(-1, 1)), w) for w in ws]
    a = rng.uniform(-1, 1)
    b = a + rng.uniform(0.3, 2)
    c = b + rng.uniform(0.3, 2)
    return arrows, (a, b, c)


def arrow_turns(method, ws, knots, t):
    """The largest |winding difference| of the steps the ARROW construction powers at time t
    (PITA Eq. 18: a twirl turns by B.w - A.w). Where it is pi or more, the pose construction's
    principal power turns the other way: another motion (windings do not carry over)."""
    wa, wb, wc = ws
    a, b, c = knots
    steps = [wb - wa, wc - wb]
    if method == "P6":
        x, y, z = lagrange(a, b, c, t)
        steps.append((wc + (x + y) * (wb - wc) + x * (wa - wb)) - (wa + (y + z) * (wb - wa) + z * (wc - wb)))
    elif method == "P9":
        q, r, _ = neville(a, b, c, t)
        steps.append((wb + r * (wc - wb)) - (wa + q * (wb - wa)))
    elif method == "P4":
        wl = wa + 0.75 * (wb - wa) + 0.25 * (wb - wc)
        wr = wc + 0.75 * (wb - wc) + 0.25 * (wb - wa)
        u = knot_warp(a, b, c, t)
        p0, p1, p2, s = (wa, wl, wb, 2 * u) if u <= 0.5 else (wb, wr, wc, 2 * u - 1)
        steps += [p1 - p0, p2 - p1, (p1 + s * (p2 - p1)) - (p0 + s * (p1 - p0))]
    return max(abs(d) for d in steps)


def arrow_scene(arrows, knots, method):
    return {"method": method, "samples": 3,
            "keyframes": [{"t": k, "p": [float(p[0]), float(p[1])], "m": m, "w": w}
                          for (p, m, w), k in zip(arrows, knots)]}


def check_against_arrow_pitas(ck, rng, pita, count, folder):
    """Each construction on similarity triples equals the arrow PITA of the same name."""
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import cli_batch  # noqa: E402

    jobs = []
    for i in range(count):
        arrows, knots = random_similarity_triple(rng)
        times = sample_times(rng, knots, 3)
        for method in METHODS:
            path = os.path.join(folder, "sim-%d-%s.json" % (i, method))
            with open(path, "w") as f:
                json.dump(arrow_scene(arrows, knots, method), f)
            jobs.append((path, method, arrows, knots, times))
    answers = cli_batch.eval_many(pita, [[p, "--t", ",".join(repr(t) for t in ts), "--format", "json"]
                                         for p, _, _, _, ts in jobs])
    G = rot3([0.3, -0.5, 0.8], 0.7)
    skipped = 0
    for (path, method, arrows, knots, times), ans in zip(jobs, answers):
        if ans.returncode != 0:
            ck.true("arrow", False, "%s: pita exit %d: %s" % (path, ans.returncode, ans.stderr.strip()))
            continue
        frames = json.loads(ans.stdout)["frames"]
        for n in (2, 3):
            poses = [arrow_pose(p, m, w, n) for p, m, w in arrows]
            Gh = np.eye(4)
            if n == 3:   # a general rotation and a translation on both sides: SAM Sec. 2.3 (2)
                Gh[:3, :3], Gh[:3, 3] = G, [1.0, -2.0, 0.5]
                if method != "P5":
                    poses = [pose(Gh @ hom(P) @ np.linalg.inv(Gh)) for P in poses]
            for t, fr, (D, mg, _) in zip(times, frames, evaluate(method, poses, knots, times)):
                if arrow_turns(method, [w for _, _, w in arrows], knots, t) > math.pi - 0.05:
                    skipped += 1     # the arrow turns by pi or more: another motion
                    continue
                if isinstance(D, NoRealPower) or mg < 1e-3:
                    ck.true("arrow " + method, False, "%s %dD t = %r: the oracle refuses or is near a "
                            "half turn (%s, margin %.3g)" % (path, n, t, D, mg))
                    continue
                E = arrow_pose(fr["p"], fr["m"], fr["w"], n)
                if n == 3 and method != "P5":
                    E = pose(Gh @ hom(E) @ np.linalg.inv(Gh))
                ck.close("arrow " + method, D, E, 1e-9, "%s %dD t = %r" % (path, n, t))
    return skipped


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("pita")
    ap.add_argument("--count", type=int, default=30)
    ap.add_argument("--seed", type=int, default=57)
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)
    ck = Checks()
    check_interpolation(ck, rng, args.count)
    check_symmetry_and_invariance(ck, rng, max(4, args.count // 3))
    check_refusals(ck)
    with tempfile.TemporaryDirectory() as folder:
        skipped = check_against_arrow_pitas(ck, rng, args.pita, args.count, folder)
    for name in sorted(ck.worst):
        print("  %-14s max relative error %.2e" % (name, ck.worst[name]))
    print("  %d frames whose arrow construction turns by pi or more left out of the arrow comparison" % skipped)
    for f in ck.failures[:30]:
        print("FAIL " + f)
    print("pose PITA oracle self-check: %d checks, %d failed" % (ck.count, len(ck.failures)))
    return 1 if ck.failures else 0


if __name__ == "__main__":
    sys.exit(main())
