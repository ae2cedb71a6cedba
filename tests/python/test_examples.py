"""The Python examples run and say what the CLI says: examples/python/fig01.py prints
Fig. 1's frames as `pita eval --panel N` does and writes its PNG; the notebook
examples/python/tour.ipynb executes (Debian's jupyter-nbconvert) without an error. Both
run as the guide says, from a folder of the user's own, and write nothing into the clone."""
import json
import os
import shutil
import subprocess
import sys

import pytest

from conftest import SOURCE, run_pita


def files_under(folder):
    """Every file and folder under `folder`, relative to it."""
    return {path.relative_to(folder) for path in folder.rglob("*")}


def test_fig01_script_prints_the_cli_numbers(tmp_path):
    before = files_under(SOURCE / "examples")
    done = subprocess.run([sys.executable, SOURCE / "examples" / "python" / "fig01.py"],
                          capture_output=True, text=True, env=dict(os.environ), cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "fig01.png").read_bytes().startswith(b"\x89PNG")    # the default OUT, in the user's folder
    assert files_under(SOURCE / "examples") == before
    rows = [line.split() for line in done.stdout.splitlines()[1:] if line[:1].isdigit()]
    assert len(rows) == 16
    for row in rows:
        panel, t = int(row[0]), float(row[-5])
        frames = json.loads(run_pita("eval", "scenes/fig01-eight-pitas.json", "--panel", panel, "--t", t).stdout)
        frame = frames["frames"][0]
        expected = [frame["p"][0], frame["p"][1], frame["m"], frame["w"]]
        assert [float(x) for x in row[-4:]] == pytest.approx(expected, abs=5e-7)


def test_the_notebook_runs(tmp_path):
    jupyter = shutil.which("jupyter")
    assert jupyter, "jupyter-nbconvert is one of the test packages (scripts/lib/deps.sh)"
    # the notebook's own command, from a folder of the user's own
    before = files_under(SOURCE / "examples")
    done = subprocess.run([jupyter, "nbconvert", "--to", "notebook", "--execute", "--output-dir", ".",
                           "--ExecutePreprocessor.timeout=120", str(SOURCE / "examples" / "python" / "tour.ipynb")],
                          capture_output=True, text=True, cwd=tmp_path, env=dict(os.environ))
    assert done.returncode == 0, done.stderr[-3000:]
    assert files_under(SOURCE / "examples") == before, "the notebook writes nothing into the clone"
    assert {p.name for p in tmp_path.iterdir()} == {"tour.ipynb"}
    first = "".join(json.loads((SOURCE / "examples" / "python" / "tour.ipynb").read_text())["cells"][0]["source"])
    assert "--output-dir ." in first and "tour.ipynb" in first
    executed = json.loads((tmp_path / "tour.ipynb").read_text())
    outputs = [o for cell in executed["cells"] if cell["cell_type"] == "code" for o in cell["outputs"]]
    assert not [o for o in outputs if o.get("output_type") == "error"]
    # the scene cell shows its figure (Scene._repr_svg_)
    assert any("image/svg+xml" in o.get("data", {}) for o in outputs)
    assert any("/keyframes/1/m" in "".join(o.get("text", "")) for o in outputs)
