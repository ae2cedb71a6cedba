"""ctest packaging.python_installed: `cmake --install` put the Python module and its
type stubs in PREFIX/lib/python3/dist-packages (PITA_PYTHON_INSTALL_DIR), and from
there the module imports, is the version built, evaluates a scene, and finds pita's own
scenes in PREFIX/share/pita/scenes (pita.example) from a folder outside the clone.

Usage: check_python_installed.py PREFIX SOURCE_DIR VERSION   (run by the python3 it is for)
"""
import os
import pathlib
import subprocess
import sys
import tempfile

prefix, source, version = pathlib.Path(sys.argv[1]), sys.argv[2], sys.argv[3]
site = prefix / "lib" / "python3" / "dist-packages"
modules = sorted(site.glob("pita.cpython-*.so"))
problems = []
if len(modules) != 1:
    problems.append(f"expected one pita.cpython-*.so in {site}, found {[m.name for m in modules]}")
if not (site / "pita.pyi").is_file():
    problems.append(f"no pita.pyi in {site}")
probe = """
import pathlib, sys
import numpy as np
import pita
assert pathlib.Path(pita.__file__).parent == pathlib.Path(sys.argv[1]), pita.__file__
assert pita.__version__ == sys.argv[2], pita.__version__
scene = pita.load_scene(sys.argv[3] + "/scenes/fig01-eight-pitas.json")
p, m, w, q = scene.eval(np.linspace(0, 1, 5))
assert p.shape == (5, 2)
assert pita.has_sam([[0, -1, 0], [1, 0, 0]])
installed = pathlib.Path(sys.argv[1]).parents[2] / "share" / "pita" / "scenes"
assert pita.scenes_dir() == installed.resolve(), (pita.scenes_dir(), installed)
assert pita.load_scene(pita.example("fig23-image-motion")).render("png").startswith(b"\\x89PNG")
"""
environment = dict(os.environ, PYTHONPATH=str(site), PYTHONDONTWRITEBYTECODE="1")
with tempfile.TemporaryDirectory() as elsewhere:  # a user's own folder
    done = subprocess.run([sys.executable, "-c", probe, str(site), version, source], env=environment,
                          capture_output=True, text=True, cwd=elsewhere)
if done.returncode != 0:
    problems.append(f"the installed module does not import and evaluate:\n{done.stderr}")
for problem in problems:
    print(problem, file=sys.stderr)
sys.exit(1 if problems else 0)
