#!/usr/bin/env python3
"""Compare `pita eval` on scenes with a "timing" field with the independent oracle
timing_oracle.py (eases, arc-length reparameterisation, per motion / per span) on top of
pita_oracle.py (the unwarped motions).

usage: compare_timing_with_cli.py PATH/TO/pita [--configs N] [--seed S] [--methods P1,P6,...]
                                  [-j JOBS] [-v] [--keep DIR]
                                  [--clamp-overshoot | --clamp-arc-overshoot]

For each method, N random keyframe configurations (fixed seed; tame keyframes: no degenerate
twirls, knots even or uneven with the middle knot in [0.2, 0.8] of the range) are each given a
random timing: an ease among every named one ("linear", "ease", "ease-in", "ease-out",
"ease-in-out", "sine", "cubic"), a random "cubic-bezier(x1, y1, x2, y2)" (x1, x2 in [0, 1],
y1, y2 in [-0.5, 1.5]), a random sine cap {"sine": {"k1", "k2"}} or parabolic
{"parabolic": {"t1", "t2"}} (edges k1 = k2, t1 = t2, 0 and 1 included), with or without
"arc_length" ("p", "q", "mid"), "per" "motion", "span" or absent.  Each scene is evaluated by
one `pita eval SCENE --t ...` request (`pita eval --batch`, cli_batch.py) at the knots, random times inside [t_0, t_n] and a few
outside.  Plus the crafted scenes of CRAFTED.

Every frame's "t" must equal the requested time exactly; p and q must match the oracle to
TOL (1e-8) times the frame's scale (max of the keyframes' extent and the frame's distance
from the keyframes' centre), as compare_with_cli.py does.  With arc_length, a frame whose
motion time is ill-determined by the length (the tracked point nearly at rest there while the
arrow moves) is allowed ARC_REL x L x |X'(tau)| / |tracked'(tau)| on top (X = p or q, L the
path length of the range, ARC_REL the relative accuracy either side can be expected to reach
on L); and any frame is allowed SENS_FACTOR times the change of the oracle's frame when
x = (t - from)/(to - from) moves by X_ULPS ulps (an ease with a vertical tangent, e.g.
cubic-bezier(1, y1, 0, y2) at x = 1/2, turns ulps of x into ~1e-5 of the frame).  Frames
passing only thanks to these allowances are counted as "illcond".  Frames where the oracle's
warp is undefined (an overshooting ease asking for more length than the path has beyond its
range within 32 range widths) or its motion overflows are not compared ("undef").

Overshoot (an ease value y outside [0, 1], e.g. cubic-bezier with y1 or y2 outside [0, 1]):
the oracle follows the specification, tau = from + y (to - from) without arc length and the
signed arc length continued beyond the range with it; --clamp-overshoot (y clamped to [0, 1]
always) and --clamp-arc-overshoot (only with arc_length) compare against those readings
instead.

Exit 1 on any mismatch (or CLI failure), 0 otherwise.
"""
import argparse
import cmath
import json
import math
import os
import random
import sys
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cli_batch as CB  # noqa: E402
import pita_oracle as O  # noqa: E402
import timing_oracle as T  # noqa: E402
from compare_with_cli import encode  # noqa: E402  (keyframes in the three JSON forms)

TOL = 1e-8
ARC_REL = 1e-11
# sensitivity to the rounding of x = (t - from)/(to - from): x moved by X_ULPS ulps of 1, the
# frame may differ by SENS_FACTOR times the oracle's own change
X_ULPS = 8
SENS_FACTOR = 10.0
# every method of pita_oracle; P4, P7, P8 go through the piecewise-quadratic knot warp (only
# C1 at the knots), which the oracle's arc length handles with one-sided differences there
# (timing_oracle.Timing.breaks); the others are analytic in time.
METHODS = ["P1", "P2", "P3", "P4", "P5", "P5S", "P6", "P7", "P8", "P9", "P10", "SMA"]
NAMED = ["linear", "ease", "ease-in", "ease-out", "ease-in-out", "sine", "cubic"]


# --------------------------------------------------------------------------- generation
def rand_arrow(rng, scale, centre, turns_max):
    p = centre + complex(rng.uniform(-1, 1), rng.uniform(-1, 1)) * scale
    m = math.exp(rng.uniform(math.log(0.1), math.log(5.0))) * scale
    w = rng.uniform(-math.pi, math.pi) + 2 * math.pi * rng.randint(-turns_max, turns_max)
    return (p, m, w)


def gen_config(rng, method):
    nk = 2 if method == "SMA" else 3
    a = rng.uniform(-3, 3)
    span = math.exp(rng.uniform(math.log(0.1), math.log(10)))
    c = a + span
    if rng.random() < 0.3:
        b, kind = (a + c) / 2, "even"
    else:
        b, kind = a + span * rng.uniform(0.2, 0.8), "uneven"
    scale = math.exp(rng.uniform(math.log(0.1), math.log(10)))
    centre = complex(rng.uniform(-5, 5), rng.uniform(-5, 5)) * scale
    turns_max = rng.choice([0, 0, 1])
    arrows = [rand_arrow(rng, scale, centre, turns_max) for _ in range(nk)]
    knots = [a, c] if nk == 2 else [a, b, c]
    return knots, arrows, kind


def fmt(v):
    """A short decimal that pita and the oracle both read as the same double."""
    return repr(round(v, 6) + 0.0)


def rand_ease(rng):
    r = rng.random()
    if r < 0.35:
        return rng.choice(NAMED)
    if r < 0.6:
        x1, x2 = rng.uniform(0, 1), rng.uniform(0, 1)
        y1, y2 = rng.uniform(-0.5, 1.5), rng.uniform(-0.5, 1.5)
        if rng.random() < 0.1:
            x1 = rng.choice([0.0, 1.0])
        if rng.random() < 0.1:
            x2 = rng.choice([0.0, 1.0])
        sep = rng.choice([", ", ",", " , "])
        return "cubic-bezier(%s)" % sep.join(fmt(v) for v in (x1, y1, x2, y2))
    if r < 0.8:
        k1 = rng.uniform(0.0, 0.7)
        k2 = rng.uniform(k1, 1.0)
        e = rng.random()
        if e < 0.15:
            k2 = k1
        elif e < 0.2:
            k1 = 0.0
        elif e < 0.25:
            k2 = 1.0
        k1, k2 = float(fmt(k1)), float(fmt(k2))
        return {"sine": {"k1": k1, "k2": max(k1, k2)}}
    t1 = rng.uniform(0.0, 0.7)
    t2 = rng.uniform(t1, 1.0)
    e = rng.random()
    if e < 0.15:
        t2 = t1
    elif e < 0.2:
        t1 = 0.0
    elif e < 0.25:
        t2 = 1.0
    elif e < 0.28:
        t1, t2 = 0.0, 1.0
    t1, t2 = float(fmt(t1)), float(fmt(t2))
    return {"parabolic": {"t1": t1, "t2": max(t1, t2)}}


def rand_timing(rng):
    tm = {"ease": rand_ease(rng)}
    r = rng.random()
    if r < 0.55:
        tm["arc_length"] = rng.choice(["p", "q", "mid"])
    r = rng.random()
    if r < 0.45:
        tm["per"] = "span"
    elif r < 0.75:
        tm["per"] = "motion"
    return tm


def gen_times(rng, knots, n_in=14, n_out=3):
    a, c = knots[0], knots[-1]
    span = c - a
    ts = list(knots)
    for _ in range(n_in):
        ts.append(rng.uniform(a, c))
    for _ in range(n_out):
        ts.append(rng.choice([rng.uniform(a - 0.5 * span, a), rng.uniform(c, c + 0.5 * span)]))
    # just inside the ends (x near 0 and 1)
    ts += [a + span * 1e-7, c - span * 1e-7]
    return ts




# --------------------------------------------------------------------------- crafted cases
FIG01 = [(0.0, (0j, 1.0, 0.4)), (0.5, (3 + 1.5j, 0.6, 2.0)), (1.0, (6 + 0j, 1.2, 3.5))]
FIG01_UNEVEN = [(0.0, (0j, 1.0, 0.4)), (0.3, (3 + 1.5j, 0.6, 2.0)),
                (1.2, (6 + 0j, 1.2, 3.5 + 2 * math.pi))]
X19 = [i / 10 for i in range(1, 10)]
OVERSHOOT_T = [i / 20 for i in range(0, 21)]
CRAFTED = [
    # (label, method, keyframes, timing, times)
    ("ease-in-out, no arc length, P6 at x = 0.1..0.9", "P6", FIG01,
     {"ease": "ease-in-out"}, X19),
    ("ease-in-out, no arc length, P6 per span, uneven knots", "P6", FIG01_UNEVEN,
     {"ease": "ease-in-out", "per": "span"}, [0.3 * x for x in X19] + [0.3 + 0.9 * x for x in X19]),
    ("cubic-bezier overshoot above 1", "P6", FIG01,
     {"ease": "cubic-bezier(0.2, 1.5, 0.8, 1.5)"}, OVERSHOOT_T),
    ("cubic-bezier overshoot below 0 and above 1", "P9", FIG01_UNEVEN,
     {"ease": "cubic-bezier(0.3, -0.5, 0.7, 1.5)", "per": "span"},
     [0.3 * x for x in OVERSHOOT_T] + [0.3 + 0.9 * x for x in OVERSHOOT_T]),
    ("cubic-bezier overshoot with arc length p", "P6", FIG01,
     {"ease": "cubic-bezier(0.2, 1.5, 0.8, 1.5)", "arc_length": "p"}, OVERSHOOT_T),
    ("cubic-bezier overshoot with arc length mid per span", "P3", FIG01_UNEVEN,
     {"ease": "cubic-bezier(0.3, -0.5, 0.7, 1.5)", "arc_length": "mid", "per": "span"},
     [0.3 * x for x in OVERSHOOT_T] + [0.3 + 0.9 * x for x in OVERSHOOT_T]),
    ("cubic-bezier overshoot with arc length q, SMA", "SMA", FIG01[:2],
     {"ease": "cubic-bezier(0.5, -0.5, 0.5, 1.5)", "arc_length": "q"}, OVERSHOOT_T),
    ("parabolic t1 = 0, t2 = 1 (linear)", "P6", FIG01,
     {"ease": {"parabolic": {"t1": 0, "t2": 1}}}, X19 + [-0.2, 1.3]),
    ("parabolic t1 = 0, t2 = 1 with arc length q per span", "P1", FIG01_UNEVEN,
     {"ease": {"parabolic": {"t1": 0, "t2": 1}}, "arc_length": "q", "per": "span"},
     [0.3 * x for x in X19] + [0.3 + 0.9 * x for x in X19]),
    ("sine cap k1 = k2 = 0.5 (= sine)", "P6", FIG01,
     {"ease": {"sine": {"k1": 0.5, "k2": 0.5}}}, X19),
    ("sine cap k1 = k2 = 0.3", "SMA", FIG01[:2],
     {"ease": {"sine": {"k1": 0.3, "k2": 0.3}}}, X19),
    ("sine cap k1 = k2 = 0.7, arc length p", "P9", FIG01_UNEVEN,
     {"ease": {"sine": {"k1": 0.7, "k2": 0.7}}, "arc_length": "p"}, [1.2 * x for x in X19]),
    # the midpoint's path has a narrow burst of speed (~50x its mean) near tau = 0.006: an
    # arc-length table must refine there (found by the random scenes, seed 20240611)
    ("P9 arc length mid through a narrow burst of speed", "P9",
     [(-0.36633230502602787, (7.023321047092342 + 4.626663741312174j, 3.4181310047286506,
                              10.467103140292604 - 4 * math.pi)),
      (0.9426015482095127, (9.441226174668213 + 4.478595012657974j, 1.4557645975659819,
                            4.05372235475599 - 2 * math.pi)),
      (1.497209479123986, (9.435061406598933 + 9.429802497570588j, 1.1005130578067275,
                           1.3949336661382823))],
     {"ease": {"sine": {"k1": 0.002763, "k2": 0.630009}}, "arc_length": "mid"},
     [-0.36633230502602787 + 1.8635417841500139 * i / 40 for i in range(41)]),
]


# --------------------------------------------------------------------------- comparison
def scene_json(method, kfs, timing):
    return json.dumps({"method": method, "keyframes": kfs, "timing": timing})


def cli_request(path, times):
    """The arguments of `pita eval` at these times."""
    return [path, "--t=" + ",".join(repr(float(t)) for t in times)]


def speed(tm, f, u):
    return abs(T.derivative(f, u, tm.h, tm.breaks))


def check_job(job):
    """Compares every frame of the CLI's answer on one scene (cli_batch.py) with the oracle.
    Returns a dict."""
    t_start = time.time()
    res = check_job_timed(job)
    res["seconds"] = time.time() - t_start
    return res


def check_job_timed(job):
    pita, label, method, knots, arrows, timing, times, path, clamp, clamp_arc, r = job
    res = {"label": label, "method": method, "path": path, "timing": timing, "frames": 0,
           "worst": 0.0, "where": "", "bad": None, "illcond": 0, "error": None,
           "arc": "arc_length" in timing, "undefined": 0}
    if r.returncode != 0:
        res["error"] = "exit %d: %s" % (r.returncode, r.stderr.strip()[:400])
        return res
    try:
        frames = json.loads(r.stdout)["frames"]
    except Exception as e:  # noqa: BLE001
        res["error"] = "bad JSON: %s" % e
        return res
    if len(frames) != len(times):
        res["error"] = "%d frames for %d times" % (len(frames), len(times))
        return res
    kf = list(zip(knots, arrows))
    tm = T.Timing(method, kf, None, timing, clamp_overshoot=clamp,
                  clamp_arc_overshoot=clamp_arc)
    pts = [A[0] for A in arrows] + [O.endpoint(A) for A in arrows]
    centre = sum(pts) / len(pts)
    extent = max(max(abs(x - y) for x in pts for y in pts), max(A[1] for A in arrows))
    for t, fr in zip(times, frames):
        res["frames"] += 1
        if fr["t"] != t:
            res["bad"] = (math.inf, "t", t, "CLI t %r != requested %r" % (fr["t"], t))
            continue
        try:
            tau = tm.tau(t)
            D = tm.motion(tau)
        except (ArithmeticError, ValueError) as e:  # incl. T.Unreachable, OverflowError
            # the oracle's warp is undefined there (an overshooting ease asks for more length
            # than the path has beyond its range) or its motion overflows: not compared
            res["undefined"] += 1
            res["undefined_what"] = "t=%r: %s" % (t, e)
            continue
        p_o, q_o = D[0], O.endpoint(D)
        p_c, q_c = complex(*fr["p"]), complex(*fr["q"])
        scale = max(extent, abs(p_o - centre), abs(q_o - centre))
        e = {"p": abs(p_c - p_o) / scale, "q": abs(q_c - q_o) / scale}
        allowed = {"p": TOL, "q": TOL}
        if knots[0] <= t <= knots[-1] and max(e.values()) > TOL:
            # x = (t - from)/(to - from) is itself rounded: where the ease is steep (a
            # cubic-bezier whose x'(s) vanishes inside (0, 1) has a vertical tangent there,
            # y - y0 ~ (x - x0)^(1/3)) a few ulps of x move the frame visibly
            lo, hi = tm.range_of(t)
            x = (t - lo) / (hi - lo)
            for dx in (-X_ULPS * 2.2e-16, X_ULPS * 2.2e-16):
                try:
                    Dx = tm.motion(tm.tau_of_x(lo, hi, x + dx))
                except (ArithmeticError, ValueError):
                    continue
                for k, v in (("p", Dx[0]), ("q", O.endpoint(Dx))):
                    ref = p_o if k == "p" else q_o
                    allowed[k] = max(allowed[k], SENS_FACTOR * abs(v - ref) / scale)
        if tm.arc and knots[0] <= t <= knots[-1] and max(e[k] / allowed[k] for k in e) > 1:
            lo, hi = tm.range_of(t)
            Al = tm.arc_length(lo, hi)
            sx = speed(tm, tm.tracked, tau)
            for k, f in (("p", lambda u: tm.motion(u)[0]), ("q", lambda u: O.endpoint(tm.motion(u)))):
                extra = ARC_REL * Al.length * speed(tm, f, tau) / max(sx, 1e-300) / scale
                allowed[k] = max(allowed[k], extra)
        ratio = {k: e[k] / allowed[k] for k in e}
        field = max(ratio, key=ratio.get)
        cond = allowed[field] > TOL
        res["illcond"] += cond and e[field] > TOL
        if not cond and e[field] > res["worst"]:
            res["worst"] = e[field]
            res["where"] = "t=%r tau=%r field %s" % (t, tau, field)
        if not ratio[field] <= 1:
            xy = ""
            if knots[0] <= t <= knots[-1]:
                lo, hi = tm.range_of(t)
                x = (t - lo) / (hi - lo)
                xy = "range [%r, %r] x=%r ease(x)=%r " % (lo, hi, x, tm.ease(x))
            detail = "%scli p=%r q=%r | oracle p=%r q=%r tau=%r (err %.3g of scale %.3g)" % (
                xy, p_c, q_c, p_o, q_o, tau, e[field], scale)
            if res["bad"] is None or ratio[field] > res["bad"][0]:
                res["bad"] = (ratio[field], field, t, detail)
    return res


def build_jobs(args, tmp):
    methods = args.methods.split(",")
    jobs = []
    for method in methods:
        rng = random.Random("%d-timing-%s" % (args.seed, method))
        for i in range(args.configs):
            knots, arrows, kind = gen_config(rng, method)
            timing = rand_timing(rng)
            times = gen_times(rng, knots)
            kfs, arrows = encode(rng, knots, arrows)
            path = os.path.join(tmp, "%s-%03d.json" % (method, i))
            with open(path, "w") as f:
                f.write(scene_json(method, kfs, timing))
            jobs.append((args.pita, "%s %d (%s)" % (method, i, kind), method, knots, arrows,
                         timing, times, path, args.clamp_overshoot, args.clamp_arc_overshoot))
    for k, (label, method, kf, timing, times) in enumerate(CRAFTED):
        knots = [t for t, _ in kf]
        arrows = [A for _, A in kf]
        kfs = [{"t": t, "p": [A[0].real, A[0].imag], "m": A[1], "w": A[2]} for t, A in kf]
        path = os.path.join(tmp, "crafted-%02d.json" % k)
        with open(path, "w") as f:
            f.write(scene_json(method, kfs, timing))
        jobs.append((args.pita, "crafted: " + label, method, knots, arrows, timing, times, path,
                     args.clamp_overshoot, args.clamp_arc_overshoot))
    return methods, jobs


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("pita")
    ap.add_argument("--configs", type=int, default=40, help="random scenes per method")
    ap.add_argument("--seed", type=int, default=20240611)
    ap.add_argument("--methods", default=",".join(METHODS))
    ap.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("-v", "--verbose", action="store_true")
    ap.add_argument("--keep", metavar="DIR", help="copy the failing scenes into DIR")
    ap.add_argument("--clamp-overshoot", action="store_true",
                    help="clamp y = ease(x) to [0, 1] in the oracle (an alternative reading of "
                         "the specification, which does not clamp)")
    ap.add_argument("--clamp-arc-overshoot", action="store_true",
                    help="the same with arc_length only (the fraction of the path length)")
    args = ap.parse_args()
    args.pita = os.path.abspath(args.pita)
    t0 = time.time()
    tmp = tempfile.mkdtemp(prefix="pita-timing-oracle-")
    methods, jobs = build_jobs(args, tmp)
    answers = CB.eval_many(args.pita, [cli_request(job[7], job[6]) for job in jobs], args.jobs)
    jobs = [job + (answer,) for job, answer in zip(jobs, answers)]
    with ProcessPoolExecutor(max_workers=max(1, args.jobs)) as ex:
        results = list(ex.map(check_job, jobs, chunksize=1))

    rows = {}
    failures = []
    for res in results:
        key = "crafted" if res["label"].startswith("crafted") else res["method"]
        s = rows.setdefault(key, {"scenes": 0, "arc": 0, "frames": 0, "fail": 0, "illcond": 0,
                                  "undef": 0, "worst": 0.0, "where": ""})
        s["undef"] += res["undefined"]
        s["scenes"] += 1
        s["arc"] += res["arc"]
        s["frames"] += res["frames"]
        s["illcond"] += res["illcond"]
        if res["worst"] > s["worst"]:
            s["worst"] = res["worst"]
            s["where"] = "%s %s" % (res["label"], res["where"])
        if res["error"] or res["bad"]:
            s["fail"] += 1
            msg = res["error"] or "%s err/allowed %.3g at t=%r: %s" % (
                res["bad"][1], res["bad"][0], res["bad"][2], res["bad"][3])
            failures.append((key, res, msg))

    print("timing oracle vs `pita eval`: p, q within %.0e of the frame's scale; t exact; "
          "overshooting eases %s" % (TOL, "clamped to [0, 1]" if args.clamp_overshoot else
                                    "clamped to [0, 1] with arc length only"
                                    if args.clamp_arc_overshoot else "not clamped"))
    print("%-8s %6s %5s %7s %7s %8s %6s %10s  %s" % ("method", "scenes", "arc", "frames",
                                                     "failing", "illcond", "undef", "worst", "where"))
    for key in methods + ["crafted"]:
        if key not in rows:
            continue
        s = rows[key]
        print("%-8s %6d %5d %7d %7d %8d %6d %10.3g  %s" % (
            key, s["scenes"], s["arc"], s["frames"], s["fail"], s["illcond"], s["undef"],
            s["worst"], s["where"][:100]))
    if failures:
        shown = {}
        print("\nmismatches (first 3 per method; -v for all):")
        for key, res, msg in failures:
            shown[key] = shown.get(key, 0) + 1
            if shown[key] <= 3 or args.verbose:
                with open(res["path"]) as f:
                    print("  %s\n    scene: %s\n    %s" % (res["label"], f.read(), msg))
        if args.keep:
            os.makedirs(args.keep, exist_ok=True)
            for key, res, msg in failures:
                with open(res["path"]) as f, \
                        open(os.path.join(args.keep, os.path.basename(res["path"])), "w") as g:
                    g.write(f.read())
    for j in jobs:
        os.unlink(j[7])
    os.rmdir(tmp)
    if args.verbose:
        undef = [r for r in results if r["undefined"]]
        if undef:
            print("\nframes not compared (oracle undefined):")
            for r in undef:
                print("  %s %s: %d frame(s), e.g. %s" % (r["label"], json.dumps(r["timing"]),
                                                       r["undefined"], r["undefined_what"]))
    slow = max(results, key=lambda r: r["seconds"])
    print("\nslowest scene (the oracle's side): %s, %.1f s (%s)" % (slow["label"], slow["seconds"],
                                               json.dumps(slow["timing"])))
    nframes = sum(s["frames"] for s in rows.values())
    print("\n%d scenes, %d frames, %.1f s: %s" % (len(jobs), nframes, time.time() - t0,
                                                 "FAIL" if failures else "OK"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
