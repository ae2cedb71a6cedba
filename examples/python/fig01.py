"""Fig. 1 of the PITA paper from Python: the eight PITAs P1-P8 through the same three
timed keyframes, as numbers and as a matplotlib figure.

    python3 PATH/TO/examples/python/fig01.py [OUT.png]     (with the module on PYTHONPATH)

prints, for each PITA, the frame D(t) at t = 0.25 and 0.75 (start point p, magnitude m,
winding w), the numbers `pita eval scenes/fig01-eight-pitas.json --panel N --t 0.25,0.75`
prints, and draws the 17 frames of each panel as in scenes/fig01-eight-pitas.json
(OUT.png, default fig01.png in the working directory). It reads pita's own scene
(pita.example), so it runs from any folder. Needs python3-matplotlib.
"""
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt
import numpy as np

import pita


def main(out):
    scene = pita.load_scene(pita.example("fig01-eight-pitas"))    # pita's own scenes/, from any folder
    figure, axes = plt.subplots(2, 4, figsize=(12, 6), sharex=True, sharey=True)
    print(f"{'panel':<6}{'method':<14}{'t':>6}{'p.x':>12}{'p.y':>12}{'m':>12}{'w':>12}")
    for panel, ax in enumerate(axes.flat):
        # The panel's own method and options, through the scene's keyframes.
        p, m, w, q = scene.eval(samples=17, panel=panel)
        for (x0, y0), (x1, y1) in zip(p, q):
            ax.plot([x0, x1], [y0, y1], color="#1f4fd0", linewidth=1)
        ax.plot(p[:, 0], p[:, 1], color="gray", linewidth=0.5, linestyle="--")
        method = scene.motion(panel=panel).label     # "P6 (La-LP)"
        ax.set_title(method)
        ax.set_aspect("equal")
        at = scene.eval(np.array([0.25, 0.75]), panel=panel)
        for k, t in enumerate((0.25, 0.75)):
            print(f"{panel:<6}{method:<14}{t:>6}{at.p[k, 0]:>12.6f}{at.p[k, 1]:>12.6f}{at.m[k]:>12.6f}{at.w[k]:>12.6f}")
    figure.suptitle("Fig. 1: eight PITAs through the same three keyframes")
    figure.tight_layout()
    figure.savefig(out, dpi=100)
    print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "fig01.png")
