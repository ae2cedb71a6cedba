#!/usr/bin/env python3
"""Compare `pita eval` of the pose PITAs P4, P5, P6 and P9 with the independent oracle
pose_pita_oracle.py (numpy + scipy's principal matrix log and exp).

usage: compare_pose_pitas_with_cli.py PATH/TO/pita [--count N] [--seed S] [--kinds K,...] [-v] [--keep DIR]

Builds (fixed seed, temp dir) N random affine triples in the plane and N in space, of the kinds
of pose_pita_oracle.KINDS in turn (tame; wild: any turn, stretches up to 4, shears; stretch:
anisotropic scales up to 12; uneven: knots as close as 0.02 beside a span of 2; near: neighbours
that differ by 1e-8 to 1e-3, every power near the identity; entries: each entry of each pose
uniform in [-2, 2], det > 0.05) and every seventh tame, wild, stretch or uneven one
with a neighbour turning by pi - d, d in [1e-3, 0.3] (near the half turn, where stretched pairs
lose their SAM). Each triple is a pose scene ("poses" of 2x3 or 3x4 matrices, "dimension": 3 in
space) with "method" P4, P5, P6 and P9 in turn, evaluated by one `pita eval SCENE --t T` per
time (`pita eval --batch`, cli_batch.py): the knots, 4 times inside [a, c], and a - w/2, a - w/10,
c + w/5, c + w/2 (w = c - a).

Every frame must be what the oracle says, computed from the poses exactly as written:
- a pose: pita exits 0 and its matrix matches: max |pita - oracle| <= tolerance * max(1, max |oracle|);
- a refusal (a power the construction needs has no real value, at every time or at this t):
  pita exits 2 with empty stdout, and stderr says "method P6" (say) and "no SAM" or "no real"
  (docs/paper-notes.md N74).
Either answer is accepted (but a pose must be finite), and the frame counted as "boundary", where
- the oracle's margin (pose_pita_oracle.margin: how far the powers taken are from having an
  eigenvalue on the closed negative real axis) is within NEAR = 1e-6 of 0: rounding decides;
- a pose the construction forms at t is lost to rounding (its determinant, known exactly since
  det is multiplicative, is not what doubles give: far outside [a, c] with close knots the
  powers reach exponents of 70 and the poses' small singular values fall below the rounding
  of the large ones), or the frame's tolerance (below) exceeds ILL = 1e-4: doubles do not know
  the frame to 1e-4, let alone whether its power is real.
Anywhere else, a frame refused by pita and not by the oracle is a failure, and so is the reverse.

Tolerance: max(TOL, SPREAD * spread, GROWTH_EPS * growth), TOL = 1e-9, where
- `spread` (SPREAD = 10) is the oracle's own rounding noise on that frame: the max-norm relative
  difference between the oracle computed in the world frame, (B o A^-1)^s o A, and in the body
  frame, A o (A^-1 o B)^s, equal in exact arithmetic. On well-conditioned frames both sides
  agree to ~1e-13 and TOL decides; on strongly stretched (non-normal) poses scipy's log and exp
  lose up to ~1e-8, the spread shows it (against a 60-digit log and exp, sam3d_oracle.py's, the
  world frame's error was at most 1.8 times the spread on 80 triples), and the tolerance follows;
- `growth` (GROWTH_EPS = 1e-12) is how much the morph M(P, Q, s) = X^s o P formed at t magnifies
  rounding errors (Motion.last_growth): the larger condition number of P and Q (X = Q o P^-1 is
  known to about eps cond) times the cancellation |X^s| |P| / max(1, |D|), which reaches 1e5
  far outside [a, c] with close knots. 1e-12 rather than eps: the powers met there are nearly
  singular (eigenvalues from 1e-5 to 0.3), and pita's 3D EAR, which goes through eigenvectors,
  is accurate to ~eps cond on them (8e-13 against the 60-digit oracle on one, where scipy's
  Schur method gives 6e-15); tame triples have growth below 100.
The number of frames whose tolerance exceeds TOL is printed ("> TOL").

Exit 1 on any mismatch, 0 otherwise.
"""
import argparse
import json
import math
import os
import re
import shutil
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cli_batch as CB  # noqa: E402
import pose_pita_oracle as O  # noqa: E402

TOL = 1e-9
SPREAD = 10
REFUSAL = re.compile(r"no SAM|no real")   # docs/paper-notes.md N74's wording
GROWTH_EPS = 1e-12
ILL = 1e-4     # a frame known to no better than this in doubles: either answer accepted
KIND_ORDER = ("tame", "wild", "stretch", "uneven", "near", "entries")


def oracle_frames(method, poses, knots, times):
    """[(pose or NoRealPower, margin, tolerance)]: the world frame's answer, the smaller margin
    of the two frames, and the frame's tolerance (inf where one frame refuses and the other does
    not: then the margin is at the boundary)."""
    out = []
    for (w, mw, gw), (b, mb, _) in zip(O.evaluate(method, poses, knots, times),
                                       O.evaluate(method, poses, knots, times, body=True)):
        refused = isinstance(w, O.NoRealPower), isinstance(b, O.NoRealPower)
        if refused[0] != refused[1]:
            out.append((w, 0.0, math.inf))
        elif refused[0]:
            out.append((w, max(mw, mb), max(TOL, GROWTH_EPS * gw)))
        else:
            out.append((w, min(mw, mb), max(TOL, SPREAD * O.rel_err(w, b), GROWTH_EPS * gw)))
    return out


def entries_triple(rng, n):
    """Three poses whose entries are uniform in [-2, 2] (translations in [-3, 3]), redrawn until
    det L > 0.05: no relation between neighbours."""
    poses = []
    while len(poses) < 3:
        P = np.hstack([rng.uniform(-2, 2, size=(n, n)), rng.uniform(-3, 3, size=(n, 1))])
        if np.linalg.det(P[:, :n]) > 0.05:
            poses.append(P)
    a = rng.uniform(-1, 1)
    b = a + rng.uniform(0.2, 2)
    return poses, (a, b, b + rng.uniform(0.2, 2))


def near_triple(rng, n):
    """Poses B = A o (I + e N), C = B o (I + e N'), N, N' standard normal, e in [1e-8, 1e-3]
    (log-uniform): slow motions, every power near the identity."""
    e = 10 ** rng.uniform(-8, -3)
    I = np.hstack([np.eye(n), np.zeros((n, 1))])
    A = O.random_pose(rng, n, "tame")
    B = O.pose(O.hom(A) @ O.hom(I + e * rng.normal(size=(n, n + 1))))
    C = O.pose(O.hom(B) @ O.hom(I + e * rng.normal(size=(n, n + 1))))
    a = rng.uniform(-1, 1)
    b = a + rng.uniform(0.2, 2)
    return [A, B, C], (a, b, b + rng.uniform(0.2, 2))


def gen_triples(rng, count, kinds=KIND_ORDER):
    """count triples in 2D and count in 3D: (dimension, kind, poses, knots, points or None)."""
    out = []
    for n in (2, 3):
        for i in range(count):
            kind = kinds[i % len(kinds)]
            turns = (None, None)
            if i % 7 == 6 and kind not in ("near", "entries"):
                d = math.exp(rng.uniform(math.log(1e-3), math.log(0.3)))
                turns = (None, math.copysign(math.pi - d, rng.uniform(-1, 1)))
                kind = "halfturn-" + kind
            if kind in ("near", "entries"):
                poses, knots = (near_triple if kind == "near" else entries_triple)(rng, n)
            else:
                poses, knots = O.random_triple(rng, n, kind.split("-")[-1], turns)
            points = None
            if i % 3 == 2:   # given as triangles / tetrahedra: the oracle takes the pose pita reads
                points = [simplex_of(P)[0] for P in poses]
                poses = [simplex_of(P)[1] for P in poses]
                kind += "+simplex"
            out.append((n, kind, poses, knots, points))
    return out


def times_for(knots):
    a, b, c = knots
    w = c - a
    inside = [a + w * f for f in (0.13, 0.37, 0.61, 0.88)]
    return [a, b, c] + inside + [a - 0.5 * w, a - 0.1 * w, c + 0.2 * w, c + 0.5 * w]


def simplex_of(P):
    """The images p0 = b, p_i = b + L e_i of the reference triangle / tetrahedron (the default
    one, the standard simplex: its frame is the identity), and the pose pita reads back from
    them, [p_1 - p0, ..., p_n - p0 | p0] (docs/reference/pose-scenes.md)."""
    n = P.shape[0]
    pts = [P[:, n]] + [P[:, n] + P[:, i] for i in range(n)]
    return pts, np.column_stack([p - pts[0] for p in pts[1:]] + [pts[0]])


def scene_json(n, method, poses, knots, points=None):
    """A pose scene; with points, the poses given as triangles (tetrahedra in space)."""
    def entry(i):
        if points:
            return {"t": float(knots[i]), ("triangle", "tetrahedron")[n - 2]:
                    [[float(v) for v in p] for p in points[i]]}
        return {"t": float(knots[i]), "matrix": [[float(v) for v in row] for row in poses[i]]}
    doc = {"method": method, "samples": 3, "poses": [entry(i) for i in range(3)]}
    if n == 3:
        doc["dimension"] = 3
    return json.dumps(doc)


def fmt(P):
    return json.dumps([[float(v) for v in row] for row in np.asarray(P)])


def judge(method, ora, margin, tol, ans):
    """The kind of the frame ('pose', 'refusal' or 'boundary'), the error of a compared pose, and
    None when pita's answer agrees with the oracle's, else a message."""
    boundary = abs(margin) <= O.NEAR or tol > ILL
    kind = "boundary" if boundary else ("refusal" if isinstance(ora, O.NoRealPower) else "pose")
    if ans.returncode == 0:
        try:
            frames = json.loads(ans.stdout)["frames"]
            D = np.array(frames[0]["matrix"], dtype=float)
        except Exception as e:  # noqa: BLE001
            return kind, math.inf, "unreadable output (%s): %r" % (e, ans.stdout[:200])
        if not np.all(np.isfinite(D)):
            return kind, math.inf, "pita returns a non-finite pose %s" % fmt(D)
        if boundary:
            return kind, 0.0, None
        if isinstance(ora, O.NoRealPower):
            return kind, math.inf, "pita returns %s, the oracle refuses (%s)" % (fmt(D), ora)
        e = O.rel_err(D, ora)
        if not e <= tol:
            return kind, e, "error %.3e > %.1e (margin %.3g)\n      pita   %s\n      oracle %s" % (
                e, tol, margin, fmt(D), fmt(ora))
        return kind, e, None
    if ans.returncode == 2 and ans.stdout == "" and "method " + method in ans.stderr and REFUSAL.search(ans.stderr):
        if boundary or isinstance(ora, O.NoRealPower):
            return kind, 0.0, None
        return kind, math.inf, "pita refuses, the oracle does not (margin %.3g): %s" % (
            margin, ans.stderr.strip()[:300])
    return kind, math.inf, "pita exit %d (expected 0, or 2 naming %s): stdout %r stderr %r" % (
        ans.returncode, method, ans.stdout[:100], ans.stderr.strip()[:300])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("pita")
    ap.add_argument("--count", type=int, default=40, help="random triples per dimension (default 40)")
    ap.add_argument("--seed", type=int, default=5757)
    ap.add_argument("--kinds", default=",".join(KIND_ORDER),
                    help="the kinds of triple, in turn (default %(default)s)")
    ap.add_argument("-v", "--verbose", action="store_true")
    ap.add_argument("--keep", metavar="DIR", help="copy the scenes of failing frames into DIR")
    args = ap.parse_args()
    tstart = time.time()
    rng = np.random.default_rng(args.seed)
    kinds = tuple(args.kinds.split(","))
    if not set(kinds) <= set(KIND_ORDER):
        ap.error("--kinds: one of " + ", ".join(KIND_ORDER))
    triples = gen_triples(rng, args.count, kinds)
    tmp = tempfile.mkdtemp(prefix="pita-pose-pitas-")
    try:
        jobs = []   # (path, n, kind, method, poses, knots, t, oracle, margin, tolerance)
        for i, (n, kind, poses, knots, points) in enumerate(triples):
            times = times_for(knots)
            for method in O.METHODS:
                path = os.path.join(tmp, "pose-%dd-%03d-%s.json" % (n, i, method))
                with open(path, "w") as f:
                    f.write(scene_json(n, method, poses, knots, points))
                for t, (ora, margin, tol) in zip(times, oracle_frames(method, poses, knots, times)):
                    jobs.append((path, n, kind, method, poses, knots, t, ora, margin, tol))
        answers = CB.eval_many(args.pita, [[j[0], "--t", repr(j[6])] for j in jobs])

        stats = {}   # (n, method) -> counts and worst error
        failures = []
        for job, ans in zip(jobs, answers):
            path, n, kind, method, poses, knots, t, ora, margin, tol = job
            if tol == math.inf:
                margin = 0.0
            fkind, e, msg = judge(method, ora, margin, tol, ans)
            st = stats.setdefault((n, method), {"pose": 0, "refusal": 0, "boundary": 0, "worst": 0.0,
                                                "pita_refusals": 0, "loose": 0, "at_t": 0})
            st[fkind] += 1
            st["loose"] += fkind == "pose" and tol > TOL
            st["at_t"] += fkind == "refusal" and ora.t is not None
            st["pita_refusals"] += ans.returncode == 2
            if fkind == "pose" and e < math.inf and e >= st["worst"]:
                st["worst"], st["where"] = e, "%s [%s] t=%r knots=%r margin %.3g tolerance %.2g" % (
                    path, kind, t, knots, margin, tol)
            if msg:
                failures.append((e, (n, method, kind), "%dD %s [%s] %s t=%r knots=%r\n      poses %s\n      %s" % (
                    n, method, kind, path, t, knots, " ".join(fmt(P) for P in poses), msg)))
                if args.keep:
                    os.makedirs(args.keep, exist_ok=True)
                    shutil.copy(path, args.keep)

        print("frames per method: the oracle's poses, refusals (of them, at a time: a power formed at t),")
        print("boundary or ill-conditioned cases (either answer accepted), pita's refusals, poses compared to more")
        print("than TOL")
        print("%-8s %6s %8s %6s %8s %8s %7s %12s" % ("method", "poses", "refused", "at t", "boundary", "by pita",
                                                     "> TOL", "worst error"))
        for (n, method), st in sorted(stats.items()):
            print("%dD %-5s %6d %8d %6d %8d %8d %7d %12.2e" % (
                n, method, st["pose"], st["refusal"], st["at_t"], st["boundary"], st["pita_refusals"], st["loose"],
                st["worst"]))
        if args.verbose:
            for (n, method), st in sorted(stats.items()):
                print("worst %dD %s: %.2e at %s" % (n, method, st["worst"], st.get("where", "-")))
        if failures:
            failures.sort(key=lambda f: -f[0])
            groups = {}
            for _, key, _ in failures:
                groups[key] = groups.get(key, 0) + 1
            print("FAIL: %d frames disagree (%s); %s:" % (len(failures), ", ".join(
                "%dD %s %s: %d" % (k + (v,)) for k, v in sorted(groups.items())), "all" if args.verbose else "the worst"))
            for _, _, msg in failures[:None if args.verbose else 12]:
                print("  " + msg)
        worst = max((st["worst"] for st in stats.values()), default=0.0)
        print("compare_pose_pitas_with_cli: %d triples, %d frames; worst relative error %.2e (tolerance %.0e);"
              " %s in %.1f s" % (len(triples), len(jobs), worst, TOL, "FAIL" if failures else "OK",
                                 time.time() - tstart))
        return 1 if failures else 0
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
