"""The Python module measured side by side with the C++ it calls, and with SciPy.
Run by scripts/bench-report.sh python (report_python of scripts/bench_report.py),
with the module on PYTHONPATH; prints one JSON object:

  motion_ns      ns per frame of pita.motion("P6", ...)(times), 10^6 times in one call
                 (the keyframes of BM_StageFrame/P6, which measures the same frames in C++)
  ear_ns         ns per matrix of pita.ear_power over 10^5 different 2D affinities at t = 1/2
  scipy_us       microseconds per matrix of scipy.linalg.fractional_matrix_power in a loop
                 over the same matrices (homogeneous 3x3), on the first `scipy_count`
  import_ms      the time `import pita` adds to a python3 that starts and imports NumPy

Usage: bench_python.py [--check]   (--check: tiny sizes, one round)
"""
import json
import statistics
import subprocess
import sys
import time

import numpy as np
import scipy.linalg

import pita

CHECK = "--check" in sys.argv
ROUNDS = 1 if CHECK else 5
FRAMES = 1000 if CHECK else 1_000_000
MATRICES = 100 if CHECK else 100_000
SCIPY = 10 if CHECK else 1000


def best(call, rounds=ROUNDS):
    """The fastest of `rounds` timings of call() (the least disturbed), in seconds."""
    times = []
    for _ in range(rounds):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return min(times)


def main():
    keys = [pita.Arrow((0, 0), 1, 0.4), pita.Arrow((3, 1.5), 0.6, 2), pita.Arrow((6, 0), 1.2, 3.5)]
    motion = pita.motion("P6", keys, [0, 0.45, 1])
    times = np.linspace(0, 1, FRAMES)
    motion_ns = best(lambda: motion(times)) / FRAMES * 1e9

    rng = np.random.default_rng(1)
    L = np.eye(2) + 0.3 * rng.standard_normal((MATRICES, 2, 2))
    keep = np.linalg.det(L) > 0.2
    M = np.concatenate([L, rng.standard_normal((MATRICES, 2, 1))], axis=2)[keep]
    M = M[[bool(pita.has_sam(m)) for m in M]]
    ear_ns = best(lambda: pita.ear_power(M, 0.5)) / len(M) * 1e9
    H = np.zeros((len(M), 3, 3))
    H[:, :2] = M
    H[:, 2, 2] = 1
    scipy_s = best(lambda: [scipy.linalg.fractional_matrix_power(h, 0.5) for h in H[:SCIPY]], min(ROUNDS, 3))
    scipy_us = scipy_s / SCIPY * 1e6

    def started(code):
        runs = []
        for _ in range(1 if CHECK else 11):
            start = time.perf_counter()
            subprocess.run([sys.executable, "-c", code], check=True)
            runs.append(time.perf_counter() - start)
        return statistics.median(runs)
    import_ms = (started("import numpy, pita") - started("import numpy")) * 1e3

    print(json.dumps({"motion_ns": motion_ns, "frames": FRAMES, "ear_ns": ear_ns, "matrices": len(M),
                      "scipy_us": scipy_us, "scipy_count": SCIPY, "import_ms": import_ms}))


if __name__ == "__main__":
    main()
