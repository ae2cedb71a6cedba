#!/usr/bin/env python3
"""ctest packaging.consumer: examples/consumer, a CMake project of its own, finds the pita
installed into PREFIX (find_package(pita 0.2 REQUIRED), pita::core), is built and run; its
frames and its A^t are checked against values computed here, independently of src/core:

- P6 at the knot t = 0.5 is the keyframe B (a PITA interpolates its keyframes), and at
  t = 0.25 what tests/oracle/pita_oracle.py (written from the paper) computes;
- A = 4 R(pi/2) about c = (1, 2), so A^(1/2) = 2 R(pi/4) about c: L = sqrt(2) [[1, -1], [1, 1]],
  b = c - L c.

The same main.cpp is also compiled with pkg-config's flags for pita (pita.pc) and must print
the same. Usage: check_consumer.py SOURCE_DIR PREFIX WORK_DIR
"""
import math
import os
import re
import shutil
import subprocess
import sys

source, prefix, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(source, "tests", "oracle"))
import pita_oracle  # noqa: E402

TOLERANCE = 1e-12  # relative to the largest value compared: a few ulps of rounding


def run(command, **kwargs):
    result = subprocess.run(command, capture_output=True, text=True, **kwargs)
    if result.returncode != 0:
        sys.exit(f"{' '.join(command)} exited {result.returncode}:\n{result.stdout}\n{result.stderr}")
    return result.stdout


def close(name, got, expected):
    scale = max(1.0, abs(expected))
    if abs(got - expected) > TOLERANCE * scale:
        sys.exit(f"{name}: got {got!r}, expected {expected!r} (difference {got - expected:.3g})")


def check_output(text, where):
    numbers = r"(-?[0-9.e+-]+)"
    frames = {}
    for match in re.finditer(rf"P6 t={numbers} p=\({numbers}, {numbers}\) m={numbers} w={numbers}", text):
        t, x, y, m, w = map(float, match.groups())
        frames[t] = (complex(x, y), m, w)
    if set(frames) != {0.25, 0.5}:
        sys.exit(f"{where}: expected P6 frames at t = 0.25 and 0.5, got:\n{text}")
    keyframes = [(0.0, (0j, 1.0, 0.4)), (0.5, (3 + 1.5j, 0.6, 2.0)), (1.0, (6 + 0j, 1.2, 3.5))]
    expected = {0.5: keyframes[1][1], 0.25: pita_oracle.evaluate("P6", keyframes, 0.25)}
    for t, (p, m, w) in expected.items():
        got = frames[t]
        close(f"{where}: P6({t}).p.x", got[0].real, p.real)
        close(f"{where}: P6({t}).p.y", got[0].imag, p.imag)
        close(f"{where}: P6({t}).m", got[1], m)
        close(f"{where}: P6({t}).w", got[2], w)

    match = re.search(rf"A\^0.5 L=\[\[{numbers}, {numbers}\], \[{numbers}, {numbers}\]\] b=\[{numbers}, {numbers}\]", text)
    if not match:
        sys.exit(f"{where}: no A^0.5 line in:\n{text}")
    l00, l01, l10, l11, b0, b1 = map(float, match.groups())
    r = math.sqrt(2.0)
    L = [[r, -r], [r, r]]
    c = (1.0, 2.0)
    b = (c[0] - (L[0][0] * c[0] + L[0][1] * c[1]), c[1] - (L[1][0] * c[0] + L[1][1] * c[1]))
    for name, got, want in (("L00", l00, L[0][0]), ("L01", l01, L[0][1]), ("L10", l10, L[1][0]),
                            ("L11", l11, L[1][1]), ("b0", b0, b[0]), ("b1", b1, b[1])):
        close(f"{where}: A^0.5 {name}", got, want)


shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
build = os.path.join(work, "build")
generator = ["-G", "Ninja"] if shutil.which("ninja") else []
run(["cmake", "-S", os.path.join(source, "examples", "consumer"), "-B", build, *generator,
     "-DCMAKE_BUILD_TYPE=Release", f"-DCMAKE_PREFIX_PATH={prefix}"])
run(["cmake", "--build", build])
output = run([os.path.join(build, "pita_consumer")])
check_output(output, "examples/consumer (CMake)")

environment = dict(os.environ, PKG_CONFIG_PATH=os.path.join(prefix, "lib", "pkgconfig"))
flags = run(["pkg-config", "--cflags", "--libs", "pita"], env=environment).split()
program = os.path.join(work, "pita_consumer_pkgconfig")
run([os.environ.get("CXX", "c++"), "-std=c++20", "-O0", os.path.join(source, "examples", "consumer", "main.cpp"),
     "-o", program, *flags])
check_output(run([program]), "examples/consumer (pkg-config)")
print(output, end="")
