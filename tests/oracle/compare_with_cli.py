#!/usr/bin/env python3
"""Compare `pita eval` with the independent oracle pita_oracle.py on random scenes.

usage: compare_with_cli.py PATH/TO/pita [--configs N] [--seed S] [--methods P1,P6,...] [-v]

For each method, N random keyframe configurations (fixed seed) are written as scene JSON and
evaluated by one `pita eval SCENE --t ...` request each (`pita eval --batch`, cli_batch.py) (knots plus random times, some outside
[a, c]).  p and q are compared with an absolute tolerance of TOL times the scale of the frame
(max of the keyframes' extent and the frame's distance from the keyframes' centre); w exactly
to TOL*max(1,|w|) for winding-carrying methods, modulo 2 pi for P1 P7 P8 (docs/reference/methods.md: principal
angle).  Exit 1 on any mismatch (or CLI failure), 0 otherwise.
"""
import argparse
import cmath
import json
import math
import os
import random
import re
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cli_batch as CB  # noqa: E402
import pita_oracle as O  # noqa: E402

TOL = 1e-9
# P7/P8 are checked against the oracle's own closed form (derived independently from the ODEs);
# their hyperbolic functions of complex k amplify rounding near kappa = -1, hence a looser tolerance.
TOL_BY_METHOD = {"P7": 1e-8, "P8": 1e-8}
METHODS = ["P1", "P2", "P3", "P4", "P5", "P5S", "P6", "P7", "P8", "P9", "P10", "SMA"]


# --------------------------------------------------------------------------- generation
def rand_mag(rng):
    return math.exp(rng.uniform(math.log(0.05), math.log(20.0)))


def rand_arrow(rng, scale, centre, turns_max):
    p = centre + complex(rng.uniform(-1, 1), rng.uniform(-1, 1)) * scale
    m = rand_mag(rng)
    w = rng.uniform(-math.pi, math.pi) + 2 * math.pi * rng.randint(-turns_max, turns_max)
    return (p, m, w)


def gen_config(rng, method, i):
    """Returns (knots, arrows, kind)."""
    nk = 2 if method == "SMA" else 3
    a = rng.uniform(-3, 3)
    span = math.exp(rng.uniform(math.log(0.05), math.log(10)))
    c = a + span
    r = rng.random()
    if r < 0.3:
        b = (a + c) / 2
        kind = "even"
    elif r < 0.4:
        b = a + span * rng.choice([0.001, 0.02, 0.98, 0.999, 0.1, 0.9])
        kind = "skewed"
    else:
        b = a + span * rng.uniform(0.15, 0.85)
        kind = "uneven"
    scale = math.exp(rng.uniform(math.log(0.05), math.log(20)))
    centre = complex(rng.uniform(-10, 10), rng.uniform(-10, 10))
    turns_max = rng.choice([0, 1, 3, 6])
    arrows = [rand_arrow(rng, scale, centre, turns_max) for _ in range(nk)]
    special = rng.random()
    if nk == 3 and special < 0.06:
        # Fig. 28: B snapped to the steady average of A and C
        arrows[1] = O.sma(arrows[0], arrows[2], 0.5)
        kind += "+B=M(A,C)"
    elif special < 0.10:
        # equal vectors: pure translation (PITA Eq. 15)
        arrows[1] = (arrows[1][0], arrows[0][1], arrows[0][2])
        kind += "+translation"
    elif special < 0.13:
        # same vector up to whole turns: the twirl fallback of docs/reference/methods.md (no twirl exists)
        arrows[1] = (arrows[1][0], arrows[0][1], arrows[0][2] + 2 * math.pi * rng.choice([-2, -1, 1, 2]))
        kind += "+whole-turns"
    elif special < 0.16:
        # nearly equal vectors (twirl close to a translation)
        e = 10 ** rng.uniform(-11, -5)
        arrows[1] = (arrows[1][0], arrows[0][1] * (1 + e), arrows[0][2] + e)
        kind += "+near-translation"
    elif nk == 3 and special < 0.24:
        # kappa = (vA + vC) / (2 vB) at or near 1 (P7/P8: parabola/cubic limits, series)
        e = rng.choice([0.0, 1e-13, 1e-9, 1e-6, 1e-4, 1e-2])
        e = complex(e * rng.uniform(-1, 1), e * rng.uniform(-1, 1))
        vb = (O.vec(arrows[0]) + O.vec(arrows[2])) / 2 * (1 + e)
        if abs(vb) > 1e-3:
            wb = cmath.phase(vb) + 2 * math.pi * rng.randint(-1, 1)
            arrows[1] = (arrows[1][0], abs(vb), wb)
            kind += "+kappa~1(%.0e)" % abs(e)
    elif nk == 3 and special < 0.30:
        # origin of B within ~1e-12 of A's or C's (P2's documented parabola fallback)
        j = rng.choice([0, 2])
        e = rng.choice([0.0, 1e-13, 3e-12, 1e-11, 1e-9])
        ext = abs(arrows[2][0] - arrows[0][0])
        arrows[1] = (arrows[j][0] + e * ext * cmath.exp(1j * rng.uniform(-3, 3)), arrows[1][1], arrows[1][2])
        kind += "+pB~p%s(%.0e)" % ("AC"[j // 2], e)
    elif nk == 3 and special < 0.33:
        # collinear origins (P2: real spiral ratio, possibly a reversal)
        d = arrows[2][0] - arrows[0][0]
        arrows[1] = (arrows[0][0] + d * rng.choice([0.3, 0.5, 1.7, -0.6]), arrows[1][1], arrows[1][2])
        kind += "+collinear"
    knots = [a, c] if nk == 2 else [a, b, c]
    return knots, arrows, kind, span


def gen_times(rng, knots, n=24):
    a, c = knots[0], knots[-1]
    span = c - a
    ts = list(knots)
    if rng.random() < 0.1:  # far extrapolation (may overflow: then both must)
        ts += [a - 20 * span, c + 20 * span]
    for _ in range(n):
        if rng.random() < 0.7:
            ts.append(rng.uniform(a, c))
        else:
            ts.append(rng.uniform(a - 0.75 * span, c + 0.75 * span))
    return ts


def encode(rng, knots, arrows):
    """Keyframe JSON: m/w, m/w + turns, or q (zero-turn) forms.  Returns (kfs, arrows as
    the CLI will read them)."""
    kfs, out = [], []
    for t, (p, m, w) in zip(knots, arrows):
        r = rng.random()
        if r < 0.15:
            q = p + m * cmath.exp(1j * w)
            kfs.append({"t": t, "p": [p.real, p.imag], "q": [q.real, q.imag]})
            v = q - p
            out.append((p, abs(v), cmath.phase(v)))
        elif r < 0.3:
            k = rng.randint(-3, 3)
            w0 = w - 2 * math.pi * k
            kfs.append({"t": t, "p": [p.real, p.imag], "m": m, "w": w0, "turns": k})
            out.append((p, m, w0 + 2 * math.pi * k))
        else:
            kfs.append({"t": t, "p": [p.real, p.imag], "m": m, "w": w})
            out.append((p, m, w))
    return kfs, out


def scene_json(method, kfs, options=None):
    d = {"method": method, "keyframes": kfs}
    if options:
        d["options"] = options
    return json.dumps(d)


# --------------------------------------------------------------------------- comparison
def wrap(d):
    return math.atan2(math.sin(d), math.cos(d))


def errors(method, D, fr, centre, extent, options=None):
    """Relative errors (p, q, w, m) of CLI frame fr against oracle arrow D."""
    p_o, q_o = D[0], O.endpoint(D)
    p_c = complex(*fr["p"])
    q_c = complex(*fr["q"])
    scale = max(extent, abs(p_o - centre), abs(q_o - centre))
    ep = abs(p_c - p_o) / scale
    eq = abs(q_c - q_o) / scale
    if method in O.PRINCIPAL_W:
        # the angle of the frame's vector: conditioned by scale / m
        ew = abs(wrap(fr["w"] - D[2])) / max(1.0, scale / max(D[1], 1e-300))
    else:
        ew = abs(fr["w"] - D[2]) / max(1.0, abs(D[2]))
    # magnitude: relative to the frame's scale too (P2's -Po magnitude may cross 0)
    em = abs(fr["m"] - D[1]) / scale
    e = {"p": ep, "q": eq, "w": ew, "m": em}
    if method in LOG_MAGNITUDE and (options or {}).get("magnitude_mean", "geometric") == "geometric" \
            and D[1] > 0:
        # m = exp(blend of logs): relative error, conditioned by the size of the exponent
        e["mrel"] = abs(fr["m"] - D[1]) / D[1] / max(1.0, abs(math.log(D[1])))
    return e


def perturbed(rng, knots, arrows, t, eps):
    """Inputs moved by ~eps relative (knots and t relative to the knot span)."""
    span = knots[-1] - knots[0]
    sc = max(abs(A[0]) for A in arrows) + max(A[1] for A in arrows)
    ks = [k + span * eps * rng.uniform(-1, 1) for k in knots]
    ks.sort()
    ar = [(A[0] + sc * eps * complex(rng.uniform(-1, 1), rng.uniform(-1, 1)),
           A[1] * (1 + eps * rng.uniform(-1, 1)),
           A[2] + max(1.0, abs(A[2])) * eps * rng.uniform(-1, 1)) for A in arrows]
    tt = t + max(span, abs(t)) * eps * rng.uniform(-1, 1)
    return list(zip(ks, ar)), tt


# methods whose magnitude is the exponential of a blend of log-magnitudes (-LP, Sec. 2.5, 2.8)
LOG_MAGNITUDE = {"P3", "P4", "P5", "P5S", "P6", "P9", "P10", "SMA"}
SENS_EPS = 1e-14   # ~50 ulp
SENS_FACTOR = 10.0
INTER_ULPS = 4096.0  # allowed error floor in ulps of the largest intermediate term  # allowed error = max(tol, SENS_FACTOR * observed sensitivity)


def compare(method, knots, arrows, times, frames, tol, options):
    """Returns per frame (err/allowed, field, t, detail, conditioned) with err/allowed <= 1 passing.

    The plain check is err <= tol.  Where it fails, the problem's conditioning is estimated
    by re-evaluating the oracle on inputs perturbed by SENS_EPS (relative); a frame whose
    error stays within SENS_FACTOR times that spread is ill-conditioned, not a mismatch.
    """
    pts = [A[0] for A in arrows] + [O.endpoint(A) for A in arrows]
    centre = sum(pts) / len(pts)
    extent = max(max(abs(x - y) for x in pts for y in pts), max(A[1] for A in arrows))
    kf = list(zip(knots, arrows))
    out = []
    for t, fr in zip(times, frames):
        if fr["t"] != t:
            out.append((float("inf"), "t", t, "CLI t %r != requested %r" % (fr["t"], t), False))
            continue
        try:
            D = O.evaluate(method, kf, t, options)
            inter = O.last_intermediate_scale()
        except (OverflowError, ZeroDivisionError, ValueError):  # e.g. log of an underflowed m
            D, inter = (complex(math.nan, math.nan), math.nan, math.nan), math.inf
        vals = [D[0].real, D[0].imag, D[1], D[2]]
        if not all(math.isfinite(v) for v in vals):
            # the oracle itself over/underflowed (e.g. m -> 0 far outside [a, c]): the frame
            # is meaningless; accept it only if the CLI's frame is degenerate as well.
            cm, cp = fr["m"], max(abs(x) for x in fr["p"] + fr["q"])
            degenerate = cm == 0 or cm > 1e300 or cp > 1e300 or inter > 1e300
            out.append((0.0 if degenerate else float("inf"), "nonfinite", t,
                        "oracle non-finite %r, CLI %r" % (D, fr), "degenerate"))
            continue
        e = errors(method, D, fr, centre, extent, options)
        field = max(e, key=e.get)
        ratio = e[field] / tol
        cond = False
        if ratio > 1:
            rng = random.Random(repr((knots, t)))
            sens = dict.fromkeys(e, 0.0)
            for _ in range(4):
                kp, tp = perturbed(rng, knots, arrows, t, SENS_EPS)
                try:
                    Dp = O.evaluate(method, kp, tp, options)
                except (OverflowError, ZeroDivisionError, ValueError):
                    continue
                fake = {"t": t, "p": [Dp[0].real, Dp[0].imag], "m": Dp[1], "w": Dp[2],
                        "q": [O.endpoint(Dp).real, O.endpoint(Dp).imag]}
                ep = errors(method, D, fake, centre, extent, options)
                for k in sens:
                    sens[k] = max(sens[k], ep[k])
            allowed = {k: max(tol, SENS_FACTOR * sens[k]) for k in e}
            # cancellation between intermediate terms of this size (a few thousand ulps)
            scale = max(extent, abs(D[0] - centre), abs(O.endpoint(D) - centre))
            for k in ("p", "q", "m"):
                allowed[k] = max(allowed[k], INTER_ULPS * 2.2e-16 * inter / scale)
            r = {k: e[k] / allowed[k] for k in e}
            field = max(r, key=r.get)
            ratio = r[field]
            cond = allowed[field] > tol
        detail = "cli p=%r q=%r m=%r w=%r | oracle p=%r q=%r m=%r w=%r (err %.3g)" % (
            complex(*fr["p"]), complex(*fr["q"]), fr["m"], fr["w"],
            D[0], O.endpoint(D), D[1], D[2], e[field])
        out.append((ratio, field, t, detail, cond))
    return out


def cli_request(path, times, method):
    """The arguments of `pita eval` for these times and this method."""
    return [path, "--t=" + ",".join(repr(float(t)) for t in times), "--method", method]


# the CLI's refusal of a frame that would not be finite (docs/reference/exit-codes-and-limits.md "Exit codes, errors and limits");
# two wordings seen across builds
NONFINITE = re.compile(r"(?:non-finite arrow|no finite frame) at t = ([-+0-9.eE]+|inf|nan)")


def oracle_overflows(method, knots, arrows, t, options):
    try:
        D = O.evaluate(method, list(zip(knots, arrows)), t, options)
    except (OverflowError, ZeroDivisionError, ValueError):
        return True
    q = O.endpoint(D)
    vals = [D[0].real, D[0].imag, D[1], D[2], q.real, q.imag]
    # also degenerate: the magnitude underflows to 0, or an intermediate term overflows
    return (not all(math.isfinite(v) and abs(v) < 1e300 for v in vals) or D[1] < 1e-300
            or not O.last_intermediate_scale() < 1e300)


def run_jobs(pita, jobs):
    """Runs the CLI on every job, in batches (cli_batch.py); where it refuses a non-finite
    frame, checks that the oracle overflows there too, drops that time and asks again in the
    next round.  Returns [(returncode, stdout, stderr, times, dropped)] in the order of jobs."""
    times = [list(job[5]) for job in jobs]
    dropped = [[] for _ in jobs]
    results = [None] * len(jobs)
    pending = list(range(len(jobs)))
    for _ in range(max((len(t) for t in times), default=0) + 1):
        if not pending:
            break
        answers = CB.eval_many(pita, [cli_request(jobs[k][6], times[k], jobs[k][0]) for k in pending])
        again = []
        for k, r in zip(pending, answers):
            method, i, knots, arrows, kind, _, path, options = jobs[k]
            results[k] = (r.returncode, r.stdout, r.stderr, times[k], dropped[k])
            m = NONFINITE.search(r.stderr) if r.returncode == 2 else None
            if not m:
                continue
            tbad = float(m.group(1))
            near = sorted((t for t in times[k] if abs(t - tbad) <= 1e-12 * max(1.0, abs(t))),
                          key=lambda t: abs(t - tbad))
            if not near:
                continue
            ok = oracle_overflows(method, knots, arrows, near[0], options)
            dropped[k].append((near[0], ok))
            if not ok:
                results[k] = (r.returncode, r.stdout, r.stderr + " [oracle is finite there]",
                              times[k], dropped[k])
                continue
            times[k].remove(near[0])
            again.append(k)
        pending = again
    return results


# Hand-made regression scenes (method, knots, arrows, options, times, label), checked like
# the random ones.
FIXED = [
    # Sec. 2.7 variant: magnitude_mean stays geometric, so m must be 20^u to rounding
    ("SMA", [0.0, 1.0], [(0j, 1.0, 0.0), (1 + 0j, 20.0, 1.0)], {"path_mean": "arithmetic"},
     [-5.0, -10.0, -12.0, 0.5, 3.0], "fixed: arithmetic path, geometric magnitude"),
    ("SMA", [0.0, 1.0], [(0j, 1.0, 0.0), (1 + 0j, 20.0, 1.0)], {"path_mean": "harmonic"},
     [-5.0, -10.0, -12.0, 0.5, 3.0], "fixed: harmonic path, geometric magnitude"),
    # the same inside [a, c]: P9 (PITA Eq. D.2) with an arithmetic path keeps -LP magnitudes
    ("P9", [0.0, 0.01, 1.0], [(0j, 1.0, 0.0), (1 + 0j, 20.0, 1.0), (2 + 1j, 1.0, 0.0)],
     {"path_mean": "arithmetic"}, [0.1, 0.2, 0.5], "fixed: P9 arithmetic path, skewed knots"),
    # Fig. 28 / docs/paper-notes.md N14 configuration, with extrapolation (Sec. 7.5)
    ("P6", [0.0, 0.5, 1.0], [(0j, 1.0, 0.4), (3 + 1.5j, 0.6, 2.0), (6 + 0j, 1.2, 3.5 + 2 * math.pi)],
     None, [-0.5, 0.0, 0.25, 0.5, 1.0, 1.5], "fixed: fig01 keyframes, C with one more turn"),
]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("pita")
    ap.add_argument("--configs", type=int, default=200)
    ap.add_argument("--seed", type=int, default=20240611)
    ap.add_argument("--methods", default=",".join(METHODS))
    ap.add_argument("-v", "--verbose", action="store_true")
    ap.add_argument("--keep", metavar="DIR", help="copy the failing scenes into DIR")
    args = ap.parse_args()
    methods = args.methods.split(",")
    t0 = time.time()
    tmp = tempfile.mkdtemp(prefix="pita-oracle-")
    jobs = []
    for method in methods:
        rng = random.Random("%d-%s" % (args.seed, method))
        for i in range(args.configs):
            knots, arrows, kind, span = gen_config(rng, method, i)
            times = gen_times(rng, knots)
            kfs, arrows = encode(rng, knots, arrows)
            options = None
            if method == "P2" and rng.random() < 0.3:
                options = {"anchor": "midpoint"}
                kind += "+anchor=midpoint"
            if method in ("SMA", "P9") and rng.random() < 0.4:
                means = ["arithmetic", "geometric", "harmonic"]
                options = {"path_mean": rng.choice(means), "magnitude_mean": rng.choice(means)}
                kind += "+%s/%s" % (options["path_mean"][:5], options["magnitude_mean"][:5])
            path = os.path.join(tmp, "%s-%03d.json" % (method, i))
            with open(path, "w") as f:
                f.write(scene_json(method, kfs, options))
            jobs.append((method, i, knots, arrows, kind, times, path, options))

    for k, (method, knots, arrows, options, times, kind) in enumerate(FIXED):
        if method not in methods:
            continue
        kfs = [{"t": t, "p": [A[0].real, A[0].imag], "m": A[1], "w": A[2]} for t, A in zip(knots, arrows)]
        path = os.path.join(tmp, "%s-fixed%d.json" % (method, k))
        with open(path, "w") as f:
            f.write(scene_json(method, kfs, options))
        jobs.append((method, "fixed%d" % k, knots, arrows, kind, times, path, options))

    results = run_jobs(args.pita, jobs)

    summary = {}
    failures = []
    for job, (rc, out, err, times, dropped) in zip(jobs, results):
        method, i, knots, arrows, kind, _, path, options = job
        s = summary.setdefault(method, {"configs": 0, "worst": 0.0, "where": "", "fail": 0,
                                        "frames": 0, "overflow": 0, "illcond": 0})
        s["configs"] += 1
        s["overflow"] += sum(1 for _, ok in dropped if ok)
        tol = TOL_BY_METHOD.get(method, TOL)
        if rc != 0:
            s["fail"] += 1
            failures.append((method, path, "exit %d: %s" % (rc, err.strip()[:400])))
            continue
        try:
            frames = json.loads(out)["frames"]
        except Exception as e:  # noqa: BLE001
            s["fail"] += 1
            failures.append((method, path, "bad JSON: %s" % e))
            continue
        if len(frames) != len(times):
            s["fail"] += 1
            failures.append((method, path, "%d frames for %d times" % (len(frames), len(times))))
            continue
        bad_here = None
        for ratio, field, t, detail, cond in compare(method, knots, arrows, times, frames, tol, options):
            s["frames"] += 1
            s["illcond"] += cond is True
            s["overflow"] += cond == "degenerate"
            if not ratio <= 1:
                if bad_here is None or ratio > bad_here[0]:
                    bad_here = (ratio, field, t, detail)
            if ratio * tol > s["worst"] and cond is False:
                s["worst"] = ratio * tol
                s["where"] = "config %s (%s) t=%r field %s" % (i, kind, t, field)
        if bad_here:
            s["fail"] += 1
            failures.append((method, path, "%s err/allowed %.3g at t=%r (%s): %s" % (
                bad_here[1], bad_here[0], bad_here[2], kind, bad_here[3])))

    print("tolerance %.0e of the frame's scale (P7, P8: %.0e); ill-conditioned frames allowed "
          "%g x the oracle's spread under %.0e input perturbations" % (
              TOL, TOL_BY_METHOD["P7"], SENS_FACTOR, SENS_EPS))
    print("%-5s %7s %7s %7s %9s %9s %10s  %s" % ("meth", "configs", "frames", "failing",
                                                 "illcond", "degen", "worst", "where"))
    failed = False
    for method in methods:
        s = summary[method]
        print("%-5s %7d %7d %7d %9d %9d %10.3g  %s" % (
            method, s["configs"], s["frames"], s["fail"], s["illcond"], s["overflow"],
            s["worst"], s["where"]))
        failed |= s["fail"] > 0
    if failures:
        shown = {}
        print("\nmismatches (first 3 per method; -v for all):")
        for method, path, msg in failures:
            shown[method] = shown.get(method, 0) + 1
            if shown[method] <= 3 or args.verbose:
                with open(path) as f:
                    print("  %s %s\n    scene: %s\n    %s" % (method, os.path.basename(path),
                                                        f.read(), msg))
        if args.keep:
            os.makedirs(args.keep, exist_ok=True)
            for method, path, msg in failures:
                with open(path) as f, open(os.path.join(args.keep, os.path.basename(path)), "w") as g:
                    g.write(f.read())
    for j in jobs:
        os.unlink(j[6])
    os.rmdir(tmp)
    print("\n%d configurations, %.1f s: %s" % (len(jobs), time.time() - t0,
                                              "FAIL" if failed else "OK"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
