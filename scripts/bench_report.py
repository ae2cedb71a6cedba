#!/usr/bin/env python3
"""Measures pita and rewrites the performance tables of the docs with the results.

Each report below measures one thing side by side (pita against its floor, or
one setting against another, in interleaved runs) and renders a Markdown block:
the machine and date, the commands it ran, and a table. In the docs the block
sits between

    <!-- bench-report:begin NAME -->
    <!-- bench-report:end NAME -->

and this script replaces what is between them. scripts/bench-report.sh builds
what is needed and calls it.

    bench_report.py --build BUILD [NAME...]   measure (every report, or those named)
                                              and rewrite the docs' blocks
    bench_report.py --build BUILD --check     run every report's commands once at a
                                              tiny size (the ctest docs.bench_report):
                                              fails when a documented command no longer
                                              runs, or a block has no report or a report
                                              no block

Run it on an idle machine: the numbers are CPU and wall times.
"""
import argparse
import datetime
import json
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DOCS = [ROOT / "docs" / "explanation" / "performance.md", ROOT / "docs" / "guide" / "python.md", ROOT / "README.md"]
FIG01 = "scenes/fig01-eight-pitas.json"
BLOCK = re.compile(r"(<!-- bench-report:begin (?P<name>[\w-]+) -->\n)(?P<body>.*?)(<!-- bench-report:end (?P=name) -->)",
                   re.S)


class Context:
    """Where the binaries are, a scratch folder, and how hard to measure."""

    def __init__(self, build, check):
        self.build = Path(build).resolve()
        self.check = check  # smoke mode: every command once, tiny sizes
        self.scratch = Path(tempfile.mkdtemp(prefix="pita-bench-report-"))
        self.facts = {}  # report name -> its headline numbers, for the README's summary

    def tool(self, name):
        return str(self.build / name)

    def rounds(self, full):
        return 1 if self.check else full


def run(command, stdout=None, rss=False):
    """Runs `command` (a list) from the repository's root, its standard output
    into the file `stdout` (default: discarded); returns (wall s, CPU s, peak
    RSS kB or 0). The process is started with posix_spawn, so that its CPU time
    is its own; the peak RSS is GNU time's (%M): a process spawned from Python
    would report Python's own, which it held before exec."""
    if rss:
        report = Path(tempfile.mkstemp(prefix="pita-bench-rss-")[1])
        command = ["/usr/bin/time", "-f", "%M", "-o", str(report)] + list(command)
    err_path = Path(tempfile.mkstemp(prefix="pita-bench-err-")[1])
    out_fd = os.open(stdout or os.devnull, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
    err_fd = os.open(err_path, os.O_WRONLY)
    try:
        start = time.perf_counter()
        pid = os.posix_spawn(command[0], command, os.environ,
                             file_actions=[(os.POSIX_SPAWN_DUP2, out_fd, 1), (os.POSIX_SPAWN_DUP2, err_fd, 2),
                                           (os.POSIX_SPAWN_CLOSE, out_fd), (os.POSIX_SPAWN_CLOSE, err_fd)])
        _, status, usage = os.wait4(pid, 0)
        wall = time.perf_counter() - start
    finally:
        os.close(out_fd)
        os.close(err_fd)
    err = err_path.read_text(errors="replace")
    err_path.unlink()
    code = os.waitstatus_to_exitcode(status)
    if code != 0:
        raise RuntimeError(f"{shown(command)} exited {code}: {err.strip()[:500]}")
    peak = 0
    if rss:
        peak = int(report.read_text().split()[-1])
        report.unlink()
    return wall, usage.ru_utime + usage.ru_stime, peak


def interleaved(commands, rounds, rss=False):
    """Each command of {label: argv} once per round, in turn; {label: [(wall, cpu, rss)]}."""
    results = {label: [] for label in commands}
    for _ in range(rounds):
        for label, command in commands.items():
            results[label].append(run(command, rss=rss))
    return results


def median(values):
    return statistics.median(values)


def shown(command):
    """A command as the docs show it: build/pita, not the absolute path."""
    text = " ".join(command)
    return text.replace(str(ROOT) + "/", "")


def grouped(n):
    """10 000: digits in groups of three, as the docs write numbers."""
    return f"{n:,}".replace(",", " ")


def ms(seconds):
    return f"{seconds * 1000:.1f} ms"


def bench_json(ctx, pattern, min_time, repetitions):
    """Google Benchmark's JSON for the benchmarks matching `pattern` (medians when repeated)."""
    out = ctx.scratch / "bench.json"
    command = [ctx.tool("pita_bench"), f"--benchmark_filter={pattern}", f"--benchmark_out={out}",
               "--benchmark_out_format=json",
               f"--benchmark_min_time={0.001 if ctx.check else min_time}",
               f"--benchmark_repetitions={1 if ctx.check else repetitions}"]
    if not ctx.check and repetitions > 1:
        command.append("--benchmark_report_aggregates_only=true")
    run(command)
    results = {}
    for bench in json.loads(out.read_text())["benchmarks"]:
        if bench.get("run_type") == "aggregate" and bench.get("aggregate_name") != "median":
            continue
        name = bench.get("run_name", bench["name"])
        results[name] = bench
    return results


def bench_ns(bench):
    scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[bench.get("time_unit", "ns")]
    return bench["cpu_time"] * scale


# ------------------------------------------------------------------ reports


def report_startup(ctx):
    """One process: pita against a C++ program that links only cairo."""
    geometry = ctx.scratch / "fig01.geometry"
    figure = ctx.scratch / "fig01.svg"
    run([ctx.tool("pita"), "render", FIG01, "-o", str(figure)])
    with open(geometry, "w") as out:
        subprocess.run([sys.executable, str(ROOT / "bench/floor/figure_geometry.py"), str(figure), FIG01],
                       cwd=ROOT, stdout=out, check=True)
    # Fig. 1 without its titles: no text, so pita never loads pango.
    untitled = json.loads((ROOT / FIG01).read_text())
    untitled.pop("title", None)
    for panel in untitled.get("panels", []):
        panel["title"] = ""
    untitled_scene = ctx.scratch / "fig01-untitled.json"
    untitled_scene.write_text(json.dumps(untitled))
    untitled_geometry = ctx.scratch / "fig01-untitled.geometry"
    untitled_geometry.write_text("".join(line for line in geometry.read_text().splitlines(keepends=True)
                                         if not line.startswith("T ")))
    pita, floor, pango_floor = ctx.tool("pita"), ctx.tool("pita_cairo_floor"), ctx.tool("pita_pango_floor")
    commands = {
        "true": ["/bin/true"],
        "floor-version": [floor, "--version"],
        "pita-version": [pita, "--version"],
        "floor-fig01": [floor, "draw", str(geometry), str(ctx.scratch / "floor.svg")],
        "pango-floor-fig01": [pango_floor, "draw", str(geometry), str(ctx.scratch / "pango-floor.svg")],
        "pita-fig01": [pita, "render", FIG01, "-o", str(ctx.scratch / "pita.svg")],
        "floor-untitled": [floor, "draw", str(untitled_geometry), str(ctx.scratch / "floor-untitled.svg")],
        "pita-untitled": [pita, "render", str(untitled_scene), "-o", str(ctx.scratch / "pita-untitled.svg")],
        "pita-eval": [pita, "eval", FIG01],
    }
    results = interleaved(commands, ctx.rounds(40))
    cpu = {label: median([r[1] for r in runs]) for label, runs in results.items()}
    wall = {label: median([r[0] for r in runs]) for label, runs in results.items()}

    ctx.facts["startup"] = {"fig01": cpu["pita-fig01"], "ratio": cpu["pita-fig01"] / cpu["pango-floor-fig01"],
                            "untitled_ratio": cpu["pita-untitled"] / cpu["floor-untitled"]}

    def row(what, label, *floors):
        ratio = " / ".join(f"{cpu[label] / cpu[f]:.2f}×" for f in floors)
        return f"| {what} | {ms(cpu[label])} | {ms(wall[label])} | {ratio} |"

    return "\n".join([
        "```sh",
        "# each of these once per round, 40 rounds, interleaved; medians of CPU (user + system) and wall time",
        "/bin/true",
        "build/pita_cairo_floor --version",
        "build/pita --version",
        "build/pita_cairo_floor draw fig01.geometry floor.svg   # bench/floor/figure_geometry.py wrote fig01.geometry",
        "build/pita_pango_floor draw fig01.geometry floor.svg",
        f"build/pita render {FIG01} -o pita.svg",
        "build/pita_cairo_floor draw fig01-untitled.geometry floor.svg   # the same without the titles' lines",
        "build/pita render fig01-untitled.json -o pita.svg   # Fig. 1 without its titles",
        f"build/pita eval {FIG01}",
        "```",
        "",
        "| process | CPU | wall | pita / floor (CPU) |",
        "|---|---|---|---|",
        row("`/bin/true`", "true"),
        row("a C++ program linking cairo: `--version`", "floor-version"),
        row("`pita --version`", "pita-version", "floor-version"),
        row("that program drawing Fig. 1's paths and titles (cairo's toy text), SVG", "floor-fig01"),
        row("the same, its titles laid out by pango (linked)", "pango-floor-fig01"),
        row("`pita render` of Fig. 1 (SVG): load, evaluate, lay out, draw, write; against each of the two",
            "pita-fig01", "floor-fig01", "pango-floor-fig01"),
        row("the cairo program drawing Fig. 1's paths alone (no titles)", "floor-untitled"),
        row("`pita render` of Fig. 1 without its titles (no text: pango never loaded)", "pita-untitled",
            "floor-untitled"),
        row("`pita eval` of Fig. 1 (9 frames), against `pita --version`", "pita-eval", "pita-version"),
    ])


def report_eval(ctx):
    """`pita eval` streaming: memory and time against the frame count, and against fmt alone."""
    pita = ctx.tool("pita")
    sizes = [10_000, 100_000, 1_000_000] if not ctx.check else [10_000, 20_000]
    commands = {}
    for n in sizes:
        commands[f"csv-{n}"] = [pita, "eval", FIG01, "--samples", str(n), "--format", "csv", "-o",
                                str(ctx.scratch / f"frames-{n}.csv")]
    top = sizes[-1]
    commands[f"json-{top}"] = [pita, "eval", FIG01, "--samples", str(top), "-o", str(ctx.scratch / "frames.json")]
    results = interleaved(commands, ctx.rounds(3), rss=True)
    floor_runs = [run([ctx.tool("pita_fmt_floor"), str(top)], stdout=ctx.scratch / "floor.csv", rss=True)
                  for _ in range(ctx.rounds(3))]
    rss = {label: max(r[2] for r in runs) / 1024.0 for label, runs in results.items()}
    wall = {label: median([r[0] for r in runs]) for label, runs in results.items()}
    floor_wall = median([r[0] for r in floor_runs])
    floor_rss = max(r[2] for r in floor_runs) / 1024.0
    ctx.facts["eval"] = {"top": top, "wall": wall[f"csv-{top}"], "rss": rss[f"csv-{top}"],
                         "small": sizes[0], "small_rss": rss[f"csv-{sizes[0]}"]}
    lines = [
        "```sh",
        "# each once per round, 3 rounds, interleaved; median wall time, largest peak RSS",
        f"build/pita eval {FIG01} --samples N --format csv -o frames.csv      # N = " +
        ", ".join(grouped(n) for n in sizes),
        f"build/pita eval {FIG01} --samples {top} -o frames.json",
        f"build/pita_fmt_floor {top} > floor.csv    # the same fmt calls, streamed, no motion",
        "```",
        "",
        "| run | wall | peak RSS |",
        "|---|---|---|",
    ]
    for n in sizes:
        lines.append(f"| CSV, {grouped(n)} frames | {ms(wall[f'csv-{n}'])} | {rss[f'csv-{n}']:.1f} MB |")
    lines.append(f"| JSON, {grouped(top)} frames | {ms(wall[f'json-{top}'])} | {rss[f'json-{top}']:.1f} MB |")
    lines.append(f"| fmt alone, {grouped(top)} rows | {ms(floor_wall)} | {floor_rss:.1f} MB |")
    lines += [
        "",
        f"Peak memory at {grouped(top)} frames is {rss[f'csv-{top}'] / rss[f'csv-{sizes[0]}']:.2f}× that at "
        f"{grouped(sizes[0])} (target ≤ 1.2×); CSV time is {wall[f'csv-{top}'] / floor_wall:.2f}× fmt's alone "
        "(target ≤ 1.5×).",
    ]
    return "\n".join(lines)


def report_check(ctx):
    """`pita check` of every scene on one thread and on two."""
    pita = ctx.tool("pita")
    scenes = sorted(str(p.relative_to(ROOT)) for p in (ROOT / "scenes").glob("*.json"))
    if ctx.check:
        scenes = scenes[:2]
    commands = {jobs: [pita, "check", "--jobs", jobs] + scenes for jobs in ("1", "2")}
    results = interleaved(commands, ctx.rounds(3))
    wall = {jobs: median([r[0] for r in runs]) for jobs, runs in results.items()}
    cpu = {jobs: median([r[1] for r in runs]) for jobs, runs in results.items()}
    ctx.facts["check"] = {"scenes": len(scenes), "one": wall["1"], "two": wall["2"]}
    return "\n".join([
        "```sh",
        "# each once per round, 3 rounds, interleaved; medians",
        "build/pita check --jobs 1      # every scene of scenes/ against golden/",
        "build/pita check --jobs 2",
        "```",
        "",
        "| jobs | wall | CPU | speed-up |",
        "|---|---|---|---|",
        f"| 1 | {wall['1']:.2f} s | {cpu['1']:.2f} s | |",
        f"| 2 | {wall['2']:.2f} s | {cpu['2']:.2f} s | {wall['1'] / wall['2']:.2f}× (target ≥ 1.7×) |",
        "",
        f"{len(scenes)} scenes.",
    ])


def report_sweep(ctx):
    """A sweep variant as SVG, PNG and CSV (metrics): time per variant."""
    pita = ctx.tool("pita")
    count = 20 if ctx.check else 300
    commands = {}
    for fmt in ("svg", "png", "csv"):
        commands[fmt] = [pita, "sweep", FIG01, "--vary", f"/keyframes/1/t=0.05:0.95:{count}", "--format", fmt,
                         "--jobs", "1", "-q", "--force", "-o", str(ctx.scratch / f"sweep-{fmt}")]
    results = interleaved(commands, ctx.rounds(3))
    per = {fmt: median([r[0] for r in runs]) / count for fmt, runs in results.items()}
    ctx.facts["sweep"] = per
    return "\n".join([
        "```sh",
        "# each once per round, 3 rounds, interleaved; median wall time / variants",
        f"build/pita sweep {FIG01} --vary /keyframes/1/t=0.05:0.95:{count} --format FORMAT --jobs 1 -q -o out",
        "```",
        "",
        "| per variant (Fig. 1, `--jobs 1`) | SVG | PNG | CSV |",
        "|---|---|---|---|",
        f"| wall time | {ms(per['svg'])} | {ms(per['png'])} | {ms(per['csv'])} |",
        "",
        f"A PNG variant costs {per['png'] / per['svg']:.1f}× an SVG one.",
    ])


def report_methods(ctx):
    """One frame, and one preparation, of each method."""
    frames = bench_json(ctx, "BM_Frame/|BM_Prepare/|BM_LoopOverhead", 0.2, 3)
    methods = [name.split("/", 1)[1] for name in frames if name.startswith("BM_Frame/")]
    lines = [
        "```sh",
        "build/pita_bench --benchmark_filter='BM_Frame/|BM_Prepare/|BM_LoopOverhead' --benchmark_min_time=0.2 "
        "--benchmark_repetitions=3 --benchmark_report_aggregates_only=true",
        "```",
        "",
        "| method | ns / frame | ns / prepare |",
        "|---|---|---|",
    ]
    for method in methods:
        prepare = frames.get(f"BM_Prepare/{method}")
        lines.append(f"| {method} | {bench_ns(frames[f'BM_Frame/{method}']):.0f} | "
                     f"{bench_ns(prepare):.0f} |" if prepare else f"| {method} | "
                     f"{bench_ns(frames[f'BM_Frame/{method}']):.0f} | |")
    loop = frames.get("BM_LoopOverhead")
    if loop:
        lines += ["", f"The timing loop alone (`BM_LoopOverhead`, the loop of `BM_Frame` with no frame in it) costs "
                      f"{bench_ns(loop):.1f} ns per iteration: Debian's Google Benchmark library is built without "
                      "NDEBUG (it warns \"Library was built as DEBUG\"), but the timed loop is inlined from its "
                      "header into `pita_bench`, built `-O3`, so the library's own build only touches the code "
                      "between batches."]
    return "\n".join(lines)


def report_png(ctx):
    """PNG encoding of painted figures: cairo's writer against pita's settings."""
    results = bench_json(ctx, "PngEncode", 0.3, 3)
    settings = [("cairo", "cairo's writer"), ("none_6", "no filter, level 6"), ("none_4", "no filter, level 4 (pita)"),
                ("none_3", "no filter, level 3"), ("none_1", "no filter, level 1")]
    figures = []
    for name in results:
        figure = re.sub(r"_(cairo|all|none|up|sub)(_\d+)?(_rle)?$", "", name.split("/", 1)[-1])
        if figure not in figures:
            figures.append(figure)
    lines = [
        "```sh",
        "build/pita_bench --benchmark_filter=PngEncode --benchmark_min_time=0.3 --benchmark_repetitions=3 "
        "--benchmark_report_aggregates_only=true",
        "```",
        "",
        "| figure | " + " | ".join(label for _, label in settings) + " |",
        "|---|" + "---|" * len(settings),
    ]
    for figure in figures:
        cells = []
        for key, _ in settings:
            bench = results.get(f"BM_PngEncode/{figure}_{key}")
            cells.append(f"{bench_ns(bench) / 1e6:.1f} ms, {bench.get('bytes', 0) / 1000:.1f} kB" if bench else "")
        lines.append(f"| {figure} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def report_existence(ctx):
    """The 3D existence experiment: the test of N61 against Eigen, the curve, and the audits."""
    benches = bench_json(ctx, "Existence3", 0.5, 3)
    pita = ctx.tool("pita")
    commands = {
        "angles": [pita, "audit", "sam3d-existence", "-q"],
        "curve": [pita, "audit", "sam3d-existence", "--curve", "4" if ctx.check else "48", "-q"],
        "figure": [pita, "render", "scenes/sam-fig06-existence-3d.json", "-o", str(ctx.scratch / "existence.png")],
    }
    results = interleaved(commands, ctx.rounds(3))
    wall = {label: median([r[0] for r in runs]) for label, runs in results.items()}
    cpu = {label: median([r[1] for r in runs]) for label, runs in results.items()}

    def bench_cell(name, unit_ns, unit):
        bench = benches.get(name)
        return f"{bench_ns(bench) / unit_ns:.1f} {unit}" if bench else ""

    return "\n".join([
        "```sh",
        "build/pita_bench --benchmark_filter=Existence3 --benchmark_min_time=0.5 --benchmark_repetitions=3 "
        "--benchmark_report_aggregates_only=true",
        "# then each of these once per round, 3 rounds, interleaved; medians",
        "build/pita audit sam3d-existence -q              # the paper's three angles, 81 axes, 17 angles",
        "build/pita audit sam3d-existence --curve 48 -q   # the figure's curve",
        "build/pita render scenes/sam-fig06-existence-3d.json -o existence.png",
        "```",
        "",
        "| | time |",
        "|---|---|",
        "| `has_real_logarithm` on one perturbed rotation (N61's sign and discriminant test) | "
        + bench_cell("BM_Existence3Test", 1, "ns") + " |",
        "| the same answer from Eigen's `EigenSolver<Matrix3d>` | " + bench_cell("BM_Existence3EigenSolver", 1, "ns")
        + " |",
        "| the curve at 13 angles over 21 axes, one thread (`BM_Existence3Curve/12`) | "
        + bench_cell("BM_Existence3Curve/12", 1e6, "ms") + " |",
        f"| `pita audit sam3d-existence` (three bisections over 27 million matrices per `p`), two cores | "
        f"{wall['angles']:.2f} s wall, {cpu['angles']:.2f} s CPU |",
        f"| `pita audit sam3d-existence --curve 48` (the figure's 49 angles), two cores | "
        f"{wall['curve']:.2f} s wall, {cpu['curve']:.2f} s CPU |",
        f"| `pita render` of `sam-fig06-existence-3d` (`\"steps\": 24`, PNG) | "
        f"{wall['figure']:.2f} s wall, {cpu['figure']:.2f} s CPU |",
    ])


def report_pose_pitas(ctx):
    """The PITAs over affine poses: a frame of each against one steady affine morph (bench_pose_pitas.cpp)."""
    benches = bench_json(ctx, "BM_PosePita", 0.2, 3)

    def cell(name):
        bench = benches.get(name)
        return f"{bench_ns(bench):.0f}" if bench else ""

    def sams(name, dimension):
        frame, sam = benches.get(name), benches.get(f"BM_PosePitaSam{dimension}")
        return f"{bench_ns(frame) / bench_ns(sam):.1f}" if frame and sam else ""

    lines = [
        "```sh",
        "build/pita_bench --benchmark_filter=BM_PosePita --benchmark_min_time=0.2 --benchmark_repetitions=3 "
        "--benchmark_report_aggregates_only=true",
        "```",
        "",
        "| method | frame, 2D (ns) | in SAMs (2D) | frame, 3D (ns) | in SAMs (3D) | build, 2D (ns) | build, 3D (ns) |",
        "|---|---|---|---|---|---|---|",
    ]
    for method in ["P4", "P5", "P6", "P9"]:
        lines.append(f"| {method} | {cell(f'BM_PosePitaFrame2/{method}')} | {sams(f'BM_PosePitaFrame2/{method}', 2)} | "
                     f"{cell(f'BM_PosePitaFrame3/{method}')} | {sams(f'BM_PosePitaFrame3/{method}', 3)} | "
                     f"{cell(f'BM_PosePitaPrepare2/{method}')} | {cell(f'BM_PosePitaPrepare3/{method}')} |")
    lines += ["", f"One steady affine morph built and evaluated (`BM_PosePitaSam2`, `BM_PosePitaSam3`): "
              f"{cell('BM_PosePitaSam2')} ns in 2D, {cell('BM_PosePitaSam3')} ns in 3D; \"in SAMs\" is a frame's "
              "cost in those units."]
    return "\n".join(lines)


def report_python(ctx):
    """The Python module against the C++ it calls (BM_StageFrame/P6, BM_PowerEar) and against SciPy."""
    module = sorted((ctx.build / "python").glob("pita.cpython-*.so"))
    if not module:
        raise RuntimeError(f"the Python module is not built in {ctx.build} (configure with -DPITA_PYTHON=ON)")
    python = "/usr/bin/python3" if Path("/usr/bin/python3").exists() else sys.executable
    out = ctx.scratch / "python.json"
    command = [python, str(ROOT / "bench" / "bench_python.py")] + (["--check"] if ctx.check else [])
    previous = os.environ.get("PYTHONPATH")
    os.environ["PYTHONPATH"] = str(ctx.build / "python")
    try:
        run(command, stdout=out)
    finally:
        if previous is None:
            del os.environ["PYTHONPATH"]
        else:
            os.environ["PYTHONPATH"] = previous
    numbers = json.loads(out.read_text())
    cpp = bench_json(ctx, "BM_StageFrame/P6$|BM_PowerEar$", 0.2, 3)
    frame_ns, ear_ns = bench_ns(cpp["BM_StageFrame/P6"]), bench_ns(cpp["BM_PowerEar"])
    ctx.facts["python"] = {"ratio": numbers["motion_ns"] / frame_ns, "scipy": numbers["scipy_us"] * 1e3 / numbers["ear_ns"],
                           "scipy_loop": numbers["scipy_us"] * 1e3 / numbers["ear_loop_ns"]}
    return "\n".join([
        "```sh",
        "PYTHONPATH=build/python /usr/bin/python3 bench/bench_python.py",
        "build/pita_bench --benchmark_filter='BM_StageFrame/P6$|BM_PowerEar$' --benchmark_min_time=0.2 "
        "--benchmark_repetitions=3 --benchmark_report_aggregates_only=true",
        "```",
        "",
        "| what | Python (`import pita`) | C++ | ratio |",
        "|---|---|---|---|",
        f"| P6 frames: `motion(times)`, {grouped(numbers['frames'])} times in one call, against "
        f"`BM_StageFrame/P6` (the frames `pita eval` computes) | {numbers['motion_ns']:.1f} ns / frame | "
        f"{frame_ns:.1f} ns / frame | {numbers['motion_ns'] / frame_ns:.2f}× |",
        f"| `ear_power(M, 0.5)` over {grouped(numbers['matrices'])} different 2D affinities in one batched call, "
        f"against `BM_PowerEar` | {numbers['ear_ns']:.1f} ns / matrix | {ear_ns:.1f} ns / matrix | "
        f"{numbers['ear_ns'] / ear_ns:.2f}× |",
        f"| `ear_power(M[k], 0.5)` in a Python loop over {grouped(numbers['loop_count'])} of the same matrices, one "
        f"2x3 array a call (a list of rows: {numbers['ear_list_ns'] / 1e3:.2f} µs) | "
        f"{numbers['ear_loop_ns'] / 1e3:.2f} µs / call | {ear_ns:.1f} ns / matrix | "
        f"{numbers['ear_loop_ns'] / ear_ns:.1f}× |",
        f"| `scipy.linalg.fractional_matrix_power` in a loop over {grouped(numbers['scipy_count'])} of the same "
        f"matrices (homogeneous 3x3; it takes one matrix a call) | {numbers['scipy_us']:.0f} µs / matrix: "
        f"{numbers['scipy_us'] * 1e3 / numbers['ear_ns']:.0f}× `ear_power` in one batched call, "
        f"{numbers['scipy_us'] * 1e3 / numbers['ear_loop_ns']:.0f}× a loop of single calls | | |",
        f"| `import pita` in a python3 that has imported NumPy (`python3 -X importtime`) | {numbers['import_ms']:.1f} ms | | |",
    ])


def report_summary(ctx):
    """The README's few numbers, from the reports above (run here if they were not)."""
    for name in ("startup", "eval", "check", "sweep"):
        if name not in ctx.facts:
            REPORTS[name](ctx)
    startup, evaluation, check, sweep = (ctx.facts[n] for n in ("startup", "eval", "check", "sweep"))
    if "python" not in ctx.facts and sorted((ctx.build / "python").glob("pita.cpython-*.so")):
        report_python(ctx)
    python = ctx.facts.get("python")
    python_line = ([f"| `import pita`: a P6 motion at 10^6 times, and EAR over 10^5 matrices "
                    f"(docs/guide/python.md) | {python['ratio']:.2f}× the cost of the same frames in C++; "
                    f"`ear_power` {python['scipy']:.0f}× as fast as SciPy's `fractional_matrix_power` in one "
                    f"batched call, {python['scipy_loop']:.0f}× in a loop of single calls |"]
                   if python else [])
    return "\n".join([
        "| what | measured |",
        "|---|---|",
        f"| `pita render` of Fig. 1 as a process of its own (SVG) | {ms(startup['fig01'])} of CPU: "
        f"{startup['ratio']:.2f}× a C++ program linking cairo and pango that draws the same paths and titles; "
        f"without text, {startup['untitled_ratio']:.2f}× one linking cairo alone |",
        f"| `pita eval`, {grouped(evaluation['top'])} frames as CSV into a file | {evaluation['wall']:.2f} s, "
        f"peak memory {evaluation['rss']:.1f} MB ({evaluation['small_rss']:.1f} MB at {grouped(evaluation['small'])}) |",
        f"| `pita check` of the {check['scenes']} scenes of `scenes/` | {check['one']:.2f} s on one core, "
        f"{check['two']:.2f} s on two (`--jobs`) |",
        f"| one variant of a `pita sweep` of Fig. 1 | SVG {ms(sweep['svg'])}, PNG {ms(sweep['png'])}, "
        f"metrics (CSV) {ms(sweep['csv'])} |",
    ] + python_line)


REPORTS = {
    "startup": report_startup,
    "eval": report_eval,
    "check": report_check,
    "sweep": report_sweep,
    "methods": report_methods,
    "png": report_png,
    "existence": report_existence,
    "pose-pitas": report_pose_pitas,
    "python": report_python,
    "summary": report_summary,  # last: it reuses the numbers of the reports run before it
}


def machine():
    model = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return f"{model}, {os.cpu_count()} cores"


def blocks():
    """{name: path} of every bench-report block in the docs."""
    found = {}
    for path in DOCS:
        for match in BLOCK.finditer(path.read_text()):
            found[match.group("name")] = path
    return found


def rewrite(name, body):
    for path in DOCS:
        text = path.read_text()
        new = BLOCK.sub(lambda m: m.group(1) + body + "\n" + m.group(4) if m.group("name") == name else m.group(0),
                        text)
        if new != text:
            tmp = path.with_name("." + path.name + ".tmp")
            tmp.write_text(new)
            os.replace(tmp, path)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", required=True, help="the build folder (pita, pita_bench, the floors)")
    parser.add_argument("--check", action="store_true", help="run every report once at a tiny size; rewrite nothing")
    parser.add_argument("--skip", action="append", default=[], metavar="NAME",
                        help="a report not to run (python, in a build without -DPITA_PYTHON=ON)")
    parser.add_argument("names", nargs="*", help="reports to run (default: all): " + ", ".join(REPORTS))
    args = parser.parse_args()
    os.chdir(ROOT)  # the commands name scenes/... as the docs show them
    unknown = [n for n in args.names if n not in REPORTS]
    if unknown:
        parser.error(f"no report {', '.join(unknown)} (reports: {', '.join(REPORTS)})")
    found = blocks()
    problems = [f"{path.relative_to(ROOT)}: block {name} has no report" for name, path in found.items()
                if name not in REPORTS]
    problems += [f"report {name} has no block in the docs" for name in REPORTS if name not in found]
    ctx = Context(args.build, args.check)
    try:
        for name in args.names or list(REPORTS):
            if name in args.skip:
                print(f"bench-report: {name} skipped (--skip {name})", file=sys.stderr)
                continue
            started = time.perf_counter()
            try:
                table = REPORTS[name](ctx)
            except (RuntimeError, OSError, KeyError, ValueError, subprocess.CalledProcessError) as error:
                problems.append(f"report {name}: {error}")
                continue
            print(f"bench-report: {name} ({time.perf_counter() - started:.1f} s)", file=sys.stderr)
            if args.check:
                continue
            stamp = (f"Measured on {machine()}, {datetime.date.today().isoformat()}, by "
                     f"`scripts/bench-report.sh {name}` (written by it: do not edit by hand).\n\n")
            if table.startswith("```sh"):
                table = ("<!-- no-run: a measurement (scripts/bench-report.sh runs it; ctest docs.bench_report "
                         "checks that its commands run) -->\n" + table)
            rewrite(name, stamp + table)
    finally:
        shutil.rmtree(ctx.scratch, ignore_errors=True)
    for problem in problems:
        print(f"bench-report: {problem}", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
