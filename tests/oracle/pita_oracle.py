#!/usr/bin/env python3
"""Independent oracle for the pita CLI (pure Python 3, standard library only).

Written from the PITA paper (see docs/paper-notes.md; with the corrections of its
sections N1-N16) and the choices documented in docs/reference/methods.md, without looking at
src/core.  Points and vectors are complex numbers.

An arrow is a tuple (p, m, w): origin p (complex), magnitude m > 0, winding w (any real).
Its vector is m e^{iw}, its end point q = p + m e^{iw}.

Methods: P1 P2 P3 P4 P5 P6 P7 P8 P9 P10 SMA.  Entry point: evaluate(method, keyframes, t)
with keyframes = [(t_i, (p_i, m_i, w_i)), ...]; returns an arrow (p, m, w).
"""
import cmath
import math

# docs/reference/methods.md "Choices where the papers leave one": phi_t = t when |e^L - 1| < 1e-12.
TWIRL_EPS = 1e-12
# docs/reference/methods.md (P2): fall back to the parabola when b nearly coincides with a or c (relative 1e-12).
P2_EPS = 1e-12


# --------------------------------------------------------------------------- helpers
# Largest magnitude of a term summed while evaluating the last frame (see evaluate()): the
# rounding error of a frame is a few ulps of it, which the comparison uses as its floor.
_SCALE = [0.0]


def _track(*vals):
    m = max(vals)
    if m > _SCALE[0] or m != m:
        _SCALE[0] = m


def last_intermediate_scale():
    return _SCALE[0]


def cexpm1(z):
    """e^z - 1 for complex z, accurate near 0 (cmath has no expm1)."""
    x, y = z.real, z.imag
    em1 = math.expm1(x)
    s = math.sin(0.5 * y)
    re = em1 * math.cos(y) - 2.0 * s * s
    im = math.exp(x) * math.sin(y)
    return complex(re, im)


def vec(A):
    return A[1] * cmath.exp(1j * A[2])


def endpoint(A):
    return A[0] + vec(A)


def principal(w):
    """Angle in (-pi, pi]."""
    if -math.pi < w <= math.pi:
        return w
    r = math.remainder(w, 2 * math.pi)
    if r <= -math.pi:
        r += 2 * math.pi
    return r


def arrow_from_vector(p, v):
    """Zero-turn arrow with origin p and vector v (principal angle)."""
    return (p, abs(v), cmath.phase(v))


# --------------------------------------------------------------------------- PITA Eq. 10, 14
def lagrange_weights(a, b, c, t):
    """x, y, z of PITA Eq. 10."""
    x = (t - b) / (a - b) * (t - c) / (a - c)
    y = (t - a) / (b - a) * (t - c) / (b - c)
    z = (t - a) / (c - a) * (t - b) / (c - b)
    return x, y, z


# --------------------------------------------------------------------------- twirls (PITA Eq. 5-8, 17-19)
class Twirl:
    """The twirl T_{A,B} mapping arrow A onto arrow B (PITA Eq. 17-19, docs/paper-notes.md N1).

    L = ln(B.m/A.m) + i (B.w - A.w); T^t x = A.p + e^{tL}(x - A.p) + phi_t (B.p - A.p),
    phi_t = expm1(tL)/expm1(L), or t when |e^L - 1| < TWIRL_EPS (docs/reference/methods.md).
    """

    def __init__(self, A, B):
        self.o = A[0]
        self.d = B[0] - A[0]
        self.lr = math.log(B[1] / A[1])
        self.li = B[2] - A[2]
        self.L = complex(self.lr, self.li)
        self.den = cexpm1(self.L)
        self.fallback = abs(self.den) < TWIRL_EPS

    def phi(self, t):
        if self.fallback:
            return t
        return cexpm1(t * self.L) / self.den

    def point(self, x, t):
        rot = cmath.exp(t * self.L) * (x - self.o)
        tr = self.phi(t) * self.d
        _track(abs(self.o), abs(rot), abs(tr))
        return self.o + rot + tr

    def arrow(self, X, t):
        """T^t . X (PITA Eq. 7)."""
        return (self.point(X[0], t), X[1] * math.exp(t * self.lr), X[2] + t * self.li)


def _mean_factor(r, t, mean):
    """Weighted mean of 1 and r with weights 1-t, t, divided by 1 (Sec. 2.7)."""
    if mean == "geometric":
        return r ** t
    if mean == "arithmetic":
        return (1 - t) + t * r
    if mean == "harmonic":
        return 1.0 / ((1 - t) + t / r)
    raise ValueError(mean)


def sma(A, B, t, path_mean="geometric", magnitude_mean="geometric"):
    """Steady morph M(A, B, t) (PITA Eq. 20); with path_mean/magnitude_mean other than
    geometric, the non-steady WAM/WHM variants of Sec. 2.7: the origin keeps turning
    about the twirl's fixed point f by t*w, but its distance to f is the weighted mean of
    |A.p - f| and |B.p - f|; the magnitude is the weighted mean of A.m and B.m.
    Written without f: p(t) = A.p + (e^{itw} g(t) - 1)/(lam - 1) (B.p - A.p)."""
    if path_mean == "geometric" and magnitude_mean == "geometric":
        return Twirl(A, B).arrow(A, t)
    T = Twirl(A, B)
    r = B[1] / A[1]
    if T.fallback:
        p = A[0] + t * T.d
    else:
        # e^{itw} g(t) - 1 = expm1(itw + ln g): ln g by log1p keeps it exact near lam = 1
        if path_mean == "geometric":
            lg = t * T.lr
        elif path_mean == "arithmetic":
            x = t * math.expm1(T.lr)          # g = 1 + t (r - 1)
            lg = math.log1p(x) if x > -1 else None
        elif path_mean == "harmonic":
            x = t * math.expm1(-T.lr)         # 1/g = 1 + t (1/r - 1)
            lg = -math.log1p(x) if x > -1 else None
        else:
            raise ValueError(path_mean)
        if lg is None:  # g <= 0: the origin crosses the fixed point
            num = cmath.exp(1j * t * T.li) * _mean_factor(r, t, path_mean) - 1
        else:
            num = cexpm1(complex(lg, t * T.li))
        p = A[0] + num / T.den * T.d
    m = A[1] * _mean_factor(r, t, magnitude_mean)
    return (p, m, A[2] + t * T.li)


def sta(X, A, B, t):
    """Steady transport T(X, A, B, t) = T_{A,B}^t . X (PITA Eq. 24)."""
    return Twirl(A, B).arrow(X, t)


def steady_average(A, B):
    return sma(A, B, 0.5)


# --------------------------------------------------------------------------- time warp (docs/reference/methods.md)
def warp(a, b, c, t):
    """docs/reference/methods.md, uneven knots for P4, P7, P8: u(a)=0, u(b)=1/2, u(c)=1, u'(b)=1 (in s),
    piecewise quadratic on [0, beta], [beta, 1], linear outside."""
    s = (t - a) / (c - a)
    beta = (b - a) / (c - a)

    def left(s, beta):  # u = A s + B s^2 on [0, beta]
        A = (1.0 - beta) / beta
        Bq = (beta - 0.5) / (beta * beta)
        if s < 0:
            return A * s
        return A * s + Bq * s * s

    if s <= beta:
        return left(s, beta)
    return 1.0 - left(1.0 - s, 1.0 - beta)


# --------------------------------------------------------------------------- independent PITAs
def p1(a, A, b, B, c, C, t):
    x, y, z = lagrange_weights(a, b, c, t)
    p = x * A[0] + y * B[0] + z * C[0]
    v = x * vec(A) + y * vec(B) + z * vec(C)
    return arrow_from_vector(p, v)


def lp_vector(a, A, b, B, c, C, t):
    """-LP: Lagrange of (log m, w)."""
    x, y, z = lagrange_weights(a, b, c, t)
    lm = x * math.log(A[1]) + y * math.log(B[1]) + z * math.log(C[1])
    w = x * A[2] + y * B[2] + z * C[2]
    return math.exp(lm), w


def p3(a, A, b, B, c, C, t):
    x, y, z = lagrange_weights(a, b, c, t)
    p = x * A[0] + y * B[0] + z * C[0]
    m, w = lp_vector(a, A, b, B, c, C, t)
    return (p, m, w)


def p2(a, A, b, B, c, C, t, anchor="start"):
    """LS-Po: PITA Eq. 26 as corrected by docs/paper-notes.md N2 and docs/reference/methods.md."""
    x, y, z = lagrange_weights(a, b, c, t)
    m = x * A[1] + y * B[1] + z * C[1]
    w = x * A[2] + y * B[2] + z * C[2]
    v = m * cmath.exp(1j * w)
    if anchor == "start":
        pa, pb, pc = A[0], B[0], C[0]
    else:
        pa, pb, pc = A[0] + vec(A) / 2, B[0] + vec(B) / 2, C[0] + vec(C) / 2
    ext = max(abs(pb - pa), abs(pc - pb), abs(pc - pa))
    if abs(pb - pa) <= P2_EPS * ext or abs(pc - pb) <= P2_EPS * ext:
        pt = x * pa + y * pb + z * pc
    else:
        u = y + 2 * z
        L = complex(math.log(abs(pc - pb) / abs(pb - pa)), cmath.phase((pc - pb) / (pb - pa)))
        den = cexpm1(L)
        phi = u if abs(den) < TWIRL_EPS else cexpm1(u * L) / den
        pt = pa + phi * (pb - pa)
    if anchor != "start":
        pt = pt - v / 2
    return (pt, m, w)


def p10(a, A, b, B, c, C, t):
    """Pa-EL (appendix B; docs/paper-notes.md N6: principal logs)."""
    x, y, z = lagrange_weights(a, b, c, t)
    p = x * A[0] + y * B[0] + z * C[0]
    lm = x * math.log(A[1]) + y * math.log(B[1]) + z * math.log(C[1])
    w = x * principal(A[2]) + y * principal(B[2]) + z * principal(C[2])
    return (p, math.exp(lm), w)


# --------------------------------------------------------------------------- coordinated PITAs
def p6(a, A, b, B, c, C, t):
    """La-LP, PITA Eq. 34 with docs/paper-notes.md N4."""
    x, y, z = lagrange_weights(a, b, c, t)
    L = sta(sma(A, B, y + z), B, C, z)
    R = sta(sma(C, B, x + y), B, A, x)
    return steady_average(L, R)


def p9(a, A, b, B, c, C, t, path_mean="geometric", magnitude_mean="geometric"):
    """Ne-LP, PITA Eq. D.2 with q, r, s of PITA Eq. 14 (options: Sec. 2.7 variants of each SMA)."""
    q = (t - a) / (b - a)
    r = (t - b) / (c - b)
    s = (t - a) / (c - a)
    kw = {"path_mean": path_mean, "magnitude_mean": magnitude_mean}
    return sma(sma(A, B, q, **kw), sma(B, C, r, **kw), s, **kw)


def bezier(A, B, C, t):
    """PITA Eq. 29."""
    return sma(sma(A, B, t), sma(B, C, t), t)


def p4(a, A, b, B, c, C, t):
    """Be-LP, PITA Eq. 27-32 with docs/paper-notes.md N3 and the time warp of docs/reference/methods.md (N17)."""
    u = warp(a, b, c, t)
    if u <= 0.5:
        Lc = sta(sma(A, B, 0.75), C, B, 0.25)
        return bezier(A, Lc, B, 2 * u)
    Rc = sta(sma(C, B, 0.75), A, B, 0.25)
    return bezier(B, Rc, C, 2 * u - 1)


def p5(a, A, b, B, c, C, t):
    """He-LP, appendix C: logs of the homogeneous similarities about the centroid.

    A similarity z -> lam z + p has the generator z -> l z + g with l = Log lam (principal)
    and p = g (e^l - 1)/l, so g = p l / expm1(l); exp of the blended generator gives
    lam(t) = e^l, p(t) = g expm1(l)/l.
    """
    x, y, z = lagrange_weights(a, b, c, t)
    o = (A[0] + B[0] + C[0]) / 3

    def ratio(l):  # expm1(l)/l
        if abs(l) < 1e-8:
            return 1 + l / 2 + l * l / 6
        return cexpm1(l) / l

    ls, gs = [], []
    for X in (A, B, C):
        l = complex(math.log(X[1]), principal(X[2]))
        ls.append(l)
        gs.append((X[0] - o) / ratio(l))
    l = x * ls[0] + y * ls[1] + z * ls[2]
    g = x * gs[0] + y * gs[1] + z * gs[2]
    return (o + g * ratio(l), math.exp(l.real), l.imag)


def _exp_ratio(l):  # expm1(l)/l
    if abs(l) < 1e-8:
        return 1 + l / 2 + l * l / 6
    return cexpm1(l) / l


def p5s(a, A, b, B, c, C, t):
    """Hs-LP (docs/reference/methods.md, docs/paper-notes.md N7): P5's blend of principal logs done in the frame of
    F = M(A, C): X' = F^-1 X (z -> (v_X/v_F) z + (p_X - p_F)/v_F), relative angles reduced
    to (-pi, pi], blended about the frame's origin F.p; D = F D', D.w = F.w + blended angle.
    (Which of centroid/no centroid and principal/actual relative angles docs/reference/methods.md means
    was settled on scenes/fig01 with an extra turn on C: only this variant matches.)"""
    x, y, z = lagrange_weights(a, b, c, t)
    F = steady_average(A, C)
    vF = vec(F)
    l_blend, g_blend = 0j, 0j
    for wgt, X in ((x, A), (y, B), (z, C)):
        l = complex(math.log(X[1] / F[1]), principal(X[2] - F[2]))
        g = ((X[0] - F[0]) / vF) / _exp_ratio(l)
        l_blend += wgt * l
        g_blend += wgt * g
    pd = g_blend * _exp_ratio(l_blend)
    return (F[0] + vF * pd, F[1] * math.exp(l_blend.real), F[2] + l_blend.imag)


# --------------------------------------------------------------------------- perseverant PITAs
def _k_from_delta(delta):
    """k with cosh k = 1 + delta, principal branch (Im k in [-pi, pi])."""
    return 2 * cmath.asinh(cmath.sqrt(delta / 2))


def _qsr(delta, tau):
    """Q(tau) = (cosh k tau - 1)/(cosh k - 1), S(tau) = sinh k tau / sinh k,
    R(tau) = (S(tau) - tau)/(cosh k - 1); limits tau^2, tau, tau(tau^2-1)/3 as k -> 0."""
    if delta == 0:
        return tau * tau, tau, tau * (tau * tau - 1) / 3
    k = _k_from_delta(delta)
    sh = cmath.sqrt(delta / 2)  # sinh(k/2)
    Q = (cmath.sinh(k * tau / 2) / sh) ** 2
    S = cmath.sinh(k * tau) / cmath.sinh(k)
    if abs(k) < 0.1 and abs(k * tau) < 2:
        # series in k^2: R = [sum_{n>=1} k^{2n-2}(tau^{2n+1}-tau)/(2n+1)!] /
        #                    [(sinh k / k) * sum_{n>=1} k^{2n-2}/(2n)!]
        k2 = k * k
        num = 0j
        den = 0j
        shk = 0j
        pw = 1 + 0j
        for n in range(1, 40):
            num += pw * (tau ** (2 * n + 1) - tau) / math.factorial(2 * n + 1)
            den += pw / math.factorial(2 * n)
            shk += pw / math.factorial(2 * n - 1)
            pw *= k2
        R = num / (shk * den)
    else:
        R = (S - tau) / delta
    return Q, S, R


def _kappa_delta(A, B, C):
    va, vb, vc = vec(A), vec(B), vec(C)
    return (va + vc - 2 * vb) / (2 * vb)


def p7(a, A, b, B, c, C, t):
    """Ra-Pe: every end point obeys x'' = k^2 (x - f), knots tau = -1, 0, 1
    (docs/paper-notes.md N13); x(tau) = x_b + (x_a+x_c-2x_b)/2 Q + (x_c-x_a)/2 S."""
    tau = 2 * warp(a, b, c, t) - 1
    delta = _kappa_delta(A, B, C)
    Q, S, _ = _qsr(delta, tau)

    def mv(xa, xb, xc):
        return xb + (xa + xc - 2 * xb) / 2 * Q + (xc - xa) / 2 * S

    p = mv(A[0], B[0], C[0])
    q = mv(endpoint(A), endpoint(B), endpoint(C))
    return arrow_from_vector(p, q - p)


def p8(a, A, b, B, c, C, t):
    """Lo-Pe: U(tau): z -> alpha(tau) z + beta(tau), alpha'' = e alpha, beta'' = g alpha.
    alpha = v_b + (v_a+v_c-2v_b)/2 Q + (v_c-v_a)/2 S;
    beta  = p_b + (p_c-p_a)/2 tau + (p_a+p_c-2p_b)/2 [Q + (v_c-v_a)/(2 v_b) R]."""
    tau = 2 * warp(a, b, c, t) - 1
    va, vb, vc = vec(A), vec(B), vec(C)
    pa, pb, pc = A[0], B[0], C[0]
    delta = _kappa_delta(A, B, C)
    Q, S, R = _qsr(delta, tau)
    v = vb + (va + vc - 2 * vb) / 2 * Q + (vc - va) / 2 * S
    p = pb + (pc - pa) / 2 * tau + (pa + pc - 2 * pb) / 2 * (Q + (vc - va) / (2 * vb) * R)
    return arrow_from_vector(p, v)


# --------------------------------------------------------------------------- dispatch
METHODS3 = {"P1": p1, "P2": p2, "P3": p3, "P4": p4, "P5": p5, "P6": p6,
            "P7": p7, "P8": p8, "P9": p9, "P10": p10, "P5S": p5s}
# docs/reference/methods.md, output windings: these report a principal (P1 P7 P8) or blended principal-log
# angle (P5 P10); the others carry the winding.
PRINCIPAL_W = {"P1", "P7", "P8"}


def evaluate(method, keyframes, t, options=None):
    _SCALE[0] = 0.0
    options = options or {}
    means = {k: options[k] for k in ("path_mean", "magnitude_mean") if k in options}
    if method == "SMA":
        (a, A), (b, B) = keyframes
        return sma(A, B, (t - a) / (b - a), **means)
    (a, A), (b, B), (c, C) = keyframes
    if method == "P2" and "anchor" in options:
        return p2(a, A, b, B, c, C, t, options["anchor"])
    if method == "P9" and means:
        return p9(a, A, b, B, c, C, t, **means)
    return METHODS3[method](a, A, b, B, c, C, t)


def selfcheck(n=200, seed=7):
    """(Distances are relative to the frame's size.)  Properties the paper states, checked on the oracle itself (independent of the CLI):
    interpolation, symmetry (PITA Eq. 41), similarity invariance (PITA Eq. 40; P5/P10 excepted,
    docs/paper-notes.md N7), twirl_between(A, B) . A = B, P4 C1 at b, and the ODEs of P7
    (x'' = K (x - f), one K and f for both end points) and P8 (alpha'' = e alpha,
    beta'' = g alpha) by finite differences.  Returns the worst residual per check."""
    import random
    rng = random.Random(seed)
    worst = {}

    def note(key, v):
        worst[key] = max(worst.get(key, 0.0), v)

    def rarrow():
        return (complex(rng.uniform(-3, 3), rng.uniform(-3, 3)), math.exp(rng.uniform(-2, 2)),
                rng.uniform(-9, 9))

    def adist(X, Y, principal_w):
        dw = X[2] - Y[2]
        if principal_w:
            dw = math.remainder(dw, 2 * math.pi)
        sc = max(1.0, abs(X[0]), abs(endpoint(X)))
        return max(abs(X[0] - Y[0]) / sc, abs(endpoint(X) - endpoint(Y)) / sc,
                   abs(dw) / max(1.0, abs(X[2])))

    for _ in range(n):
        A, B, C = rarrow(), rarrow(), rarrow()
        a = rng.uniform(-1, 1)
        c = a + rng.uniform(0.5, 2)
        b = a + (c - a) * rng.uniform(0.2, 0.8)
        note("twirl T_AB.A = B", adist(Twirl(A, B).arrow(A, 1.0), B, False))
        kf = [(a, A), (b, B), (c, C)]
        S = (complex(rng.uniform(-2, 2), rng.uniform(-2, 2)), math.exp(rng.uniform(-1, 1)),
             rng.uniform(-3, 3))  # similarity z -> S.p + S.m e^{i S.w} z

        def sim(X):
            lam = S[1] * cmath.exp(1j * S[2])
            return (S[0] + lam * X[0], S[1] * X[1], X[2] + S[2])

        for meth in METHODS3:
            pw = meth in PRINCIPAL_W or meth in ("P5", "P5S", "P10")
            for tk, K in kf:
                note("interpolation " + meth, adist(evaluate(meth, kf, tk), K, pw))
            t = rng.uniform(a - 0.5, c + 0.5)
            D = evaluate(meth, kf, t)
            Dr = evaluate(meth, [(a, C), (a + c - b, B), (c, A)], a + c - t)
            note("symmetry PITA Eq.41 " + meth, adist(D, Dr, pw))
            if meth not in ("P5", "P10"):
                Ds = evaluate(meth, [(tk, sim(K)) for tk, K in kf], t)
                note("similarity PITA Eq.40 " + meth, adist(Ds, sim(D), True) / S[1])
        h = 1e-5
        P = lambda s: p4(a, A, b, B, c, C, s)[0]
        d1 = (-3 * P(b) + 4 * P(b + h) - P(b + 2 * h)) / (2 * h)   # one-sided, O(h^2)
        d0 = (3 * P(b) - 4 * P(b - h) + P(b - 2 * h)) / (2 * h)
        note("P4 C1 at b (fd)", abs(d1 - d0) / max(1.0, abs(d1)))
        # perseverance, even knots (u = s, tau = 2 s - 1), in tau
        ke = [(-1.0, A), (0.0, B), (1.0, C)]
        delta = _kappa_delta(A, B, C)
        if abs(delta + 2) < 0.3:
            continue
        k2 = _k_from_delta(delta) ** 2
        hh = 1e-3
        for tau in (-1.7, -0.4, 0.3, 1.2):
            def d2(f):
                return (f(tau + hh) - 2 * f(tau) + f(tau - hh)) / hh ** 2
            # P7
            fp = lambda s: p7(-1.0, A, 0.0, B, 1.0, C, s)[0]
            fq = lambda s: endpoint(p7(-1.0, A, 0.0, B, 1.0, C, s))
            f = ((A[0] + C[0] - 2 * (1 + delta) * B[0]) / (-2 * delta)) if delta != 0 else None
            if f is not None:
                for g in (fp, fq):
                    r = d2(g) - k2 * (g(tau) - f)
                    note("P7 x''=k^2(x-f) (fd)", abs(r) / max(1.0, abs(d2(g))))
            # P8: alpha'' = k^2 alpha and beta''/alpha constant
            fa = lambda s: vec(p8(-1.0, A, 0.0, B, 1.0, C, s))
            fb = lambda s: p8(-1.0, A, 0.0, B, 1.0, C, s)[0]
            note("P8 alpha''=e alpha (fd)", abs(d2(fa) - k2 * fa(tau)) / max(1.0, abs(d2(fa))))
            gg = d2(fb) / fa(tau)
            if tau == -1.7:
                g0 = gg
            note("P8 beta''/alpha const (fd)", abs(gg - g0) / max(1.0, abs(g0)))
    return worst


if __name__ == "__main__":
    for k, v in sorted(selfcheck().items()):
        print("%-32s %.2e" % (k, v))
