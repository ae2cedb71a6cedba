"""What a careless or hostile caller gets: arrays beyond the work limit refused from their
shapes before anything is copied; objects made by __new__ alone refused by every method;
files that cannot be read as OSError subclasses naming them; scene files read without the
GIL."""
import os
import pickle
import resource
import stat
import sys
import threading
import time

import numpy as np
import pytest

import pita
from conftest import BAD, SOURCE

SCENE = SOURCE / "scenes" / "fig01-eight-pitas.json"
POSES = SOURCE / "scenes" / "sam-fig03-series.json"

# 2e8 times that cost no memory: a broadcast view of one number.
HUGE = np.broadcast_to(np.zeros(1), (200_000_000,))
MATRIX = np.array([[1.0, 0.0, 0.5], [0.0, 1.0, 0.0]])


def peak_mb():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def huge_calls():
    scene = pita.load_scene(SCENE)
    motion = scene.motion()
    a, b = pita.Arrow((0, 0), 1, 0), pita.Arrow((1, 0), 2, 1)
    pose = pita.Pose([[1, 0], [0, 1]], [0, 0])
    return {
        "Motion(t)": lambda: motion(HUGE),
        "Scene.eval(t)": lambda: scene.eval(HUGE),
        "Scene.eval(t, format)": lambda: scene.eval(HUGE, format="csv"),
        "Scene.motion(panel)(t)": lambda: scene.motion(panel=0)(HUGE.reshape(20_000, 10_000)),
        "sma": lambda: pita.sma(a, b, HUGE),
        "sam": lambda: pita.sam(pose, pose, HUGE),
        "ear_power(t)": lambda: pita.ear_power(MATRIX, HUGE),
        "ear_power(M)": lambda: pita.ear_power(np.broadcast_to(MATRIX, (200_000_000, 2, 3)), 0.5),
        "ear_power(M, t) broadcast": lambda: pita.ear_power(np.broadcast_to(MATRIX, (20_000, 2, 3)),
                                                            np.broadcast_to(0.5, (20_000, 1))),
        "Pose(L)": lambda: pita.Pose(np.broadcast_to(0.0, (100_000, 100_000))),
        "Pose.from_matrix": lambda: pita.Pose.from_matrix(np.broadcast_to(0.0, (100_000, 100_000))),
        "has_sam": lambda: pita.has_sam(np.broadcast_to(0.0, (100_000, 100_000))),
    }


@pytest.mark.parametrize("name", list(huge_calls()))
def test_huge_arrays_are_refused_before_any_copy(name):
    call = huge_calls()[name]
    before, start = peak_mb(), time.monotonic()
    with pytest.raises(ValueError) as error:
        call()
    assert time.monotonic() - start < 2.0
    assert peak_mb() - before < 200, f"{name}: the peak memory grew by {peak_mb() - before:.0f} MB"
    message = str(error.value)
    assert message.split(":")[0] in ("t", "M and t", "L", "M"), message
    if "elements" in message:
        assert "limit of 1e+08" in message


def test_too_many_keyframes_are_refused_before_any_is_read():
    arrows = [pita.Arrow((0, 0), 1, 0)] * 1_000_000
    start = time.monotonic()
    with pytest.raises(pita.SceneError, match="at most 1000 keyframes") as error:
        pita.motion("P6", arrows, np.arange(len(arrows), dtype=float))
    assert error.value.pointer == "/keyframes"
    poses = [np.eye(2, 3)] * 1_000_000
    with pytest.raises(pita.SceneError, match="at most 1000 poses") as error:
        pita.motion("SAM", poses)
    assert error.value.pointer == "/poses"
    assert time.monotonic() - start < 2.0


def test_the_limit_itself_is_allowed():
    # 1e8 elements are within the limit: a small broadcast is evaluated as before.
    motion = pita.load_scene(SCENE).motion()
    t = np.broadcast_to(np.linspace(0, 1, 5), (3, 5))
    assert motion(t).p.shape == (3, 5, 2)
    assert pita.ear_power(np.broadcast_to(MATRIX, (4, 2, 3)), np.linspace(0, 1, 4)).shape == (4, 2, 3)


# ------------------------------------------------------------- objects made by __new__ alone

def real_objects():
    arrow = pita.Arrow((0, 0), 1, 0.4)
    pose = pita.Pose([[0, -1], [1, 0]], [2, 0])
    scene = pita.load_scene(SCENE)
    return {pita.Arrow: arrow, pita.Pose: pose, pita.Motion: scene.motion(), pita.Scene: scene,
            pita.SamExistence: pita.has_sam(pose)}


# Arguments a method of a real object accepts (the others take none).
ARGUMENTS = {"__eq__": "self", "__matmul__": "self", "__call__": (0.5,), "check": ("golden",),
             "__setstate__": None}


def test_every_type_made_by_new_alone_refuses_every_use():
    for kind, real in real_objects().items():
        bare = kind.__new__(kind)
        for name, member in vars(kind).items():
            if name in ("__init__", "__new__", "__doc__", "__module__", "__dict__", "__weakref__", "__setstate__"):
                continue
            if isinstance(member, staticmethod) or name == "from_matrix" or name == "from_points":
                continue
            if isinstance(member, property):
                with pytest.raises(TypeError, match="holds no value"):
                    getattr(bare, name)
                getattr(real, name)  # and a real object has it
            elif callable(member):
                given = ARGUMENTS.get(name, ())
                args = (real,) if given == "self" else given
                with pytest.raises(TypeError, match="holds no value"):
                    getattr(bare, name)(*args)
        with pytest.raises(TypeError, match="holds no value"):
            repr(bare)
        if "__eq__" in vars(kind):
            with pytest.raises(TypeError, match="holds no value"):
                bool(bare == bare)
        with pytest.raises(TypeError):
            pickle.dumps(bare)


def test_a_value_set_by_setstate_is_whole():
    arrow = pita.Arrow.__new__(pita.Arrow)
    arrow.__setstate__((1.0, 2.0, 3.0, 0.5))
    assert arrow == pita.Arrow((1, 2), 3, 0.5)
    with pytest.raises(ValueError, match="^m: "):
        pita.Arrow.__new__(pita.Arrow).__setstate__((0.0, 0.0, -1.0, 0.0))
    pose = pita.Pose.__new__(pita.Pose)
    pose.__setstate__(([[1.0, 0.0, 2.0], [0.0, 1.0, 0.0]],))
    assert pose == pita.Pose([[1, 0], [0, 1]], [2, 0])
    with pytest.raises(ValueError):
        pita.Pose.__new__(pita.Pose).__setstate__(([[1.0, 0.0], [0.0, 1.0]], 1))


# ------------------------------------------------------------- files

def test_a_missing_file_is_file_not_found(tmp_path):
    with pytest.raises(FileNotFoundError) as error:
        pita.load_scene(tmp_path / "missing.json")
    assert error.value.filename == str(tmp_path / "missing.json")
    assert "scene file" in str(error.value)


def test_a_directory_is_is_a_directory_error(tmp_path):
    with pytest.raises(IsADirectoryError) as error:
        pita.load_scene(tmp_path)
    assert error.value.filename == str(tmp_path)


@pytest.mark.skipif(os.geteuid() == 0, reason="root reads any file")
def test_an_unreadable_file_is_permission_error(tmp_path):
    path = tmp_path / "secret.json"
    path.write_text("{}")
    path.chmod(0)
    with pytest.raises(PermissionError) as error:
        pita.load_scene(path)
    assert error.value.filename == str(path)


def test_a_file_in_an_unreadable_folder_is_permission_error(tmp_path):
    if os.geteuid() == 0:
        pytest.skip("root reads any folder")
    folder = tmp_path / "closed"
    folder.mkdir()
    (folder / "scene.json").write_text("{}")
    folder.chmod(0)
    try:
        with pytest.raises(PermissionError):
            pita.load_scene(folder / "scene.json")
    finally:
        folder.chmod(0o755)


def test_other_errors_of_open_keep_their_errno(tmp_path):
    # (Run as root, the permission tests above are skipped; these errnos hold for any user.)
    (tmp_path / "file").write_text("{}")
    with pytest.raises(NotADirectoryError) as error:
        pita.load_scene(tmp_path / "file" / "scene.json")
    assert error.value.filename == str(tmp_path / "file" / "scene.json")
    os.symlink("loop", tmp_path / "loop")
    with pytest.raises(OSError) as error:
        pita.load_scene(tmp_path / "loop")
    assert error.value.errno == 40 and error.value.filename == str(tmp_path / "loop")  # ELOOP


def test_a_fifo_is_refused_at_once_saying_what_it_is(tmp_path):
    fifo = tmp_path / "scene.json"
    os.mkfifo(fifo)
    start = time.monotonic()
    with pytest.raises(OSError, match="named pipe") as error:
        pita.load_scene(fifo)  # never blocks in open(): no writer is needed
    assert time.monotonic() - start < 1.0
    assert str(fifo) in str(error.value)
    assert not isinstance(error.value, ValueError)


@pytest.mark.parametrize("device", ["/dev/null", "/dev/zero"])
def test_a_device_is_refused_saying_what_it_is(device):
    if not os.path.exists(device):
        pytest.skip(f"no {device}")
    with pytest.raises(OSError, match="device") as error:
        pita.load_scene(device)
    assert device in str(error.value)


def test_a_nul_in_the_name_is_a_value_error_that_shows_it(tmp_path):
    (tmp_path / "secret.txt").write_text('{"password": 1}')
    with pytest.raises(ValueError, match=r"NUL byte") as error:
        pita.load_scene(str(tmp_path / "secret.txt") + "\0.json")
    assert "password" not in str(error.value)
    assert "secret.txt\\0.json" in str(error.value)


def test_a_bad_scene_is_a_value_error_with_the_pointer(tmp_path):
    path = tmp_path / "bad.json"
    scene = {"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
                                           {"t": 1, "p": [1, 0], "m": -1, "w": 0},
                                           {"t": 2, "p": [2, 0], "m": 1, "w": 0}]}
    import json
    path.write_text(json.dumps(scene))
    with pytest.raises(pita.SceneError) as error:
        pita.load_scene(path)
    assert isinstance(error.value, ValueError)
    assert error.value.pointer == "/keyframes/1/m" and error.value.file == str(path)
    assert str(path) in str(error.value) and "/keyframes/1/m" in str(error.value)


def test_malformed_json_is_a_value_error_with_line_and_column(tmp_path):
    path = tmp_path / "broken.json"
    path.write_text('{\n  "method": "P6",\n  "keyframes": ]\n}\n')
    with pytest.raises(pita.SceneError) as error:
        pita.load_scene(path)
    assert isinstance(error.value, ValueError) and error.value.line == 3


def test_a_file_beyond_the_size_limit_is_a_value_error(tmp_path):
    path = tmp_path / "big.json"
    with open(path, "wb") as out:
        out.truncate(33 << 20)  # sparse: 33 MiB of zero bytes
    with pytest.raises(pita.SceneError, match="32 MiB"):
        pita.load_scene(path)


# ------------------------------------------------------------- the GIL

def test_load_scene_lets_other_threads_run(tmp_path):
    # About 30 MB of JSON: parsing it takes a good part of a second, without the GIL.
    path = tmp_path / "large.json"
    with open(path, "w") as out:
        out.write('{"method": "P6", "unknown": [')
        out.write(",".join(["0.125"] * 5_000_000))
        out.write("]}")
    outcome = {}
    counter = [0]

    def load():
        before, start = counter[0], time.monotonic()
        try:
            pita.load_scene(path)
        except pita.SceneError as error:
            outcome["error"] = error
        outcome["took"] = time.monotonic() - start
        outcome["counted"] = counter[0] - before  # by the main thread while this one loaded

    thread = threading.Thread(target=load)
    thread.start()
    while thread.is_alive():
        counter[0] += 1
    thread.join()
    assert "error" in outcome  # the unknown field
    assert outcome["took"] > 0.05
    assert outcome["counted"] > 10_000, f"the counter advanced {outcome['counted']} times in {outcome['took']:.2f} s"
