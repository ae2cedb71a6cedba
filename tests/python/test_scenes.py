"""Every scene of scenes/ through pita.load_scene agrees with the CLI: Scene.eval with
`pita eval` byte for byte (its text) and number for number (its arrays); a few figures
with `pita render`, the measures with `pita measure`."""
import json
import pathlib
import tempfile

import numpy as np
import pytest

import pita
from conftest import SCENES, SOURCE, run_pita


@pytest.mark.parametrize("path", SCENES, ids=[p.stem for p in SCENES])
def test_eval_agrees_with_pita_eval(path):
    relative = path.relative_to(SOURCE)
    scene = pita.load_scene(relative)
    cli = run_pita("eval", relative).stdout
    assert scene.eval(format="json") == cli
    assert scene.eval(format="csv") == run_pita("eval", relative, "--format", "csv").stdout
    frames = json.loads(cli)["frames"]
    arrays = scene.eval()
    if not frames:
        assert not scene.has_motion and arrays.shape[0] == 0
        return
    t = [f["t"] for f in frames]
    kind = scene.kind
    if kind == "arrows":
        p, m, w, q = arrays
        np.testing.assert_array_equal(p, [f["p"] for f in frames])
        np.testing.assert_array_equal(m, [f["m"] for f in frames])
        np.testing.assert_array_equal(w, [f["w"] for f in frames])
        np.testing.assert_array_equal(q, [f["q"] for f in frames])
    elif kind == "points":
        np.testing.assert_array_equal(arrays, [f["p"] for f in frames])
    else:
        np.testing.assert_array_equal(arrays, [f["matrix"] for f in frames])
    # the scene's own motion at the same times gives the same numbers
    again = scene.motion()(np.array(t))
    if kind == "arrows":
        np.testing.assert_array_equal(again.p, arrays.p)
    else:
        np.testing.assert_array_equal(again, arrays)


def test_eval_options_mirror_the_cli():
    scene = pita.load_scene(SOURCE / "scenes" / "fig01-eight-pitas.json")
    cli = run_pita("eval", "scenes/fig01-eight-pitas.json", "--method", "P8", "--samples", "5").stdout
    ours = scene.eval(method="P8", samples=5, format="json").replace(str(SOURCE / "scenes"), "scenes")
    assert ours == cli
    assert scene.eval([0, 0.25], panel=3, format="json") == run_pita(
        "eval", "scenes/fig01-eight-pitas.json", "--t", "0,0.25", "--panel", "3").stdout
    with pytest.raises(ValueError):
        scene.eval(panel=99)
    with pytest.raises(ValueError):
        scene.eval(samples=1)


@pytest.mark.parametrize("name", ["fig01-eight-pitas", "fig03-steady-morph", "sam-fig01-regular-patterns",
                                  "sam-3d-fig01-regular-pattern"])
def test_render_agrees_with_pita_render(name):
    relative = pathlib.Path("scenes") / f"{name}.json"
    scene = pita.load_scene(relative)
    with tempfile.TemporaryDirectory() as out:
        run_pita("render", relative, "-o", out, "--format", "svg,png")
        assert scene.render("svg") == (pathlib.Path(out) / f"{name}.svg").read_bytes()
        assert scene.render("png") == (pathlib.Path(out) / f"{name}.png").read_bytes()
    assert scene.render("pdf").startswith(b"%PDF")
    assert scene._repr_svg_().startswith("<?xml") and scene._repr_png_().startswith(b"\x89PNG")


def test_render_at_a_time_is_render_at():
    relative = pathlib.Path("scenes") / "fig24-animation-frames.json"
    scene = pita.load_scene(relative)
    with tempfile.TemporaryDirectory() as out:
        target = pathlib.Path(out) / "frame.svg"
        run_pita("render", relative, "--at", "0.5", "-o", target)
        assert scene.render("svg", at=0.5) == target.read_bytes()


def test_measure_is_pita_measure():
    relative = pathlib.Path("scenes") / "fig12-pops.json"
    assert pita.load_scene(relative).measure() == json.loads(run_pita("measure", relative, "--format", "json").stdout)


def test_animate_writes_the_animated_svg(tmp_path):
    relative = pathlib.Path("scenes") / "fig24-animation-frames.json"
    scene = pita.load_scene(relative)
    svg = scene.animate(frames=6)
    run_pita("animate", relative, "-o", tmp_path / "cli.svg", "--frames", "6")
    assert svg == (tmp_path / "cli.svg").read_text()
    assert scene.animate(tmp_path / "ours.svg", frames=6) == [str(tmp_path / "ours.svg")]
    assert (tmp_path / "ours.svg").read_text() == svg
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".")] == []   # no temporary left


def test_check_against_the_goldens():
    result = pita.load_scene("scenes/fig03-steady-morph.json").check("golden")
    assert result.passes and result.matches and result.claims_hold
    assert {f.kind for f in result.files} >= {".data.json", ".svg", ".png"}
    assert all(f.verdict == "match" for f in result.files)


def test_check_takes_the_scenes_tolerances_as_pita_check_does(tmp_path):
    source = json.loads((SOURCE / "scenes" / "fig03-steady-morph.json").read_text())
    source["keyframes"][1]["w"] += 1e-6                 # a change below a loose tolerance only
    source["golden"] = {"number_tolerance": 0.01, "svg_tolerance": 5, "pixel_tolerance": 255, "max_differing": 1}
    (tmp_path / "fig03-steady-morph.json").write_text(json.dumps(source))
    scene = pita.load_scene(tmp_path / "fig03-steady-morph.json")
    cli = run_pita("check", tmp_path / "fig03-steady-morph.json", "--golden", SOURCE / "golden", check=False)
    result = scene.check(SOURCE / "golden")
    assert result.matches                              # the figure, within the scene's tolerances
    assert result.passes == (cli.returncode == 0)      # (a claim about the exact winding range fails)
    assert not scene.check(SOURCE / "golden", number_tolerance=0.0).matches
    with pytest.raises(ValueError):
        scene.check(SOURCE / "golden", pixel_tolerance=300)


def test_check_finds_a_changed_figure(tmp_path):
    source = json.loads((SOURCE / "scenes" / "fig03-steady-morph.json").read_text())
    source["keyframes"][1]["w"] += 0.5
    (tmp_path / "fig03-steady-morph.json").write_text(json.dumps(source))
    result = pita.load_scene(tmp_path / "fig03-steady-morph.json").check(SOURCE / "golden")
    assert not result.matches and any(f.verdict == "differs" for f in result.files)


def test_a_dict_is_a_scene():
    scene = pita.load_scene({"method": "SMA", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
                                                             {"t": 1, "p": [2, 0], "m": 2, "w": 1}]})
    assert scene.path == "<dict>" and scene.kind == "arrows" and scene.method == "SMA"
    end = scene.eval(1.0)
    assert end.p == pytest.approx((2, 0), abs=1e-15) and (end.m, end.w) == (2, 1)
    assert scene.render().startswith(b"<?xml")
    with pytest.raises(ValueError):
        scene.check("golden")
