#!/usr/bin/env python3
"""ctest docs.examples: every example of README.md and docs/ runs.

An example is a fenced ```sh block: every one runs, unless marked (below).
Each block runs with bash -e -o pipefail. The examples of one page run
in order in one temporary folder, as a reader who follows the page runs them
(the tour writes three.json, the next block renders it); the folder holds a
copy of scenes/ and golden/ (so that an example may write there) and
symlinks to schema/, examples/ and scripts/, with the pita under test first
on PATH as `pita`. A non-zero exit fails the test, which prints the file, the
line of the block, the block and its output.

A block that must not run (it installs packages, needs a cluster, is a
benchmark or the test command itself) has an HTML comment just before it that
says why:
<!-- no-run: installs packages -->. A no-run comment without a reason is an error.

  tests/docs/run_examples.py ROOT PITA [FILE...]
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

NO_RUN = re.compile(r"^<!-- no-run(?::\s*(.*?))?\s*-->$")


def blocks(page: pathlib.Path):
    """(line, code, no-run reason or None, no-run comment without a reason) of each sh block."""
    lines = page.read_text().split("\n")
    i = 0
    while i < len(lines):
        if lines[i].strip() == "```sh":
            start = i + 1
            j = start
            while j < len(lines) and lines[j].strip() != "```":
                j += 1
            before = next((lines[k].strip() for k in range(i - 1, -1, -1) if lines[k].strip()), "")
            m = NO_RUN.match(before)
            yield start, "\n".join(lines[start:j]), (m.group(1) if m else None), bool(m and not m.group(1))
            i = j
        i += 1


def link_or_copy(source, target):
    """A hard link where the file system allows one (pita writes every file to
    a temporary and renames it, so an example that updates a golden replaces
    the link and never the original), else a copy (/tmp on another file
    system than the clone)."""
    try:
        os.link(source, target)
    except OSError:
        shutil.copy2(source, target)


def sandbox(root: pathlib.Path, pita: pathlib.Path, work: pathlib.Path) -> dict:
    shutil.copytree(root / "scenes", work / "scenes", symlinks=True)
    shutil.copytree(root / "golden", work / "golden", copy_function=link_or_copy)
    for name in ("schema", "examples", "scripts"):
        (work / name).symlink_to(root / name)
    bin_dir = work / ".bin"
    bin_dir.mkdir()
    (bin_dir / "pita").symlink_to(pita)
    # HOME too: an example that goes to ~/somewhere stays in the folder
    return {**os.environ, "HOME": str(work), "PATH": f"{bin_dir}:{os.environ.get('PATH', '/usr/bin:/bin')}"}


def main() -> int:
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    root = pathlib.Path(sys.argv[1]).resolve()
    pita = pathlib.Path(sys.argv[2]).resolve()
    pages = [pathlib.Path(p).resolve() for p in sys.argv[3:]] or \
        [root / "README.md", *sorted((root / "docs").rglob("*.md"))]
    failures, ran, skipped = [], 0, 0
    for page in pages:
        runnable = []
        for line, code, reason, unexplained in blocks(page):
            where = f"{page.relative_to(root)}:{line}"
            if unexplained:
                failures.append(f"{where}: a no-run comment must say why (<!-- no-run: REASON -->)")
                continue
            if reason is not None:
                skipped += 1
                continue
            runnable.append((where, code))
        if not runnable:
            continue
        with tempfile.TemporaryDirectory(prefix="pita-doc-") as work:
            env = sandbox(root, pita, pathlib.Path(work))
            for where, code in runnable:
                ran += 1
                result = subprocess.run(["bash", "-e", "-o", "pipefail", "-c", code], cwd=work, env=env,
                                        stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=600)
                if result.returncode != 0:
                    failures.append(f"{where}: the example exits {result.returncode}:\n{code}\n"
                                    f"--- its output:\n{result.stdout[-2000:]}{result.stderr[-2000:]}")
    for failure in failures:
        print(failure, file=sys.stderr)
    print(f"{ran} examples ran, {skipped} marked no-run, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
