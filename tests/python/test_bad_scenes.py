"""Every bad scene of tests/data/bad/ (README.md there) raises a pita.SceneError (or
NoMotionError) with exactly the pointer and reason of its .expect file, as the CLI
and test_motion give them; none crashes the interpreter."""
import pytest

import pita
from conftest import BAD

CASES = sorted(BAD.glob("*.json"))


def test_the_cases_are_there():
    assert len(CASES) >= 50, f"{BAD} holds {len(CASES)} cases"


def expectation(case):
    lines = case.with_suffix(".expect").read_text().splitlines()
    where, reason = lines[0], lines[1].removeprefix("reason: ")
    return where, reason


@pytest.mark.parametrize("case", CASES, ids=[c.stem for c in CASES])
def test_bad_scene_is_refused_with_its_pointer(case):
    where, reason = expectation(case)
    with pytest.raises(pita.SceneError) as caught:
        scene = pita.load_scene(case)
        scene.eval()
    error = caught.value
    assert error.file == str(case)
    assert error.reason == reason
    if where.startswith("position: "):
        line, column = where.removeprefix("position: ").split(":")
        assert (error.line, error.column) == (int(line), int(column))
    else:
        assert error.pointer == where.removeprefix("pointer:").strip()
