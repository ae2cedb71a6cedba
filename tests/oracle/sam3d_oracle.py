#!/usr/bin/env python3
"""Independent high-precision oracle for real powers A^t of 3D affinities (EAR in 3D).

Pure Python 3 standard library (decimal, 60 significant digits), sharing nothing with
pita's split of src/core/affine_power_of_space.cpp (no eigenvector, no 2D block): the principal
real logarithm of the 4x4 homogeneous matrix H = [[L, b], [0, 0, 0, 1]] is computed by
inverse scaling and squaring, as tests/oracle/sam_oracle.py does in 2D,

    X_0 = H,  X_{j+1} = sqrt(X_j)  (Denman-Beavers iteration) until ||X_k - I|| < 1e-3,
    log H = 2^k log(I + E),  E = X_k - I  (Taylor series),

and A^t = exp(t log H) by scaling and squaring of the Taylor series.  The iteration
converges to the principal square root whenever H has no eigenvalue on the closed negative
real axis (Jordan blocks, shears and translations included).  An exact rotation by pi has
no principal log (pita takes the rotation by +pi, docs/paper-notes.md N58); the oracle
refuses it and the comparison leaves it to tests/core/test_affine_power_of_space.cpp.

Usage:
  sam3d_oracle.py                      self-check (exit 0 when every check holds to 1e-40)
  sam3d_oracle.py --compare PROBE      A^t of the ear3d_probe executable against the oracle
                                       on random and singular affinities (exit 0 when every
                                       case agrees to its tolerance: 1e-12 relative, but
                                       4e-16/e for rotations by pi - e, e < 4e-4; see
                                       TOLERANCE below)
"""
import decimal
import math
import random
import subprocess
import sys
import time
from decimal import Decimal as D

PREC = 60
decimal.setcontext(decimal.Context(prec=PREC, Emin=-999999, Emax=999999))
ZERO, ONE, TWO = D(0), D(1), D(2)
N = 4


class NoSam(ValueError):
    """L has a real negative eigenvalue (no principal log) or det L <= 0."""


# --------------------------------------------------------------------------- matrices
def dec(x):
    return +x if isinstance(x, D) else D(x)  # floats convert exactly


def eye(n=N):
    return [[ONE if i == j else ZERO for j in range(n)] for i in range(n)]


def mmul(X, Y):
    return [[sum((X[i][k] * Y[k][j] for k in range(len(Y))), ZERO) for j in range(len(Y[0]))]
            for i in range(len(X))]


def madd(X, Y):
    return [[a + b for a, b in zip(r, s)] for r, s in zip(X, Y)]


def msub(X, Y):
    return [[a - b for a, b in zip(r, s)] for r, s in zip(X, Y)]


def mscale(c, X):
    return [[c * a for a in r] for r in X]


def mnorm(X):
    return max(sum((abs(a) for a in r), ZERO) for r in X)


def fro(X):
    return sum((a * a for r in X for a in r), ZERO).sqrt()


def inv(X):
    """Gauss-Jordan with partial pivoting."""
    n = len(X)
    A = [list(r) + [ONE if i == j else ZERO for j in range(n)] for i, r in enumerate(X)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(A[r][c]))
        if A[p][c] == 0:
            raise ZeroDivisionError("singular matrix")
        A[c], A[p] = A[p], A[c]
        pivot = A[c][c]
        A[c] = [a / pivot for a in A[c]]
        for r in range(n):
            if r != c and A[r][c] != 0:
                f = A[r][c]
                A[r] = [a - f * b for a, b in zip(A[r], A[c])]
    return [r[n:] for r in A]


def det3(X):
    return (X[0][0] * (X[1][1] * X[2][2] - X[1][2] * X[2][1])
            - X[0][1] * (X[1][0] * X[2][2] - X[1][2] * X[2][0])
            + X[0][2] * (X[1][0] * X[2][1] - X[1][1] * X[2][0]))


def homog(M34):
    M = [[dec(v) for v in r] for r in M34]
    return M + [[ZERO, ZERO, ZERO, ONE]]


# --------------------------------------------------------------------------- sqrt, log, exp
def sqrtm_db(M, maxit=200):
    tol = D(10) ** (-(PREC - 4))
    Y, Z = [r[:] for r in M], eye(len(M))
    prev = None
    for _ in range(maxit):
        Yi, Zi = inv(Y), inv(Z)
        Yn = mscale(D("0.5"), madd(Y, Zi))
        Zn = mscale(D("0.5"), madd(Z, Yi))
        step = mnorm(msub(Yn, Y)) / max(ONE, mnorm(Yn))
        Y, Z = Yn, Zn
        if step <= tol or (prev is not None and step < D("1e-30") and step > prev / 2):
            return mscale(D("0.5"), madd(Y, inv(Z)))
        prev = step
    raise RuntimeError("Denman-Beavers iteration did not converge")


def logm_taylor(E):
    eps = D(10) ** (-(PREC + 2))
    S, P, n = [r[:] for r in E], E, 1
    while True:
        n += 1
        P = mmul(P, E)
        if mnorm(P) < eps:
            return S
        S = madd(S, mscale((ONE if n % 2 else -ONE) / n, P))
        if n > 400:
            raise RuntimeError("log series did not converge")


def logm(M):
    X, k = [r[:] for r in M], 0
    while mnorm(msub(X, eye(len(M)))) >= D("1e-3"):
        X = sqrtm_db(X)
        k += 1
        if k > 200:
            raise RuntimeError("too many square roots")
    return mscale(TWO ** k, logm_taylor(msub(X, eye(len(M)))))


def expm(X):
    nrm = mnorm(X)
    s = int(math.ceil(math.log2(float(nrm) / 0.5))) if nrm > D("0.5") else 0
    Y = mscale(ONE / (TWO ** s), X)
    eps = D(10) ** (-(PREC + 4))
    S, T, n = eye(len(X)), eye(len(X)), 0
    while True:
        n += 1
        T = mscale(ONE / n, mmul(T, Y))
        S = madd(S, T)
        if mnorm(T) < eps:
            break
    for _ in range(s):
        S = mmul(S, S)
    return S


def real_eigenvalues_negative(L):
    """True when the 3x3 L (det L > 0) has a real eigenvalue < 0, or a double one = 0: no
    principal real logarithm.  p(z) = z^3 - a z^2 + b z - c has p(0) = -c < 0 and tends to
    -inf as z -> -inf, so it has negative roots iff its largest value on (-inf, 0] is >= 0,
    which is taken at a critical point p'(z) = 3 z^2 - 2 a z + b = 0 (all in Decimal)."""
    a = L[0][0] + L[1][1] + L[2][2]
    b = (L[0][0] * L[1][1] - L[0][1] * L[1][0] + L[0][0] * L[2][2] - L[0][2] * L[2][0]
         + L[1][1] * L[2][2] - L[1][2] * L[2][1])
    c = det3(L)
    disc = a * a - 3 * b
    if disc < 0:
        return False  # p increasing: its one real root is > 0
    for z in ((a - disc.sqrt()) / 3, (a + disc.sqrt()) / 3):
        if z < 0 and ((z - a) * z + b) * z - c >= 0:
            return True
    return False


class Power:
    """A^t of one 3D affinity (a 3x4 list of floats/Decimals)."""

    def __init__(self, A34):
        self.H = homog(A34)
        L = [r[:3] for r in self.H[:3]]
        if det3(L) <= 0:
            raise NoSam("det L = %s <= 0" % det3(L))
        if real_eigenvalues_negative(L):
            raise NoSam("L has a real negative eigenvalue")
        self.log = logm(self.H)

    def __call__(self, t):
        return expm(mscale(dec(t), self.log))


# --------------------------------------------------------------------------- pi, sin, cos
def _pi():
    with decimal.localcontext() as ctx:
        ctx.prec = PREC + 10

        def arctan_inv(x):
            x, s, n, sign = D(x), ZERO, 1, 1
            term = ONE / x
            while term > D(10) ** (-(PREC + 12)):
                s += sign * term / n
                term /= x * x
                n += 2
                sign = -sign
            return s
        return +(4 * (4 * arctan_inv(5) - arctan_inv(239)))


PI = _pi()


def sincos(x):
    with decimal.localcontext() as ctx:
        ctx.prec = PREC + 10
        k = (x / (2 * PI)).to_integral_value()
        y = x - 2 * PI * k
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


def rotation_dec(axis, angle):
    """Rodrigues' rotation by angle about the unit axis (Decimal)."""
    n = sum((dec(a) ** 2 for a in axis), ZERO).sqrt()
    u = [dec(a) / n for a in axis]
    s, c = sincos(dec(angle))
    K = [[ZERO, -u[2], u[1]], [u[2], ZERO, -u[0]], [-u[1], u[0], ZERO]]
    uu = [[u[i] * u[j] for j in range(3)] for i in range(3)]
    return [[c * (ONE if i == j else ZERO) + s * K[i][j] + (1 - c) * uu[i][j] for j in range(3)]
            for i in range(3)]


# --------------------------------------------------------------------------- self-check
def self_check():
    start = time.time()
    rng = random.Random(20261201)
    tol = D("1e-40")
    failures, worst = [], {}

    def check(name, err, scale=ONE):
        rel = err / max(ONE, scale)
        worst[name] = max(worst.get(name, ZERO), rel)
        if rel > tol:
            failures.append("%s: error %.3e" % (name, rel))

    for i in range(4):
        A = random_affinity(rng, 1e2)
        P = Power(A)
        check("exp(log A) = A", fro(msub(expm(P.log), P.H)), fro(P.H))
        h = P(D("0.5"))
        check("A^1/2 A^1/2 = A", fro(msub(mmul(h, h), P.H)), fro(P.H))
        s, t = D(rng.uniform(-1, 2)), D(rng.uniform(-1, 2))
        check("A^s A^t = A^(s+t)", fro(msub(mmul(P(s), P(t)), P(s + t))), fro(P(s + t)))
    # screw motion about the axis u through p: turn theta, slide d; A^t turns t theta, slides t d
    u, p, theta, d = [1, -2, D("0.5")], [D("0.3"), D("1.1"), D("-0.7")], D("2.2"), D("1.7")
    n = sum((dec(a) ** 2 for a in u), ZERO).sqrt()
    un = [dec(a) / n for a in u]

    def screw(angle, slide):
        R = rotation_dec(u, angle)
        b = [p[i] - sum((R[i][j] * p[j] for j in range(3)), ZERO) + slide * un[i] for i in range(3)]
        return [R[i] + [b[i]] for i in range(3)]
    P = Power(screw(theta, d))
    for t in (D("0.3"), D("-1.25"), D("1.7")):
        check("screw motion", fro(msub(P(t), homog(screw(t * theta, t * d)))))
    # Jordan block of size 3 at 1 with translation: L^t = I + tN + C(t,2) N^2, b_t = sum C(t,n) N^(n-1) b
    Nm = [[ZERO, D("1.3"), D("0.9")], [ZERO, ZERO, D("-0.6")], [ZERO, ZERO, ZERO]]
    b = [ONE, D("-0.5"), D("0.25")]
    P = Power([[ONE, D("1.3"), D("0.9"), b[0]], [ZERO, ONE, D("-0.6"), b[1]], [ZERO, ZERO, ONE, b[2]]])
    N2 = mmul(Nm, Nm)
    for t in (D("0.37"), D("-1.5"), D("2.25")):
        c2, c3 = t * (t - 1) / 2, t * (t - 1) * (t - 2) / 6
        Lt = [[(ONE if i == j else ZERO) + t * Nm[i][j] + c2 * N2[i][j] for j in range(3)] for i in range(3)]
        Nb = [sum((Nm[i][k] * b[k] for k in range(3)), ZERO) for i in range(3)]
        N2b = [sum((N2[i][k] * b[k] for k in range(3)), ZERO) for i in range(3)]
        bt = [t * b[i] + c2 * Nb[i] + c3 * N2b[i] for i in range(3)]
        check("Jordan block of size 3 at 1", fro(msub(P(t), [Lt[i] + [bt[i]] for i in range(3)] + [[ZERO] * 3 + [ONE]])))
    # diagonal stretch 1e4, 1e-4, 3 with translation
    vals, b = [D("1e4"), D("1e-4"), D(3)], [ONE, -ONE, D("0.5")]
    P = Power([[vals[0], 0, 0, b[0]], [0, vals[1], 0, b[1]], [0, 0, vals[2], b[2]]])
    for t in (D("0.25"), D("1.5"), D("-0.5")):
        pw = [(t * v.ln()).exp() for v in vals]
        ref = [[pw[i] if i == j else ZERO for j in range(3)] + [(pw[i] - 1) / (vals[i] - 1) * b[i]] for i in range(3)]
        check("diag(1e4, 1e-4, 3)", fro(msub(P(t), ref + [[ZERO] * 3 + [ONE]])), fro(ref))
    # pure translation
    P = Power([[1, 0, 0, D("2.5")], [0, 1, 0, D("-0.75")], [0, 0, 1, D("1.25")]])
    check("translation", fro(msub(P(D("0.37")), homog([[1, 0, 0, D("0.37") * D("2.5")], [0, 1, 0, D("0.37") * D("-0.75")],
                                                       [0, 0, 1, D("0.37") * D("1.25")]]))))
    # refusals
    for bad in ([[2, 0, 0, 0], [0, D("-0.5"), 0, 0], [0, 0, -3, 0]],
                [[-1, 1, 0, 0], [0, -1, 0, 0], [0, 0, 4, 0]],
                [[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]],
                [[-1, 0, 0, 0], [0, -1, 0, 0], [0, 0, 1, 0]]):  # an exact half turn: no principal log
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
    print("sam3d_oracle self-check: OK (%d families, tol 1e-40, %.1f s)" % (len(worst), time.time() - start))
    return 0


# --------------------------------------------------------------------------- random cases (floats)
def _matmul(X, Y):
    return [[sum(X[i][k] * Y[k][j] for k in range(len(Y))) for j in range(len(Y[0]))] for i in range(len(X))]


def _rotation(axis, angle):
    n = math.sqrt(sum(a * a for a in axis))
    x, y, z = (a / n for a in axis)
    c, s = math.cos(angle), math.sin(angle)
    return [[c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s],
            [y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s],
            [z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)]]


def _random_axis(rng):
    return [rng.gauss(0, 1) for _ in range(3)]


def _inverse3(X):
    inv_d = inv([[D(v) for v in r] for r in X])
    return [[float(v) for v in r] for r in inv_d]


def random_affinity(rng, spread, kappa_v=10.0, kind=None):
    """[L | b] with L = V D V^-1: D positive diagonal or a positive eigenvalue beside a
    rotation-scaling (angle within 0.97 pi), eigenvalue ratios up to `spread`, V of condition
    up to kappa_v."""
    half = math.log(spread) / 2
    e = lambda: math.exp(rng.uniform(-half, half))  # noqa: E731
    kind = kind or rng.choice(["diagonal", "rotation"])
    if kind == "diagonal":
        Dm = [[e(), 0, 0], [0, e(), 0], [0, 0, e()]]
    else:
        rho, a = e(), rng.uniform(-0.97 * math.pi, 0.97 * math.pi)
        Dm = [[e(), 0, 0], [0, rho * math.cos(a), -rho * math.sin(a)], [0, rho * math.sin(a), rho * math.cos(a)]]
    U, W = _rotation(_random_axis(rng), rng.uniform(0, math.pi)), _rotation(_random_axis(rng), rng.uniform(0, math.pi))
    s = [[1, 0, 0], [0, kappa_v ** (-rng.uniform(0, 1)), 0], [0, 0, 1 / kappa_v]]
    V = _matmul(U, _matmul(s, [list(r) for r in zip(*W)]))
    L = _matmul(V, _matmul(Dm, _inverse3(V)))
    return [L[i] + [rng.uniform(-5, 5)] for i in range(3)]


# Tolerance of the comparison: 1e-12 relative (Frobenius, over max(|R|, 1)). A rotation by
# pi - e has a log of condition ~pi/e: a backward-stable A^t (ours or Eigen's) is off by
# ~1e-16/e, so near-pi cases get max(1e-12, 4e-16/e) (docs/paper-notes.md N58).
TOLERANCE = 1e-12


def compare(probe):
    start = time.time()
    rng = random.Random(17)
    cases = []  # (name, A34, t, tolerance)

    def add(name, A, tol=TOLERANCE, times=(-0.5, 0.3, 0.5, 1.7)):
        for t in times:
            cases.append((name, A, t, tol))

    for _ in range(40):
        add("random, ratios up to 1e2", random_affinity(rng, 1e2))
    for _ in range(30):
        add("stretch, ratios up to 1e4", random_affinity(rng, 1e4, kind="diagonal"))
    for _ in range(20):  # the hardest family: Eigen's pow is off by 2.7e-12 here (we 7e-13)
        add("rotation-scaling, ratios up to 1e4", random_affinity(rng, 1e4, kind="rotation"))
    for _ in range(20):  # near-pi rotations about random axes, with slides
        eps = 10 ** rng.uniform(-8, -2)
        angle = (math.pi - eps) * rng.choice([1, -1])
        R = _rotation(_random_axis(rng), angle)
        add("rotation by pi - %.0e" % eps, [R[i] + [rng.uniform(-2, 2)] for i in range(3)],
            max(TOLERANCE, 4e-16 / eps))
    for _ in range(10):  # screw motions
        R = _rotation(_random_axis(rng), rng.uniform(-3, 3))
        add("screw motion", [R[i] + [rng.uniform(-2, 2)] for i in range(3)])
    singular = {
        "identity": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]],
        "translation": [[1, 0, 0, 2.5], [0, 1, 0, -0.75], [0, 0, 1, 1.25]],
        "shear beside 1": [[1, 1.7, 0, 0.3], [0, 1, 0, -2.1], [0, 0, 1, 0.5]],
        "shear beside 3": [[1, 1.7, 0, 0.3], [0, 1, 0, -2.1], [0, 0, 3, 0.5]],
        "Jordan 3 at 1": [[1, 1.3, 0.9, 1], [0, 1, -0.6, -0.5], [0, 0, 1, 0.25]],
        "Jordan 3 at 2": [[2, 1.3, 0.9, 1], [0, 2, -0.6, -0.5], [0, 0, 2, 0.25]],
        "Jordan 2 at 2 beside 5": [[2, 1, 0, 0.5], [0, 2, 0, -1], [0, 0, 5, 2]],
        "eigenvalue 1 double": [[1, 0, 0, 0.4], [0, 3, 0, -2], [0, 0, 1, 1.5]],
        "eigenvalue 1 simple, diagonal": [[1, 0, 0, 0.7], [0, 2, 0, -1.2], [0, 0, 0.3, 2]],
        "rotation about z with slide": [[0.6, -0.8, 0, 1], [0.8, 0.6, 0, 2], [0, 0, 1, 3]],
        "uniform scaling": [[2, 0, 0, 1], [0, 2, 0, 1], [0, 0, 2, 1]],
        "stretch 1e4": [[1e4, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 1]],
        "stretch 1e2, 1e-2": [[1e2, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1e-2, 1]],
    }
    # the two random cases of tests/core/test_affine_power_of_space.cpp where a 1e-12
    # check failed: exp(log A) at 1.08e-12 (condition 3.3e6: ours is 6e-12 from
    # the oracle at t = 0.37, the floor of double for that conditioning) and
    # Eigen's pow 7.4e-10 from ours (ours 1.6e-14 from the oracle)
    add("ill-conditioned, test case 33 (condition 3.3e6)",
        [[-178.11359575953321, -105.75899310931703, 191.6428653399351, -3.8227831463049622],
         [1042.575439869519, 607.23990095874103, -1105.5306620717145, -4.6366991133092696],
         [361.52224826684755, 208.69105993688549, -380.77427938870181, 2.1982135269574776]],
        1e-11, times=(0.37, 0.5, 1.7))
    add("ill-conditioned, test case 150",
        [[-42.983634882412545, 45.535024366762009, 77.599550762470471, -0.22267011860235186],
         [4.1352836183608277, -4.3563735022312216, -7.4798914051503615, 3.1881057990202795],
         [-42.757794897057977, 45.228933160008097, 77.161484979405785, 3.6786033366469191]],
        times=(-0.04324499263209447, 0.5))
    for name, A in singular.items():
        add(name, A, times=(-1.5, 0.25, 0.5, 0.71, 2.25))
    # rotated copies of the singular ones (not exactly representable: the 1 is then approximate)
    for name in ("shear beside 1", "Jordan 3 at 1", "eigenvalue 1 double"):
        R = _rotation([0.2, -0.5, 0.9], 0.8)
        A = singular[name]
        L = _matmul(R, _matmul([r[:3] for r in A], [list(r) for r in zip(*R)]))
        b = [sum(R[i][k] * A[k][3] for k in range(3)) for i in range(3)]
        add(name + ", rotated", [L[i] + [b[i]] for i in range(3)], times=(-1.5, 0.25, 0.5, 2.25))
    refusals = [
        [[2, 0, 0, 0], [0, -0.5, 0, 0], [0, 0, -3, 0]],
        [[-1, 1, 0, 0], [0, -1, 0, 0], [0, 0, 4, 0]],
        [[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]],
    ]

    lines = ["%r %s" % (t, " ".join(repr(float(v)) for r in A for v in r)) for (_, A, t, _) in cases]
    lines += ["0.5 %s" % " ".join(repr(float(v)) for r in A for v in r) for A in refusals]
    out = subprocess.run([probe], input="\n".join(lines) + "\n", capture_output=True, text=True, check=True)
    answers = out.stdout.splitlines()
    if len(answers) != len(lines):
        print("probe answered %d lines for %d" % (len(answers), len(lines)))
        return 1

    failures, worst, powers = [], {}, {}
    for (name, A, t, tol), answer in zip(cases, answers):
        key = repr(A)
        if key not in powers:
            powers[key] = Power(A)
        R = powers[key](t)
        if answer.startswith("nosam"):
            failures.append("%s t=%r: refused: %s" % (name, t, answer))
            continue
        X = [[D(v) for v in answer.split()[4 * i:4 * i + 4]] for i in range(3)] + [[ZERO] * 3 + [ONE]]
        err = float(fro(msub(X, R)) / max(ONE, fro(R)))
        family = name.split(" - ")[0] if name.startswith("rotation by pi") else name
        worst[family] = max(worst.get(family, 0.0), err)
        if err > tol:
            failures.append("%s t=%r: relative error %.3e > %.1e" % (name, t, err, tol))
    for A, answer in zip(refusals, answers[len(cases):]):
        if not answer.startswith("nosam"):
            failures.append("no refusal for %s" % A)
    for family in sorted(worst):
        print("%-42s worst %.2e" % (family, worst[family]))
    if failures:
        print("FAIL (%d of %d):" % (len(failures), len(cases)))
        for f in failures:
            print("  " + f)
        return 1
    print("sam3d compare: OK (%d powers, %d refusals, tolerance %.0e relative, %.1f s)"
          % (len(cases), len(refusals), TOLERANCE, time.time() - start))
    return 0


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--compare":
        sys.exit(compare(sys.argv[2]))
    sys.exit(self_check())
