#!/usr/bin/env python3
"""Compare `pita eval` on SAM pose scenes with the independent oracle sam_oracle.py.

usage: compare_sam_with_cli.py PATH/TO/pita [--count N] [--seed S] [-v] [--keep DIR] [--anisotropic]

Builds (fixed seed, temp dir) N random two-pose SAM scenes, B at t0 and C = A o B at t1, where
A is a random orientation-preserving affinity with a real principal logarithm
(L = e^k R(a) R(-c) diag(1/s, s) R(c), |a| < 0.98 (1 + s) pi/2, s in [0.05, 1], k in [-2, 2]),
plus every special case explicitly: pure translation, shear, diag(1, 3) (eigenvalue 1),
L = -2 I (half turn with scale: pita's rotation by +pi), rotation by pi - 1e-9, the Jordan
block [[2, 1], [0, 2]], 3 I, near-identity and near-shear affinities.  Each scene is evaluated
by one `pita eval SCENE --t ...` request (`pita eval --batch`, cli_batch.py) at u in {0, 0.25, 0.5, 1, 1.5, -0.5, -8, 12, random}; every
frame's 2x3 matrix must match the oracle's A^u o B (computed at ~60 digits from the poses
exactly as written in the scene) to 1e-12 * max(1, ||oracle||_max).

Where rounding the poses (C = A o B in doubles) would change the problem itself (A = -2 I,
the nearly half turn, the negative Jordan block), B is chosen so that C is exact (identity,
dyadic translation, unimodular integer linear part).

Refusals: L = diag(-2, -0.5), [[-1, 1], [0, -1]], R(pi) diag(1.5, 1/1.5) must exit 2 with
empty stdout and "no SAM exists between these poses" on stderr; det L < 0 must exit 2 with
"orientation-preserving".  Exit 1 on any mismatch, 0 otherwise.

Rotations by +-(pi - 1e-13) and by cos/sin of +-pi (off-diagonal +-1.2e-16) must keep their
principal angle: pita snaps only real negative eigenvalues within 1e-12 |r| of -rho I to S2
(docs/reference/pose-scenes.md "EAR").  --anisotropic (on in ctest) adds strong stretches, L = diag(r, 1/r) and
rotated copies up to r = 1e4, where a naive closed form loses ~r^2 ulps (pita computes its
determinants with fma and its powers through spectral projectors there).
"""
import argparse
from fractions import Fraction
import json
import math
import os
import random
import shutil
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cli_batch as CB  # noqa: E402
import sam_oracle as S  # noqa: E402

TOL = 1e-12
U_FIXED = [0.0, 0.25, 0.5, 1.0, 1.5, -0.5, -8.0, 12.0]
NO_SAM = "no SAM exists between these poses"


# --------------------------------------------------------------------------- 2x3 float helpers
def rot(a):
    return [[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]]


def mul2(X, Y):
    return [[X[i][0] * Y[0][j] + X[i][1] * Y[1][j] for j in range(2)] for i in range(2)]


def aff(L, t):
    return [[L[0][0], L[0][1], t[0]], [L[1][0], L[1][1], t[1]]]


def compose(A, B):
    """(A o B)(x) = A(B(x)) in doubles: [L_A L_B | L_A t_B + t_A]."""
    L = mul2([r[:2] for r in A], [r[:2] for r in B])
    t = [A[i][0] * B[0][2] + A[i][1] * B[1][2] + A[i][2] for i in range(2)]
    return aff(L, t)


def rand_linear(rng, kmin, kmax, s_min, a_max=None):
    """e^k R(a) R(-c) diag(1/s, s) R(c); |a| < a_max(s) (default: any angle)."""
    s = rng.uniform(s_min, 1.0)
    amax = math.pi if a_max is None else a_max(s)
    a = rng.uniform(-amax, amax)
    c = rng.uniform(-math.pi, math.pi)
    k = rng.uniform(kmin, kmax)
    L = mul2(rot(a), mul2(rot(-c), mul2([[1 / s, 0], [0, s]], rot(c))))
    return [[math.exp(k) * v for v in r] for r in L]


def rand_t(rng, r=5.0):
    return [rng.uniform(-r, r), rng.uniform(-r, r)]


def rand_dyadic_t(rng, r=5.0):
    """A random translation on the 1/64 grid (C = A o B stays exact for the exact poses B)."""
    return [round(rng.uniform(-r, r) * 64) / 64, round(rng.uniform(-r, r) * 64) / 64]


def rand_pose(rng):
    return aff(rand_linear(rng, -1, 1, 0.3), rand_t(rng))


def exact_poses(rng):
    """Poses B for which C = A o B is exact in doubles when A has short dyadic entries."""
    return [
        aff([[1, 0], [0, 1]], [0, 0]),
        aff([[1, 0], [0, 1]], [rng.choice([-2.5, -0.75, 0.5, 1.25, 3.0]), rng.choice([-1.5, 0.25, 2.0])]),
        aff([[2, 1], [1, 1]], [0.5, -0.25]),
        aff([[1, -2], [0, 1]], [-1.75, 0.125]),
    ]


# --------------------------------------------------------------------------- scenes
def add_case(cases, rng, family, A, B, exact=False):
    """A scene B at t0, C = A o B at t1, evaluated at the u of U_FIXED plus two random ones."""
    t0 = rng.uniform(-3, 3)
    span = math.exp(rng.uniform(math.log(0.05), math.log(10)))
    t1 = t0 + span
    us = U_FIXED + [rng.uniform(-1, 2), rng.uniform(0, 1)]
    times = []
    for u in us:
        t = t0 + u * (t1 - t0)
        if u == 1.0:
            t = t1
        times.append(t)
    C = compose(A, B)
    if exact:
        # the special structure must survive C = A o B in doubles (checked in exact rationals)
        F = [[Fraction(v) for v in r] for r in A]
        G = [[Fraction(v) for v in r] for r in B]
        exact_C = [[F[i][0] * G[0][j] + F[i][1] * G[1][j] + (F[i][2] if j == 2 else 0) for j in range(3)]
                   for i in range(2)]
        assert exact_C == [[Fraction(v) for v in r] for r in C], (family, A, B)
    cases.append({"family": family, "A": A, "B": B, "C": C, "t0": t0, "t1": t1, "times": times})


def gen_cases(rng, count):
    cases = []
    bound = lambda s: 0.98 * (1 + s) * math.pi / 2  # noqa: E731

    for _ in range(count):
        L = rand_linear(rng, -2, 2, 0.05, bound)
        add_case(cases, rng, "random", aff(L, rand_t(rng)), rand_pose(rng))

    def variants(family, A, exact_only=False, n_random=2):
        for B in exact_poses(rng):
            add_case(cases, rng, family, A, B, exact=True)
        if not exact_only:
            for _ in range(n_random):
                add_case(cases, rng, family, A, rand_pose(rng))

    # pure translation
    variants("translation", aff([[1, 0], [0, 1]], [2.5, -1.25]))
    variants("translation", aff([[1, 0], [0, 1]], rand_dyadic_t(rng)))
    # shear with translation
    variants("shear", aff([[1, 1.5], [0, 1]], [0.75, -2.0]))
    variants("shear", aff([[1, 0], [-0.625, 1]], [-3.0, 0.5]))
    variants("shear", aff([[1, round(rng.uniform(-3, 3) * 64) / 64], [0, 1]], rand_dyadic_t(rng)))
    # eigenvalue 1: diag(1, 3) with translation
    variants("diag(1,3)", aff([[1, 0], [0, 3]], [1.25, -0.5]))
    variants("diag(1,3)", aff([[1, 0], [0, 3]], rand_dyadic_t(rng)))
    # L = -2 I: half turn with uniform scale, rotation by +pi (exact poses only: a rounded
    # C B^-1 is no longer -2 I)
    variants("-2I", aff([[-2, 0], [0, -2]], [1.5, -0.75]), exact_only=True)
    variants("-2I", aff([[-0.5, 0], [0, -0.5]], [0.0, 0.0]), exact_only=True)
    variants("-2I", aff([[-1, 0], [0, -1]], [3.0, 1.0]), exact_only=True)
    # nearly a half turn (complex eigenvalues): B identity or a translation so that the
    # linear part of C B^-1 is the exact rotation (its log is ill-conditioned otherwise)
    for th, rho in ((math.pi - 1e-9, 1.0), (-(math.pi - 1e-9), 1.0), (math.pi - 1e-9, 2.0),
                    (math.pi - 1e-6, 0.5), (-(math.pi - 1e-13), 1.0), (math.pi, 1.0),
                    (-math.pi, 1.5)):
        L = [[rho * math.cos(th), -rho * math.sin(th)], [rho * math.sin(th), rho * math.cos(th)]]
        A = aff(L, rand_t(rng))
        add_case(cases, rng, "near half turn", A, aff([[1, 0], [0, 1]], [0, 0]), exact=True)
        add_case(cases, rng, "near half turn", A, aff([[1, 0], [0, 1]], [0.5, -1.25]))
    # Jordan block [[2, 1], [0, 2]]
    variants("Jordan [[2,1],[0,2]]", aff([[2, 1], [0, 2]], [0.5, -1.0]))
    variants("Jordan [[2,1],[0,2]]", aff([[2, 0], [-0.5, 2]], rand_dyadic_t(rng)))
    # double eigenvalue 3 I
    variants("3I", aff([[3, 0], [0, 3]], [-1.0, 2.25]))
    variants("3I", aff([[0.375, 0], [0, 0.375]], rand_dyadic_t(rng)))
    # near identity: L = I + 1e-9 * random (and a tiny translation once)
    for scale_t in (1.0, 1e-9, 0.0):
        for _ in range(3):
            L = [[1 + 1e-9 * rng.uniform(-1, 1), 1e-9 * rng.uniform(-1, 1)],
                 [1e-9 * rng.uniform(-1, 1), 1 + 1e-9 * rng.uniform(-1, 1)]]
            A = aff(L, [scale_t * v for v in rand_t(rng)])
            add_case(cases, rng, "near identity", A, aff([[1, 0], [0, 1]], [0, 0]))
            add_case(cases, rng, "near identity", A, rand_pose(rng))
    # near shear: [[1, k], [0, 1]] + eps * random (eigenvalues split or complex near 1)
    for eps in (1e-12, 1e-9, 1e-6):
        for _ in range(2):
            k = rng.uniform(-3, 3)
            L = [[1 + eps * rng.uniform(-1, 1), k + eps * rng.uniform(-1, 1)],
                 [eps * rng.uniform(-1, 1), 1 + eps * rng.uniform(-1, 1)]]
            A = aff(L, rand_t(rng))
            add_case(cases, rng, "near shear", A, aff([[1, 0], [0, 1]], [0, 0]))
            add_case(cases, rng, "near shear", A, rand_pose(rng))
    # near Jordan [[2, 1], [0, 2]] + eps * random
    for eps in (1e-12, 1e-8):
        for _ in range(2):
            L = [[2 + eps * rng.uniform(-1, 1), 1 + eps * rng.uniform(-1, 1)],
                 [eps * rng.uniform(-1, 1), 2 + eps * rng.uniform(-1, 1)]]
            A = aff(L, rand_t(rng))
            add_case(cases, rng, "near Jordan", A, aff([[1, 0], [0, 1]], [0, 0]))
            add_case(cases, rng, "near Jordan", A, rand_pose(rng))
    return cases


def gen_anisotropic(rng):
    """--anisotropic: L = diag(r, 1/r) and rotated copies, r up to 1e4 (kappa(L) = r^2).
    Exact diagonal inputs are perfectly conditioned entrywise; a closed form that is only
    normwise stable (atanh(s/r), cosh - sinh, a x d - b x c without fma) errs by ~r^2 eps."""
    cases = []
    for r in (10.0, 100.0, 1e3, 1e4):
        add_case(cases, rng, "anisotropic r=%g" % r, aff([[r, 0], [0, 1 / r]], [1.0, 1.0]),
                 aff([[1, 0], [0, 1]], [0, 0]))
        L = mul2(rot(0.7), mul2([[r, 0], [0, 1 / r]], rot(-0.7)))
        add_case(cases, rng, "anisotropic r=%g" % r, aff(L, [1.0, 1.0]), aff([[1, 0], [0, 1]], [0, 0]))
    return cases


def gen_refusals(rng):
    """(family, A, B, expected stderr text)."""
    out = []
    bad = [
        ("refuse diag(-2,-0.5)", [[-2, 0], [0, -0.5]], False),
        ("refuse negative Jordan", [[-1, 1], [0, -1]], True),
        ("refuse R(pi) diag(1.5,1/1.5)", [[-1.5, 0], [0, -1 / 1.5]], False),
    ]
    for family, L, exact_only in bad:
        A = aff(L, rand_dyadic_t(rng))
        Bs = exact_poses(rng) + ([] if exact_only else [rand_pose(rng), rand_pose(rng)])
        for B in Bs:
            out.append((family, A, B, NO_SAM))
    for B in exact_poses(rng)[:2]:
        out.append(("refuse det < 0", aff([[1, 0], [0, -1]], [0.5, 0.5]), B, "orientation-preserving"))
    return out


def scene_json(B, C, t0, t1):
    return json.dumps({"method": "SAM", "poses": [{"t": t0, "matrix": B}, {"t": t1, "matrix": C}]})


def cli_request(path, times):
    """The arguments of `pita eval` at these times."""
    return [path, "--t=" + ",".join(repr(float(t)) for t in times)]


# --------------------------------------------------------------------------- comparison
def oracle_frames(case):
    """The oracle's 2x3 frames (floats of the ~60-digit values) at the case's times."""
    Bh, Ch = S.homog(case["B"]), S.homog(case["C"])
    A = S.mmul(Ch, S.inv3(Bh))
    P = S.Power(A)
    t0, t1 = S.dec(case["t0"]), S.dec(case["t1"])
    out = []
    for t in case["times"]:
        u = (S.dec(t) - t0) / (t1 - t0)
        out.append(S.affine23(S.mmul(P(u), Bh)))
    return out


def frame_error(cli, ora):
    """max |cli - oracle| / max(1, ||oracle||_max) (in high precision)."""
    diff = max(abs(S.dec(cli[i][j]) - ora[i][j]) for i in range(2) for j in range(3))
    scale = max(S.D(1), max(abs(ora[i][j]) for i in range(2) for j in range(3)))
    return float(diff / scale)


def fmt_mat(M):
    return "[[%s], [%s]]" % tuple(", ".join(repr(float(v)) for v in r) for r in M)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("pita")
    ap.add_argument("--count", type=int, default=300, help="random scenes (default 300)")
    ap.add_argument("--seed", type=int, default=20240611)
    ap.add_argument("-v", "--verbose", action="store_true")
    ap.add_argument("--keep", metavar="DIR", help="copy the failing scenes into DIR")
    ap.add_argument("--anisotropic", action="store_true",
                    help="also L = diag(r, 1/r), r up to 1e4 (known to exceed the tolerance for r >~ 300)")
    args = ap.parse_args()
    tstart = time.time()
    rng = random.Random(args.seed)
    cases = gen_cases(rng, args.count)
    if args.anisotropic:
        cases += gen_anisotropic(random.Random(args.seed + 1))
    refusals = gen_refusals(rng)
    tmp = tempfile.mkdtemp(prefix="pita-sam-oracle-")
    try:
        for i, c in enumerate(cases):
            c["path"] = os.path.join(tmp, "sam-%04d.json" % i)
            with open(c["path"], "w") as f:
                f.write(scene_json(c["B"], c["C"], c["t0"], c["t1"]))
        ref_jobs = []
        for i, (family, A, B, expect) in enumerate(refusals):
            C = compose(A, B)
            path = os.path.join(tmp, "refuse-%03d.json" % i)
            with open(path, "w") as f:
                f.write(scene_json(B, C, 0.0, 1.0))
            ref_jobs.append((family, A, B, C, expect, path))

        requests = ([cli_request(c["path"], c["times"]) for c in cases] +
                    [cli_request(j[5], [0.0, 0.5, 1.0]) for j in ref_jobs])
        with ThreadPoolExecutor(max_workers=1) as ex:
            answers = ex.submit(CB.eval_many, args.pita, requests)
            # the oracle runs here while the CLI's batches proceed (cli_batch.py)
            oracles = []
            for c in cases:
                try:
                    oracles.append(oracle_frames(c))
                except S.NoSam as e:
                    oracles.append(e)
            answers = answers.result()
        results, ref_results = answers[:len(cases)], answers[len(cases):]

        failures = []
        worst = {}   # family -> (err, description)
        nframes = 0
        for c, ora, r in zip(cases, oracles, results):
            fam = c["family"]
            worst.setdefault(fam, (0.0, ""))
            where = "%s: B=%s C=%s t0=%r t1=%r" % (c["path"], fmt_mat(c["B"]), fmt_mat(c["C"]), c["t0"], c["t1"])
            if isinstance(ora, Exception):
                failures.append((math.inf, fam, "%s\n    oracle refuses (%s); CLI exit %d" % (where, ora, r.returncode)))
                continue
            if r.returncode != 0:
                failures.append((math.inf, fam, "%s\n    CLI exit %d: %s" % (where, r.returncode, r.stderr.strip()[:400])))
                continue
            try:
                doc = json.loads(r.stdout)
                frames = doc["frames"]
                assert doc.get("method") == "SAM"
            except Exception as e:  # noqa: BLE001
                failures.append((math.inf, fam, "%s\n    bad output: %s" % (where, e)))
                continue
            if len(frames) != len(c["times"]):
                failures.append((math.inf, fam, "%s\n    %d frames for %d times" % (where, len(frames), len(c["times"]))))
                continue
            for t, fr, o in zip(c["times"], frames, ora):
                nframes += 1
                if fr["t"] != t:
                    failures.append((math.inf, fam, "%s\n    CLI t %r != requested %r" % (where, fr["t"], t)))
                    continue
                e = frame_error(fr["matrix"], o)
                u = (t - c["t0"]) / (c["t1"] - c["t0"])
                desc = "%s t=%r (u~%.6g)\n    CLI    %s\n    oracle %s\n    A (oracle, C o B^-1) = %s" % (
                    where, t, u, fmt_mat(fr["matrix"]), fmt_mat(o),
                    fmt_mat(S.affine23(S.mmul(S.homog(c["C"]), S.inv3(S.homog(c["B"]))))))
                if e > worst[fam][0] or not worst[fam][1]:
                    worst[fam] = (e, desc)
                if not e <= TOL:
                    failures.append((e, fam, desc))

        for (family, A, B, C, expect, path), r in zip(ref_jobs, ref_results):
            worst.setdefault(family, (0.0, ""))
            where = "%s: B=%s C=%s" % (path, fmt_mat(B), fmt_mat(C))
            try:
                S.Power(S.mmul(S.homog(C), S.inv3(S.homog(B))))
                failures.append((math.inf, family, "%s\n    the oracle finds a SAM here" % where))
            except S.NoSam:
                pass
            ok = r.returncode == 2 and r.stdout == "" and expect in r.stderr
            if not ok:
                failures.append((math.inf, family, "%s\n    expected exit 2, empty stdout, %r on stderr; got exit %d, "
                                 "stdout %r, stderr %r" % (where, expect, r.returncode, r.stdout[:200], r.stderr[:300])))

        families = list(dict.fromkeys([c["family"] for c in cases] + [j[0] for j in ref_jobs]))
        if args.verbose or failures:
            for fam in families:
                e, desc = worst.get(fam, (0.0, ""))
                n = sum(1 for c in cases if c["family"] == fam) + sum(1 for j in ref_jobs if j[0] == fam)
                nf = sum(1 for f in failures if f[1] == fam)
                print("%-30s scenes %4d  worst %.2e  failures %d" % (fam, n, e, nf))
                if args.verbose and desc:
                    print("    worst at " + desc.replace("\n", "\n    "))
        if failures:
            failures.sort(key=lambda f: -f[0])
            print("FAIL: %d mismatches (tolerance %.0e * max(1, ||oracle||_max)); worst cases:" % (len(failures), TOL))
            for e, fam, desc in failures[:12]:
                print("  [%s] error %.3e: %s" % (fam, e, desc))
            if args.keep:
                os.makedirs(args.keep, exist_ok=True)
                for path in {d.split(":")[0] for _, _, d in failures}:
                    if os.path.exists(path):
                        shutil.copy(path, args.keep)
        worst_all = max((w[0] for w in worst.values()), default=0.0)
        print("compare_sam_with_cli: %d scenes, %d frames, %d refusals; worst relative error %.2e "
              "(tolerance %.0e); %s in %.1f s" % (len(cases), nframes, len(ref_jobs), worst_all, TOL,
                                                  "FAIL" if failures else "OK", time.time() - tstart))
        return 1 if failures else 0
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
