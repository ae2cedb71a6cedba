"""Shared fixtures of the Python module's tests (ctest python.*: tests/python/CMakeLists.txt).

ctest runs pytest with PYTHONPATH=build/python (the module), PITA_BINARY (the CLI the
results are compared with) and PITA_SOURCE_DIR (scenes/, tests/data/bad/).
"""
import json
import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("PITA_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BINARY = os.environ.get("PITA_BINARY", str(SOURCE / "build" / "pita"))
SCENES = sorted((SOURCE / "scenes").glob("*.json"))
BAD = SOURCE / "tests" / "data" / "bad"


def run_pita(*args, check=True):
    """`pita ARGS...` from the source folder; its CompletedProcess (text)."""
    done = subprocess.run([BINARY, *map(str, args)], cwd=SOURCE, capture_output=True, text=True)
    if check and done.returncode != 0:
        raise AssertionError(f"pita {' '.join(map(str, args))} exited {done.returncode}: {done.stderr}")
    return done


def pita_eval_json(*args):
    """The document `pita eval ARGS... --format json` prints, parsed."""
    return json.loads(run_pita("eval", *args).stdout)


@pytest.fixture(scope="session")
def figure_one():
    """Fig. 1's keyframes (scenes/fig01-eight-pitas.json), as pita.Arrow and knots."""
    import pita
    scene = json.loads((SOURCE / "scenes" / "fig01-eight-pitas.json").read_text())
    arrows = [pita.Arrow(k["p"], k["m"], k["w"]) for k in scene["keyframes"]]
    return arrows, [k["t"] for k in scene["keyframes"]]
