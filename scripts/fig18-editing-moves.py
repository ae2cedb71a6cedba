#!/usr/bin/env python3
"""The editing test of PITA Sec. 6.3 (Fig. 18), played by a perfect user.

The user sees the P8 pattern through A, B, C (knots 0, 1/2, 1), the frame
D(1/4) and a target arrow E, and drags B to bring D(1/4) onto E. A click
nearer B.p than B.q translates B by the drag; otherwise the drag moves B.q
only. This user alternates the two moves, and each drag is the one that
aligns exactly one point: a translation of B that puts D(1/4).p on E.p, then
a move of B.q that puts D(1/4).q on E.q (each found by Newton's method on the
two coordinates, the frames computed by `pita eval`). A move undoes part of
the previous one, as Sec. 6.3 says for the non-independent PITAs; the script
prints B and the distance max(|dp|, |dq|) after every move, and the scene
fig18-editing.json takes B after four moves (the paper's count for P8).

usage: scripts/fig18-editing-moves.py [--pita build/pita] [--moves 4]
"""
import argparse
import json
import math
import subprocess
import tempfile

A = {"t": 0, "p": [0, 0], "m": 1.0, "w": 0.6}
B = {"p": [3.0, 2.0], "q": [3.0 + 0.6 * math.cos(1.5), 2.0 + 0.6 * math.sin(1.5)]}
C = {"t": 1, "p": [6, 0], "m": 1.4, "w": 2.3}
E = {"p": [1.4, 1.9], "q": [1.9, 2.5]}
T = 0.25


def frame(pita, b):
    scene = {"method": "P8", "keyframes": [A, {"t": 0.5, "p": b["p"], "q": b["q"]}, C]}
    with tempfile.NamedTemporaryFile("w", suffix=".json") as f:
        json.dump(scene, f)
        f.flush()
        out = subprocess.run([pita, "eval", f.name, "--t", str(T), "--format", "csv"], check=True,
                             capture_output=True, text=True).stdout.strip().splitlines()[-1]
    t, px, py, m, w, qx, qy = map(float, out.split(","))
    return (px, py), (qx, qy)


def align(pita, b, which):
    """The drag that puts D(T).<which> on E.<which>: Newton on the drag vector."""
    index = 0 if which == "p" else 1
    target = E[which]
    v = [0.0, 0.0]

    def moved(v):
        if which == "p":  # the click is near B.p: the drag translates B
            return {"p": [b["p"][0] + v[0], b["p"][1] + v[1]], "q": [b["q"][0] + v[0], b["q"][1] + v[1]]}
        return {"p": list(b["p"]), "q": [b["q"][0] + v[0], b["q"][1] + v[1]]}

    for _ in range(30):
        x = frame(pita, moved(v))[index]
        r = [x[0] - target[0], x[1] - target[1]]
        if math.hypot(*r) < 1e-13:
            break
        h = 1e-6
        jx = frame(pita, moved([v[0] + h, v[1]]))[index]
        jy = frame(pita, moved([v[0], v[1] + h]))[index]
        J = [[(jx[0] - x[0]) / h, (jy[0] - x[0]) / h], [(jx[1] - x[1]) / h, (jy[1] - x[1]) / h]]
        det = J[0][0] * J[1][1] - J[0][1] * J[1][0]
        v = [v[0] - (J[1][1] * r[0] - J[0][1] * r[1]) / det, v[1] - (-J[1][0] * r[0] + J[0][0] * r[1]) / det]
    return moved(v)


def distance(pita, b):
    p, q = frame(pita, b)
    return max(math.dist(p, E["p"]), math.dist(q, E["q"]))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--pita", default="build/pita")
    parser.add_argument("--moves", type=int, default=4)
    args = parser.parse_args()
    b = B
    print(f"move 0: B = {json.dumps(b)}  d = {distance(args.pita, b):.6g}")
    for move in range(1, args.moves + 1):
        b = align(args.pita, b, "p" if move % 2 == 1 else "q")
        print(f"move {move}: B = {json.dumps({'p': [repr(x) for x in b['p']], 'q': [repr(x) for x in b['q']]})}"
              f"  d = {distance(args.pita, b):.6g}")


if __name__ == "__main__":
    main()
