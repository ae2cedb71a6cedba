"""The Python examples run and say what the CLI says: examples/python/fig01.py prints
Fig. 1's frames as `pita eval --panel N` does and writes its PNG; the notebook
examples/python/tour.ipynb executes (Debian's jupyter-nbconvert) without an error."""
import json
import os
import shutil
import subprocess
import sys

import pytest

from conftest import SOURCE, run_pita


def test_fig01_script_prints_the_cli_numbers(tmp_path):
    out = tmp_path / "fig01.png"
    done = subprocess.run([sys.executable, SOURCE / "examples" / "python" / "fig01.py", out],
                          capture_output=True, text=True, env=dict(os.environ))
    assert done.returncode == 0, done.stderr
    assert out.read_bytes().startswith(b"\x89PNG")
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
    done = subprocess.run([jupyter, "nbconvert", "--to", "notebook", "--execute", "--output-dir", str(tmp_path),
                           "--ExecutePreprocessor.timeout=120", str(SOURCE / "examples" / "python" / "tour.ipynb")],
                          capture_output=True, text=True, cwd=SOURCE, env=dict(os.environ))
    assert done.returncode == 0, done.stderr[-3000:]
    executed = json.loads((tmp_path / "tour.ipynb").read_text())
    outputs = [o for cell in executed["cells"] if cell["cell_type"] == "code" for o in cell["outputs"]]
    assert not [o for o in outputs if o.get("output_type") == "error"]
    # the scene cell shows its figure (Scene._repr_svg_)
    assert any("image/svg+xml" in o.get("data", {}) for o in outputs)
    assert any("/keyframes/1/m" in "".join(o.get("text", "")) for o in outputs)
