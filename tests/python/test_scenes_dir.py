"""pita.scenes_dir() and pita.example(name) reach pita's own scenes from any working
directory: the module of a build folder finds the source folder's scenes/, an installed
module PREFIX/share/pita/scenes (cmake --install; packaging.python_installed checks the real
install). Each test runs from a scratch folder, as a user's own, and writes nothing else."""
import os
import pathlib
import shutil
import subprocess
import sys

import pytest

import pita
from conftest import SOURCE


@pytest.fixture
def elsewhere(tmp_path, monkeypatch):
    """A folder of the user's own, outside the clone, as the working directory."""
    folder = tmp_path / "my-work"
    folder.mkdir()
    monkeypatch.chdir(folder)
    yield folder
    assert not list(folder.iterdir()), "nothing is written into the user's folder"


def test_the_scenes_are_found_from_any_folder(elsewhere):
    assert not pathlib.Path("scenes").exists()
    folder = pita.scenes_dir()
    assert isinstance(folder, pathlib.Path) and folder.is_absolute()
    assert folder.resolve() == (SOURCE / "scenes").resolve()
    path = pita.example("fig01-eight-pitas")
    assert path == folder / "fig01-eight-pitas.json" and path.is_file()
    assert pita.example("fig01-eight-pitas.json") == path
    scene = pita.load_scene(pita.example("fig01-eight-pitas"))
    by_path = pita.load_scene(SOURCE / "scenes" / "fig01-eight-pitas.json")
    assert scene.eval(format="json") == by_path.eval(format="json")
    assert scene.panels == 8


def test_a_scene_with_an_image_draws_from_any_folder(elsewhere):
    scene = pita.load_scene(pita.example("fig23-image-motion"))       # images/picture.png beside it
    assert scene.render("png").startswith(b"\x89PNG")


def test_a_name_it_does_not_have_gets_a_did_you_mean(elsewhere):
    with pytest.raises(ValueError, match='did you mean "fig01-eight-pitas"'):
        pita.example("fig01-eight-pita")
    with pytest.raises(ValueError, match='did you mean "fig01-eight-pitas"'):
        pita.example("fig01")                                           # the scenes it begins
    with pytest.raises(ValueError, match="no scene \"no-such-figure\""):
        pita.example("no-such-figure")
    for bad in ["../README", "scenes/fig01-eight-pitas", "", ".json"]:
        with pytest.raises(ValueError, match="not the name of a scene"):
            pita.example(bad)


PROBE = """
import sys, pita
try:
    print(pita.scenes_dir())
    print(pita.example("fig01-eight-pitas"))
except FileNotFoundError as error:
    print("FileNotFoundError:", error)
"""


def test_an_installed_module_finds_the_installed_scenes(tmp_path):
    """The layout cmake --install makes (default PITA_PYTHON_INSTALL_DIR): the module in
    PREFIX/lib/python3/dist-packages finds PREFIX/share/pita/scenes, and says where it looked
    when they are not there."""
    module = pathlib.Path(pita.__file__)
    prefix = tmp_path / "prefix"
    site = prefix / "lib" / "python3" / "dist-packages"
    site.mkdir(parents=True)
    shutil.copy(module, site / module.name)
    environment = dict(os.environ, PYTHONPATH=str(site), PYTHONDONTWRITEBYTECODE="1")

    def probe():
        done = subprocess.run([sys.executable, "-c", PROBE], cwd=tmp_path, env=environment,
                              capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        return done.stdout.splitlines()

    missing = probe()
    assert missing[0].startswith("FileNotFoundError:") and str(prefix / "share" / "pita" / "scenes") in missing[0]
    scenes = prefix / "share" / "pita" / "scenes"
    scenes.mkdir(parents=True)
    shutil.copy(SOURCE / "scenes" / "fig01-eight-pitas.json", scenes)
    assert probe() == [str(scenes), str(scenes / "fig01-eight-pitas.json")]
