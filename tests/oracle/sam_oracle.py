#!/usr/bin/env python3
"""Independent high-precision oracle for real powers A^u of planar affinities (the SAM).

Pure Python 3 standard library (decimal, ~60 significant digits).  Shares nothing with
pita's closed forms: the principal real logarithm of the homogeneous 3x3 matrix
M = [[L, b], [0, 0, 1]] is computed by inverse scaling and squaring,

    X_0 = M,  X_{j+1} = sqrt(X_j)  (Denman-Beavers iteration, real arithmetic)
    until ||X_k - I|| < 1e-3,
    log M = 2^k log(I + E),  E = X_k - I  (Taylor series of log(I + E)),

and A^u = exp(u log M) by scaling and squaring of the exponential's Taylor series.  The
Denman-Beavers iteration converges to the principal square root whenever M has no real
negative eigenvalue (the Jordan blocks of a shear or of a pure translation included: it is
Newton's method and M is nonsingular).

The principal real logarithm exists iff L has no real negative eigenvalue (and det L > 0).
The one exception pita accepts is L = -rho I (a half turn with uniform scale): pita uses
the rotation by +pi, log L = ln(rho) I + pi J; the oracle then returns, with the fixed point
q = (I - L)^{-1} b,  A^u(p) = rho^u R(pi u) (p - q) + q.

Run with no arguments for the self-check (exit 0 when every check holds to 1e-40).
"""
import decimal
import math
import random
import sys
from decimal import Decimal as D

PREC = 60
CTX = decimal.Context(prec=PREC, Emin=-999999, Emax=999999)
decimal.setcontext(CTX)

ZERO, ONE, TWO = D(0), D(1), D(2)


class NoSam(ValueError):
    """A^u has no real principal power (L has a real negative eigenvalue, or det L <= 0)."""


# --------------------------------------------------------------------------- 3x3 helpers
def dec(x):
    """Exact Decimal of a float / int / str / Decimal (floats are converted exactly)."""
    if isinstance(x, D):
        return +x
    return D(x)


def mat(rows):
    return [[dec(v) for v in r] for r in rows]


def eye(n=3):
    return [[ONE if i == j else ZERO for j in range(n)] for i in range(n)]


def mmul(X, Y):
    n, m, p = len(X), len(Y), len(Y[0])
    return [[sum((X[i][k] * Y[k][j] for k in range(m)), ZERO) for j in range(p)] for i in range(n)]


def madd(X, Y):
    return [[a + b for a, b in zip(r, s)] for r, s in zip(X, Y)]


def msub(X, Y):
    return [[a - b for a, b in zip(r, s)] for r, s in zip(X, Y)]


def mscale(c, X):
    return [[c * a for a in r] for r in X]


def mnorm(X):
    """Max-abs-row-sum (infinity) norm: submultiplicative."""
    return max(sum((abs(a) for a in r), ZERO) for r in X)


def mmax(X):
    return max(abs(a) for r in X for a in r)


def det3(X):
    return (X[0][0] * (X[1][1] * X[2][2] - X[1][2] * X[2][1])
            - X[0][1] * (X[1][0] * X[2][2] - X[1][2] * X[2][0])
            + X[0][2] * (X[1][0] * X[2][1] - X[1][1] * X[2][0]))


def inv3(X):
    d = det3(X)
    if d == 0:
        raise ZeroDivisionError("singular matrix")
    c = [[ZERO] * 3 for _ in range(3)]
    for i in range(3):
        for j in range(3):
            r = [k for k in range(3) if k != i]
            s = [k for k in range(3) if k != j]
            minor = X[r[0]][s[0]] * X[r[1]][s[1]] - X[r[0]][s[1]] * X[r[1]][s[0]]
            c[j][i] = (minor if (i + j) % 2 == 0 else -minor) / d  # adjugate: transposed cofactors
    return c


def homog(M23):
    """3x3 homogeneous matrix of a 2x3 [[a, b, tx], [c, d, ty]]."""
    M = mat(M23)
    return [M[0][:], M[1][:], [ZERO, ZERO, ONE]]


def affine23(M):
    return [M[0][:3], M[1][:3]]


# --------------------------------------------------------------------------- sqrt, log, exp
def sqrtm_db(M, tol=None, maxit=200):
    """Principal square root by the Denman-Beavers iteration Y <- (Y + Z^-1)/2, Z <- (Z + Y^-1)/2."""
    tol = tol if tol is not None else D(10) ** (-(PREC - 4))
    Y, Z = [r[:] for r in M], eye(len(M))
    prev = None
    for _ in range(maxit):
        Yi, Zi = inv3(Y), inv3(Z)
        Yn = mscale(D("0.5"), madd(Y, Zi))
        Zn = mscale(D("0.5"), madd(Z, Yi))
        step = mnorm(msub(Yn, Y)) / max(ONE, mnorm(Yn))
        Y, Z = Yn, Zn
        # converged, or (strongly non-normal M) stagnating at the rounding level well past
        # double precision: quadratic convergence no longer halves the step
        if step <= tol or (prev is not None and step < D("1e-30") and step > prev / 2):
            # one more iteration to clean up the last digits
            Yi, Zi = inv3(Y), inv3(Z)
            Y = mscale(D("0.5"), madd(Y, Zi))
            return Y
        prev = step
    raise RuntimeError("Denman-Beavers iteration did not converge")


def logm_taylor(E):
    """log(I + E) = sum (-1)^(n+1) E^n / n for ||E|| small."""
    eps = D(10) ** (-(PREC + 2))
    S = [r[:] for r in E]
    P = E
    n = 1
    while True:
        n += 1
        P = mmul(P, E)
        if mnorm(P) < eps:
            break
        term = mscale((ONE if n % 2 else -ONE) / n, P)
        S = madd(S, term)
        if n > 400:
            raise RuntimeError("log series did not converge")
    return S


def logm_iss(M, thresh=D("1e-3")):
    """Principal logarithm by inverse scaling and squaring.  Returns (log M, k)."""
    I = eye(3)
    X = [r[:] for r in M]
    k = 0
    while mnorm(msub(X, I)) >= thresh:
        X = sqrtm_db(X)
        k += 1
        if k > 200:
            raise RuntimeError("too many square roots")
    return mscale(TWO ** k, logm_taylor(msub(X, I))), k


def expm(X):
    """exp(X) by scaling and squaring of the Taylor series."""
    nrm = mnorm(X)
    s = 0
    if nrm > D("0.5"):
        s = int(math.ceil(math.log2(float(nrm) / 0.5)))
    Y = mscale(ONE / (TWO ** s), X)
    eps = D(10) ** (-(PREC + 4))
    S = eye(3)
    T = eye(3)
    n = 0
    while True:
        n += 1
        T = mscale(ONE / n, mmul(T, Y))
        S = madd(S, T)
        if mnorm(T) < eps:
            break
        if n > 500:
            raise RuntimeError("exp series did not converge")
    for _ in range(s):
        S = mmul(S, S)
    return S


# --------------------------------------------------------------------------- classification
def is_minus_rho_identity(M):
    return M[0][1] == 0 and M[1][0] == 0 and M[0][0] == M[1][1] and M[0][0] < 0


def check_exists(M):
    """Raises NoSam unless L = M[:2,:2] has a real principal logarithm (or is -rho I)."""
    a, b, c, d = M[0][0], M[0][1], M[1][0], M[1][1]
    det = a * d - b * c
    if det <= 0:
        raise NoSam("det L = %s <= 0" % det)
    if is_minus_rho_identity(M):
        return "half-turn"
    tr = a + d
    disc = tr * tr - 4 * det
    if disc >= 0 and tr < 0:
        raise NoSam("L has real negative eigenvalues (tr %s, det %s)" % (tr, det))
    return "principal"


class Power:
    """A^u for a fixed affinity A (2x3 or 3x3): log computed once."""

    def __init__(self, A):
        M = homog(A) if len(A) == 2 else mat(A)
        self.M = M
        self.kind = check_exists(M)
        if self.kind == "half-turn":
            rho = -M[0][0]
            self.rho = rho
            L = [[M[0][0], M[0][1]], [M[1][0], M[1][1]]]
            # fixed point q = (I - L)^-1 b; I - L = (1 + rho) I
            self.q = [M[0][2] / (1 + rho), M[1][2] / (1 + rho)]
            self.log = None
            del L
        else:
            self.log, self.k = logm_iss(M)

    def __call__(self, u):
        u = dec(u)
        if self.kind == "half-turn":
            ru = self.rho ** u if u != 0 else ONE
            ang = pi() * u
            cs, sn = cos(ang), sin(ang)
            a, b = ru * cs, -ru * sn
            c, d = ru * sn, ru * cs
            qx, qy = self.q
            tx = qx - (a * qx + b * qy)
            ty = qy - (c * qx + d * qy)
            return [[a, b, tx], [c, d, ty], [ZERO, ZERO, ONE]]
        return expm(mscale(u, self.log))


def power(A, u):
    return Power(A)(u)


def sam_frame(B, C, t0, t1, t):
    """The SAM from pose B (2x3, time t0) to pose C (time t1) at time t: A^u B, A = C B^-1."""
    Bh, Ch = homog(B), homog(C)
    A = mmul(Ch, inv3(Bh))
    u = (dec(t) - dec(t0)) / (dec(t1) - dec(t0))
    return affine23(mmul(Power(A)(u), Bh))


# --------------------------------------------------------------------------- pi, sin, cos
_PI = None


def pi():
    """pi to PREC digits (Machin)."""
    global _PI
    if _PI is None:
        with decimal.localcontext() as ctx:
            ctx.prec = PREC + 10

            def arctan_inv(x):
                x = D(x)
                s, term, n, x2 = ZERO, ONE / x, 1, x * x
                sign = 1
                while term > D(10) ** (-(PREC + 12)):
                    s += sign * term / n
                    term /= x2
                    n += 2
                    sign = -sign
                return s
            _PI = +(4 * (4 * arctan_inv(5) - arctan_inv(239)))
        _PI = +_PI
    return _PI


def _sincos(x):
    with decimal.localcontext() as ctx:
        ctx.prec = PREC + 10
        p = pi()
        k = (x / (2 * p)).to_integral_value()
        y = x - 2 * p * k
        s, c = ZERO, ZERO
        term, n = y, 1
        while abs(term) > D(10) ** (-(PREC + 12)):
            s += term
            term = -term * y * y / ((n + 1) * (n + 2))
            n += 2
        term, n = ONE, 0
        while abs(term) > D(10) ** (-(PREC + 12)):
            c += term
            term = -term * y * y / ((n + 1) * (n + 2))
            n += 2
    return +s, +c


def sin(x):
    return _sincos(x)[0]


def cos(x):
    return _sincos(x)[1]


# --------------------------------------------------------------------------- self-check
def _rand_affine(rng, kmax=1.5, s_min=0.2):
    """A random orientation-preserving affinity with a real principal log."""
    s = rng.uniform(s_min, 1.0)
    a = rng.uniform(-1, 1) * (1 + s) * math.pi / 2 * 0.95
    c = rng.uniform(-math.pi, math.pi)
    k = rng.uniform(-kmax, kmax)
    L = _mat2_mul(_rot(a), _mat2_mul(_rot(-c), _mat2_mul([[1 / s, 0], [0, s]], _rot(c))))
    L = [[math.exp(k) * v for v in r] for r in L]
    return [[L[0][0], L[0][1], rng.uniform(-5, 5)], [L[1][0], L[1][1], rng.uniform(-5, 5)]]


def _rot(a):
    return [[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]]


def _mat2_mul(X, Y):
    return [[X[i][0] * Y[0][j] + X[i][1] * Y[1][j] for j in range(2)] for i in range(2)]


def main():
    t_start = __import__("time").time()
    rng = random.Random(20240611)
    tol = D("1e-40")
    failures = []
    worst = {}

    def check(name, err, scale=ONE):
        rel = err / max(ONE, scale)
        worst[name] = max(worst.get(name, ZERO), rel)
        if rel > tol:
            failures.append("%s: error %.3e" % (name, rel))

    # random matrices: exp(log A) = A, A^{1/2} A^{1/2} = A, A^{u} A^{v} = A^{u+v}
    for i in range(8):
        A = _rand_affine(rng)
        P = Power(A)
        M = P.M
        check("exp(log A) = A", mmax(msub(expm(P.log), M)), mmax(M))
        h = P(D("0.5"))
        check("A^1/2 A^1/2 = A", mmax(msub(mmul(h, h), M)), mmax(M))
        u, v = D(rng.uniform(-2, 2)), D(rng.uniform(-2, 2))
        check("A^u A^v = A^(u+v)", mmax(msub(mmul(P(u), P(v)), P(u + v))), mmax(P(u + v)))
        check("A^0 = I", mmax(msub(P(ZERO), eye())))
        # A^u fixes the fixed point q of A: (I - L) q = b
        a, b_, c, d = M[0][0], M[0][1], M[1][0], M[1][1]
        det = (1 - a) * (1 - d) - b_ * c
        qh = [[((1 - d) * M[0][2] + b_ * M[1][2]) / det], [(c * M[0][2] + (1 - a) * M[1][2]) / det], [ONE]]
        check("A^u fixes the fixed point of A", mmax(msub(mmul(P(u), qh), qh)), mmax(qh))
    # nearly a half turn: rotation by pi - 1e-9, exact float entries; A^1 = A and a closed form
    th = math.pi - 1e-9
    cs, sn = math.cos(th), math.sin(th)
    A = [[cs, -sn, 0.75], [sn, cs, -1.25]]
    P = Power(A)
    check("near half turn: A^1 = A", mmax(msub(P(ONE), P.M)))
    u = D("0.3")
    thd = _atan2(dec(sn), dec(cs))
    ru = (dec(cs) ** 2 + dec(sn) ** 2).sqrt() ** u
    Lu = [[ru * cos(u * thd), -ru * sin(u * thd)], [ru * sin(u * thd), ru * cos(u * thd)]]
    check("near half turn: linear part closed form",
          mmax([[P(u)[i][j] - Lu[i][j] for j in range(2)] for i in range(2)]))
    # pure translation: A^u = [I | u b]
    b = [D("2.5"), D("-0.75")]
    P = Power([[1, 0, b[0]], [0, 1, b[1]]])
    for u in (D("0.37"), D("-1.5"), D("2.25")):
        ref = [[ONE, ZERO, u * b[0]], [ZERO, ONE, u * b[1]], [ZERO, ZERO, ONE]]
        check("translation", mmax(msub(P(u), ref)))
    # shear [[1, k], [0, 1]] with translation
    kk = D("1.7")
    b = [D("0.3"), D("-2.1")]
    P = Power([[1, kk, b[0]], [0, 1, b[1]]])
    for u in (D("0.37"), D("-1.5"), D("2.25")):
        Lm = [[ONE, kk], [ZERO, ONE]]
        LmI_b = [kk * b[1], ZERO]  # (L - I) b
        tx = u * b[0] + u * (u - 1) / 2 * LmI_b[0]
        ty = u * b[1] + u * (u - 1) / 2 * LmI_b[1]
        ref = [[ONE, u * kk, tx], [ZERO, ONE, ty], [ZERO, ZERO, ONE]]
        check("shear", mmax(msub(P(u), ref)))
        del Lm
    # diag(1, 3) with translation (eigenvalue 1)
    b = [D("1.25"), D("-0.6")]
    P = Power([[1, 0, b[0]], [0, 3, b[1]]])
    for u in (D("0.37"), D("-1.5"), D("2.25")):
        t3 = exp_d(u * D(3).ln())
        ref = [[ONE, ZERO, u * b[0]], [ZERO, t3, (t3 - 1) / 2 * b[1]], [ZERO, ZERO, ONE]]
        check("diag(1,3)", mmax(msub(P(u), ref)))
    # Jordan block [[2, 1], [0, 2]] with translation: L^u = 2^u [[1, u/2], [0, 1]]
    P = Power([[2, 1, D("0.5")], [0, 2, D("-1")]])
    for u in (D("0.37"), D("-1.5")):
        tu = exp_d(u * TWO.ln())
        got = P(u)
        check("Jordan [[2,1],[0,2]]", mmax([[got[0][0] - tu, got[0][1] - tu * u / 2],
                                           [got[1][0], got[1][1] - tu]]))
        # translation: A^u fixes the fixed point of A
        # (I - L) q = b with I - L = [[-1, -1], [0, -1]]: q = (-(b_x - b_y), -b_y)
        qy = -D("-1")
        qx = -D("0.5") - qy
        qh = [[qx], [qy], [ONE]]
        check("Jordan fixed point", mmax(msub(mmul(got, qh), qh)))
    # -rho I: half turn with uniform scale (rotation by +pi)
    P = Power([[-2, 0, D("1.5")], [0, -2, D("-3")]])
    check("-2I: A^1 = A", mmax(msub(P(ONE), P.M)))
    h = P(D("0.5"))
    check("-2I: A^1/2 A^1/2 = A", mmax(msub(mmul(h, h), P.M)))
    check("-2I: rotation by +pi/2", mmax([[h[0][0], h[0][1] + TWO.sqrt()], [h[1][0] - TWO.sqrt(), h[1][1]]]))
    # near identity: compare with the log series directly
    E = [[D(rng.uniform(-1, 1)) * D("1e-9") for _ in range(3)] for _ in range(2)] + [[ZERO] * 3]
    M = madd(eye(), E)
    P = Power(M)
    check("near identity: log", mmax(msub(P.log, logm_taylor(E))))
    check("near identity: exp(log A) = A", mmax(msub(expm(P.log), M)))
    # strongly anisotropic (kappa(L) = 1e12): diag(1e6, 1e-6) closed form, and a rotated copy
    P = Power([[D("1e6"), 0, 1], [0, D("1e-6"), 1]])
    for u in (D("0.25"), D("1.5"), D("-0.5")):
        l1, l2 = exp_d(u * D("1e6").ln()), exp_d(u * D("1e-6").ln())
        ref = [[l1, ZERO, (l1 - 1) / (D("1e6") - 1)], [ZERO, l2, (l2 - 1) / (D("1e-6") - 1)], [ZERO, ZERO, ONE]]
        check("diag(1e6, 1e-6)", mmax(msub(P(u), ref)), mmax(ref))
    R = [[D("0.6"), D("-0.8"), ZERO], [D("0.8"), D("0.6"), ZERO], [ZERO, ZERO, ONE]]
    Rt = [[D("0.6"), D("0.8"), ZERO], [D("-0.8"), D("0.6"), ZERO], [ZERO, ZERO, ONE]]
    M = mmul(R, mmul(homog([[D("1e6"), 0, 1], [0, D("1e-6"), 1]]), Rt))
    P = Power(M)
    check("rotated diag(1e6, 1e-6): exp(log A) = A", mmax(msub(expm(P.log), M)), mmax(M))
    u = D("0.7")
    check("rotated diag(1e6, 1e-6): similarity", mmax(msub(P(u), mmul(R, mmul(
        Power([[D("1e6"), 0, 1], [0, D("1e-6"), 1]])(u), Rt)))), mmax(P(u)))
    # refusals
    for bad in ([[-2, 0, 1], [0, D("-0.5"), 0]], [[-1, 1, 0], [0, -1, 0]], [[1, 0, 0], [0, -1, 0]]):
        try:
            Power(bad)
            failures.append("no refusal for %s" % bad)
        except NoSam:
            pass
    for name in worst:
        print("%-40s worst %.2e" % (name, worst[name]))
    if failures:
        print("FAIL (%d):" % len(failures))
        for f in failures:
            print("  " + f)
        return 1
    print("sam_oracle self-check: OK (%d families, tol 1e-40, %.1f s)" % (len(worst), __import__("time").time() - t_start))
    return 0


def exp_d(x):
    return dec(x).exp()


def _atan2(y, x):
    """atan2 in Decimal by Newton on tan: refine the float guess."""
    a = dec(math.atan2(float(y), float(x)))
    for _ in range(6):
        s, c = _sincos(a)
        # f(a) = s x - c y = 0 (the angle of (x, y)); f'(a) = c x + s y
        a = a - (s * x - c * y) / (c * x + s * y)
    return a


if __name__ == "__main__":
    sys.exit(main())
