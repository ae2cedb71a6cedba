#!/usr/bin/env python3
"""Writes the seed corpus of every fuzz target into OUT_DIR/<target>/ (scripts/fuzz.sh;
nothing of it is kept in git): the scenes of scenes/ and tests/data/bad/ for the scene
targets, trimmed copies of the golden data files golden/*/*.data.json (a few panels,
items and points each: the structure without the bulk), affinities of every EAR case, and
--vary arguments with manifest parts for fuzz_sweep, and requests to pita serve.
--vary arguments with manifest parts for fuzz_sweep, edit bodies of `pita serve --edit` for
fuzz_edit_body, and `eval --batch` files for fuzz_batch_line.
The regression inputs of tests/data/fuzz/<target>/ are a corpus of their own.

    fuzz/make_seeds.py OUT_DIR
"""
import json
import shutil
import struct
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SCENE_TARGETS = ["fuzz_scene_reader", "fuzz_eval", "fuzz_render"]


def scene_seeds(out):
    files = sorted(ROOT.glob("scenes/*.json")) + sorted(ROOT.glob("tests/data/bad/*.json"))
    for target in SCENE_TARGETS:
        folder = out / target
        folder.mkdir(parents=True, exist_ok=True)
        for f in files:
            prefix = "scene-" if f.parent.name == "scenes" else "bad-"
            shutil.copyfile(f, folder / (prefix + f.name))


def trimmed(value, depth=0):
    """The first few elements of every array: a panel or two, a few items, a few points."""
    keep = 2 if depth < 2 else 4
    if isinstance(value, list):
        return [trimmed(v, depth + 1) for v in value[:keep]]
    if isinstance(value, dict):
        return {k: trimmed(v, depth + 1) for k, v in value.items()}
    return value


def golden_seeds(out):
    folder = out / "fuzz_golden_data"
    folder.mkdir(parents=True, exist_ok=True)
    for f in sorted(ROOT.glob("golden/*/*.data.json")):
        data = json.loads(f.read_text())
        (folder / f.name).write_text(json.dumps(trimmed(data)) + "\n")


def affine_seeds(out):
    """mode 1 (a grid of multiples of 1/64, fuzz_affine_power.cpp): L, b, t."""
    folder = out / "fuzz_affine_power"
    folder.mkdir(parents=True, exist_ok=True)
    cases = {
        "identity": [1, 0, 0, 1], "g1-rotation": [0, -1, 1, 0], "g1-near-half-turn": [-1, -0.015625, 0.015625, -1],
        "g2-stretch": [4, 0, 0, 0.25], "g2-jordan": [2, 1, 0, 2], "s1-shear": [1, 3, 0, 1],
        "s1-one-direction": [1, 0, 0, 3], "s2-half-turn": [-0.5, 0, 0, -0.5], "g3-negative": [-1, 0, 0, -3],
        "g3-jordan": [-2, 1, 0, -2], "mirror": [1, 0, 0, -1], "singular": [1, 2, 2, 4],
    }
    for name, L in cases.items():
        for t in (0.5, -2.0, 3.25):
            values = L + [1.5, -2.0, t]
            data = bytes([1, 100]) + b"".join(struct.pack(">h", round(v * 64)) for v in values)
            (folder / f"{name}-t{t}.bin").write_bytes(data)
    # mode 2 at 10^+-200 and mode 0 (raw doubles), a NaN among them.
    for exponent in (0, 200):
        values = [0.5, -1.25, 1.25, 0.5, 1, 2, 0.5]
        data = bytes([2, exponent]) + b"".join(struct.pack(">h", round(v * 64)) for v in values)
        (folder / f"scaled-{exponent}.bin").write_bytes(data)
    raw = [1e200, -3e199, 2e199, 1e200, 1.0, float("nan"), 0.5]
    (folder / "raw.bin").write_bytes(bytes([0, 0]) + b"".join(struct.pack("<d", v) for v in raw))


def animate_seeds(out):
    """fuzz_animate: the options as JSON on the first line, then a scene (or a frames.json)."""
    folder = out / "fuzz_animate"
    folder.mkdir(parents=True, exist_ok=True)
    options = ['{}', '{"frames": 9, "out": "a.svg"}', '{"fps": 24, "duration": 2, "out": "v.mp4", "scale": 0.5}',
               '{"frames": 100000, "out": "frames/", "format": "svg"}', '{"budget": 3, "frames": 2}']
    files = sorted(ROOT.glob("scenes/*.json"))
    for i, f in enumerate(files):
        (folder / f.name).write_text(options[i % len(options)] + "\n" + f.read_text())
    (folder / "frames-json.txt").write_text('{}\n{"frames": 2, "frame_list": [{"frame": 1, "file": "frame-0001.png"}]}\n')


def sweep_seeds(out):
    """fuzz_sweep: a --vary argument on the first line, then a manifest part (fuzz_sweep.cpp)."""
    folder = out / "fuzz_sweep"
    folder.mkdir(parents=True, exist_ok=True)
    metrics = ("path_length_p,path_length_q,turning_p,turning_q,winding_min,winding_max,discrepancy_max,"
               "discrepancy_max_previous,discrepancy_max_average,discrepancy_t_of_max,most_sensitive,gain,"
               "pop_jump,pops,ara,area_monotone")
    header = "index,/keyframes/1/t,status,outputs,hash," + metrics
    blank = "," * metrics.count(",")
    axes = ["/keyframes/1/t=0.1:0.9:5", "/keyframes/1/t=log:1e-3:1e3:7", "/method=[\"ribbon\",\"neville\"]",
            "/keyframes/0/w=0,1,2", "/title=\"a,b\"", "/keyframes/1/t=0:1:0", "bad"]
    rows = {
        "sorted": ["0,0.1,ok,a.svg,h0", "1,0.3,ok,b.svg,h1", "2,0.5,failed,,"],
        "reordered": ["2,0.5,ok,,h2", "0,0.1,ok,,h0", "1,0.3,ok,,h1"],
        "duplicate": ["1,0.3,ok,,h1", "1,0.3,ok,,h1"],
        "conflict": ["1,0.3,ok,,h1", "1,0.4,ok,,h9"],
        "quoted": ['0,0.1,ok,"x,y.svg",h0', '1,0.3,"o""k",,h1'],
        "no-header": ["0,0.1,ok,,h0"],
    }
    for i, (name, lines) in enumerate(rows.items()):
        lines = [line + "," + blank for line in lines]
        body = lines if name == "no-header" else [header] + lines
        text = axes[i % len(axes)] + "\n" + "\n".join(body) + "\n"
        (folder / f"{name}.txt").write_text(text)
    (folder / "axis-only.txt").write_text(axes[-2])


def http_seeds(out):
    """Requests to pita serve as a client sends them (fuzz_http_request.cpp's token)."""
    folder = out / "fuzz_http_request"
    folder.mkdir(parents=True, exist_ok=True)
    token = "0123456789abcdef0123456789abcdef"
    host = "Host: 127.0.0.1:8765\r\n"

    def get(target):
        return f"GET {target} HTTP/1.1\r\n{host}\r\n"

    def post(target, body):
        return f"POST {target} HTTP/1.1\r\n{host}Content-Length: {len(body.encode())}\r\n\r\n{body}"

    edit = json.dumps({"changes": [{"pointer": "/keyframes/1/m", "value": "2"}]})
    drag = json.dumps({"drag": {"panel": 0, "pointer": "/keyframes/0", "part": "tip", "to": [1, 2]}})
    requests = {
        "page": get(f"/?token={token}"), "scenes": get(f"/api/scenes?token={token}"),
        "figure": get(f"/api/figure/0?token={token}"), "figure-at": get(f"/api/figure/0?at=0.5&token={token}"),
        "measures": get(f"/api/measures/0?token={token}"), "events": get(f"/api/events?token={token}"),
        "edit": post(f"/api/edit/0?token={token}", edit), "drag": post(f"/api/edit/0?token={token}", drag),
        "no-token": get("/api/scenes"), "foreign-host": "GET / HTTP/1.1\r\nHost: evil.example\r\n\r\n",
        "chunked": f"POST /api/edit/0 HTTP/1.1\r\n{host}Transfer-Encoding: chunked\r\n\r\n5\r\nhello\r\n0\r\n\r\n",
        "header-token": f"GET /api/scenes HTTP/1.1\r\n{host}X-Pita-Token: {token}\r\n\r\n",
    }
    for name, text in requests.items():
        (folder / f"{name}.http").write_bytes(text.encode())


def python_entry_seeds(out):
    """fuzz_python_entry: a byte of the check, then its numbers (fuzz_python_entry.cpp)."""
    folder = out / "fuzz_python_entry"
    folder.mkdir(parents=True, exist_ok=True)

    def shape(*extents):
        return bytes([len(extents)]) + b"".join(struct.pack("<q", e) for e in extents)

    seeds = {
        "shapes-broadcast": bytes([0]) + shape(20000, 1) + shape(20000),
        "shapes-huge": bytes([0]) + shape(200_000_000) + shape(),
        "shapes-mismatch": bytes([0]) + shape(3) + shape(4),
        "shapes-negative": bytes([0]) + shape(-1, 2) + shape(2),
        "arrow": bytes([1]) + struct.pack("<4d", 0.0, 0.0, 1.0, 0.4),
        "arrow-winding": bytes([1]) + struct.pack("<4d", 0.0, 0.0, 1.0, 1e300),
        "arrow-nan": bytes([1]) + struct.pack("<4d", 0.0, 0.0, float("nan"), 0.0),
        "pose-2x3": bytes([2, 0]) + struct.pack("<2q", 2, 3),
        "pose-l-huge": bytes([2, 1]) + struct.pack("<2q", 100000, 100000),
        "repr": bytes([3]) + struct.pack("<d", -1.0),
    }
    for name, data in seeds.items():
        (folder / f"{name}.bin").write_bytes(data)


def edit_seeds(out):
    """fuzz_edit_body: a byte choosing the scene (0 arrows, 1 panels, 2 poses, 3 poses of space), then the body."""
    folder = out / "fuzz_edit_body"
    folder.mkdir(parents=True, exist_ok=True)
    bodies = [
        (0, {"drag": {"panel": 0, "pointer": "/keyframes/0", "part": "tail", "to": [120, 200]}}),
        (0, {"drag": {"panel": 0, "pointer": "/keyframes/1", "part": "tip", "to": [300, 100], "version": 1}}),
        (0, {"drag": {"panel": 0, "pointer": "/keyframes/2", "part": "tip", "to": [500, 50]}}),
        (0, {"changes": [{"pointer": "/keyframes/0/p", "value": "[1, 2]"},
                         {"pointer": "/keyframes/1/w", "value": "1.5"}]}),
        (0, {"changes": [{"pointer": "/keyframes/2/q", "value": "[9.5, 1e3]"}]}),
        (1, {"drag": {"panel": 0, "pointer": "/panels/0/keyframes/1", "part": "tip", "to": [200, 200]}}),
        (1, {"drag": {"panel": 1, "pointer": "/keyframes/0", "part": "tail", "to": [10, 10]}}),
        (1, {"changes": [{"pointer": "/panels/0/keyframes/2/turns", "value": "2"}]}),
        (2, {"drag": {"panel": 0, "pointer": "/poses/1", "part": "corner2", "to": [400, 300]}}),
        (2, {"drag": {"panel": 0, "pointer": "/poses/0", "part": "corner0", "to": [100, 300]}}),
        (2, {"changes": [{"pointer": "/poses/0/matrix", "value": "[[1, 0, 1], [0, 1, 0]]"}]}),
        (0, {"drag": {"panel": 1e20, "pointer": "/keyframes/0", "part": "tail", "to": [0, 0]}}),
        # "Save view" of a 3D camera, and its undo: members added, then removed.
        (3, {"changes": [{"pointer": "/camera/azimuth", "value": "30"},
                         {"pointer": "/camera/elevation", "value": "-20.5"}, {"pointer": "/camera/auto", "value": "false"}]}),
        (0, {"changes": [{"pointer": "/camera", "remove": True}, {"pointer": "/camera", "value": "{\"azimuth\": 10}"}]}),
        # A time moved on the timeline, one past its neighbour, and a drag in views the page holds.
        (0, {"time": {"pointer": "/keyframes/1", "t": 1.25, "step": 0.01}}),
        (2, {"time": {"pointer": "/poses/0", "t": 2, "step": 0.5}}),
        (0, {"drag": {"panel": 0, "pointer": "/keyframes/1", "part": "tail", "to": [200, 150]},
             "views": [[-1, -1, 10, 4]]}),
    ]
    for i, (scene, body) in enumerate(bodies):
        (folder / f"edit-{i:02d}.bin").write_bytes(bytes([scene]) + json.dumps(body).encode())
    (folder / "bom.bin").write_bytes(b"\x00\xef\xbb\xbf" + json.dumps(bodies[0][1]).encode())


def batch_seeds(out):
    """fuzz_batch_line: `eval --batch` files (tests/data/bad-batch/ and made-up lines)."""
    folder = out / "fuzz_batch_line"
    folder.mkdir(parents=True, exist_ok=True)
    for f in sorted(ROOT.glob("tests/data/bad-batch/*.jsonl")):
        shutil.copy(f, folder / f.name)
    lines = ['["scenes/fig01-eight-pitas.json", "--t=0,0.5"]', '["s.json", "--method", "P8", "--samples", "5"]',
             '[]', '{"not": "an array"}', '["a", 1]', '["caf\u00e9.json"]', '[', '"x"']
    (folder / "lines.jsonl").write_text("\n".join(lines) + "\n")
    (folder / "no-final-newline.jsonl").write_text("\n".join(lines))
    (folder / "nul.jsonl").write_bytes(b'["a\x00b"]\n["c"]\n')
    (folder / "crlf.jsonl").write_bytes(b'["a"]\r\n["b"]\r\n\n\n')


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = Path(sys.argv[1])
    if out.exists():
        shutil.rmtree(out)
    scene_seeds(out)
    golden_seeds(out)
    affine_seeds(out)
    sweep_seeds(out)
    animate_seeds(out)
    http_seeds(out)
    python_entry_seeds(out)
    edit_seeds(out)
    batch_seeds(out)


if __name__ == "__main__":
    main()
