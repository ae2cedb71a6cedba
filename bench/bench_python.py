"""The Python module measured side by side with the C++ it calls, and with SciPy.
Run by scripts/bench-report.sh python (report_python of scripts/bench_report.py),
with the module on PYTHONPATH; prints one JSON object:

  motion_ns      ns per frame of pita.motion("P6", ...)(times), 10^6 times in one call
                 (the keyframes of BM_StageFrame/P6, which measures the same frames in C++)
  ear_ns         ns per matrix of pita.ear_power over 10^5 different 2D affinities at t = 1/2
                 in one batched call
  ear_loop_ns    ns per call of pita.ear_power(M[k], 0.5) in a Python loop over the first
                 `loop_count` of those matrices, one matrix a call (each a 2x3 array)
  ear_list_ns    the same loop with each matrix a list of rows of Python floats
  scipy_us       microseconds per matrix of scipy.linalg.fractional_matrix_power in a loop
                 over the same matrices (homogeneous 3x3), on the first `scipy_count`
  import_ms      the time `import pita` takes in a python3 that has imported NumPy (-X importtime,
                 median of 11 processes)

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
LOOP = 100 if CHECK else 10_000


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
    singles = list(M[:LOOP])
    listed = [m.tolist() for m in singles]
    power = pita.ear_power

    def loop(matrices):
        for m in matrices:
            power(m, 0.5)
    ear_loop_ns = best(lambda: loop(singles)) / len(singles) * 1e9
    ear_list_ns = best(lambda: loop(listed)) / len(listed) * 1e9
    H = np.zeros((len(M), 3, 3))
    H[:, :2] = M
    H[:, 2, 2] = 1
    scipy_s = best(lambda: [scipy.linalg.fractional_matrix_power(h, 0.5) for h in H[:SCIPY]], min(ROUNDS, 3))
    scipy_us = scipy_s / SCIPY * 1e6

    def import_time():
        """The time of `import pita` in a python3 that has imported NumPy, by python3 -X importtime
        (the difference of two process start-ups, about 90 ms each, drowns it on a busy machine)."""
        done = subprocess.run([sys.executable, "-X", "importtime", "-c", "import numpy, pita"], check=True,
                              capture_output=True, text=True)
        line = next(line for line in done.stderr.splitlines() if line.split("|")[-1].strip() == "pita")
        return int(line.split("|")[1]) / 1e3   # the cumulative microseconds, as ms
    import_ms = statistics.median(import_time() for _ in range(1 if CHECK else 11))

    print(json.dumps({"motion_ns": motion_ns, "frames": FRAMES, "ear_ns": ear_ns, "matrices": len(M),
                      "ear_loop_ns": ear_loop_ns, "ear_list_ns": ear_list_ns, "loop_count": len(singles),
                      "scipy_us": scipy_us, "scipy_count": SCIPY, "import_ms": import_ms}))


if __name__ == "__main__":
    main()
