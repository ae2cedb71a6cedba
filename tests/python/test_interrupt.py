"""Ctrl-C in the long calls of the module: Scene.animate (into a folder of frames, a video,
an animated SVG file or in memory), Scene.render and Scene.eval(format=) raise
KeyboardInterrupt within a second or two, and an animation leaves neither its output nor a temporary beside it."""
import os
import shutil
import signal
import subprocess
import sys
import time

import pytest

from conftest import SOURCE

# The child: loads the scene, says "ready", repeats the call (removing a finished output, so
# that what is left after Ctrl-C is the interrupted call's), and reports how it ended.
CHILD = r"""
import os, shutil, sys, time
import pita
scene = pita.load_scene(sys.argv[1])
call = sys.argv[2]
out = sys.argv[3]
print("ready", flush=True)
start = time.monotonic()
try:
    if call == "render":
        for _ in range(1000):  # each drawing takes about 2.5 s: Ctrl-C comes during one
            scene.render("png", scale=12.0, budget=40.0)
    elif call == "eval-text":
        for _ in range(1000):  # a million frames as JSON: about a second each
            scene.eval(samples=1_000_000, format="json")
    elif call == "svg-memory":
        for _ in range(1000):
            scene.animate(frames=4000)
    else:
        for _ in range(1000):  # a whole animation is removed before the next one starts
            scene.animate(out, frames=4000, threads=2)
            shutil.rmtree(out) if os.path.isdir(out) else os.remove(out)
except KeyboardInterrupt:
    print("interrupted", flush=True)
    sys.exit(0)
print(f"finished after {time.monotonic() - start:.1f} s", flush=True)
sys.exit(1)
"""

SCENE = SOURCE / "scenes" / "fig01-eight-pitas.json"

CASES = ["frames", "out.svg", "svg-memory", "render", "eval-text"]
if shutil.which("ffmpeg"):
    CASES.append("out.mp4")


@pytest.mark.parametrize("case", CASES)
def test_ctrl_c_stops_within_seconds(tmp_path, case):
    folder = tmp_path / "out"
    folder.mkdir()
    scene = tmp_path / SCENE.name
    scene.write_bytes(SCENE.read_bytes())
    call = case if case in ("render", "svg-memory", "eval-text") else "animate"
    out = folder / case
    env = dict(os.environ)
    env.setdefault("PYTHONPATH", "")
    child = subprocess.Popen([sys.executable, "-c", CHILD, str(scene), call, str(out)], stdout=subprocess.PIPE,
                             text=True, env=env)
    try:
        assert child.stdout.readline().strip() == "ready"
        time.sleep(1.0)
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        said = child.stdout.readline().strip()
        took = time.monotonic() - sent  # until KeyboardInterrupt was caught
        child.wait(timeout=30)  # (a dropped drawing ends before the process exits)
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()
    assert said == "interrupted" and child.returncode == 0, said
    assert took < 3.0, f"KeyboardInterrupt {took:.1f} s after SIGINT"
    # Nothing half-written: no output, no temporary (".NAME.XXXXXX") beside it.
    assert sorted(os.listdir(folder)) == []
