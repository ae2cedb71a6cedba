#!/usr/bin/env python3
"""ctest docs.examples: every example of README.md and docs/ runs, from a
user's own folder, and writes nothing into the clone.

An example is a fenced ```sh block: every one runs, unless marked (below).
Each block runs with bash -e -o pipefail. The examples of one page run in
order in one folder of the user's own, as a reader who follows the page runs
them (the tour writes three.json, the next block renders it): a new, empty
temporary folder outside the source tree, which is also HOME (an example that
goes to ~/somewhere stays in it). The environment is what the guides ask of a
reader: the pita under test first on PATH as `pita` (from a folder of its
own, not the page's), and PITA_SOURCE set to the source tree, through which
the guides reach pita's own scenes, goldens and images
(`cp "$PITA_SOURCE/scenes/fig13-knot-ratio.json" .`). A non-zero exit fails
the test, which prints the file, the line of the block, the block and its
output.

Nothing a page tells its reader to run may write into the source tree: the
test compares the tree before and after each page's examples (with
`git status` where the tree is a git work tree and git is installed, else a
listing of its files, build folders left out) and fails naming what a page
added, removed or changed.

Two HTML comments just before a block mark it; each must say why:
- <!-- no-run: installs packages --> : the block does not run (it installs
  packages, needs a cluster, is a benchmark or the test command itself);
- <!-- in-clone: a developer's command --> : the block runs in the source
  tree, as the page tells its reader to (a developer's page: make-docs, the
  test command), with the same environment; it, too, must leave the tree as
  it was.
A marking comment without a reason is an error.

  tests/docs/run_examples.py ROOT PITA [FILE...]
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

MARK = re.compile(r"^<!-- (no-run|in-clone)(?::\s*(.*?))?\s*-->$")


def blocks(page: pathlib.Path):
    """(line, code, mark, reason) of each sh block: mark is None, "no-run" or
    "in-clone", reason the marking comment's (empty when it gave none)."""
    lines = page.read_text().split("\n")
    i = 0
    while i < len(lines):
        if lines[i].strip() == "```sh":
            start = i + 1
            j = start
            while j < len(lines) and lines[j].strip() != "```":
                j += 1
            before = next((lines[k].strip() for k in range(i - 1, -1, -1) if lines[k].strip()), "")
            m = MARK.match(before)
            yield start, "\n".join(lines[start:j]), (m.group(1) if m else None), (m.group(2) or "" if m else "")
            i = j
        i += 1


def is_build_folder(path: pathlib.Path) -> bool:
    return (path / "CMakeCache.txt").exists()


def snapshot(root: pathlib.Path) -> dict:
    """What the source tree holds, to compare before and after a page. In a
    git work tree, git status: each untracked, ignored or changed entry (an
    untracked or ignored folder is one entry) with its status, so that a file
    a page writes, or a tracked file it changes (a golden, a scene), shows as a
    new entry, while the files a developer edits meanwhile keep theirs.
    Elsewhere (a source tarball, no git), every file with its size and
    modification time, build folders left out."""
    git = shutil.which("git")
    if git and (root / ".git").exists():
        result = subprocess.run([git, "-C", str(root), "status", "--porcelain=v1", "-z", "--ignored",
                                 "--untracked-files=normal"], capture_output=True)
        if result.returncode == 0:
            # a rename's source path follows it as an item of its own: harmless here
            return {item[3:]: item[:2] for item in result.stdout.decode(errors="replace").split("\0")
                    if len(item) > 3}
    entries = {}
    for folder, dirs, files in os.walk(root):
        here = pathlib.Path(folder)
        dirs[:] = [d for d in dirs if d != ".git" and not is_build_folder(here / d)]
        for name in files:
            try:
                s = (here / name).stat()
            except OSError:
                continue
            entries[str((here / name).relative_to(root))] = (s.st_size, s.st_mtime_ns)
    return entries


def differences(before: dict, after: dict) -> list:
    """What a page left: "new: PATH" for a file or folder it wrote, "changed:
    PATH" for one it changed, "removed: PATH" for one it removed (in a git
    work tree, "changed" and "removed" are tracked files, by their status)."""
    def what(path):
        if path in before and path in after:
            return "changed"
        status = after.get(path, before.get(path))
        if isinstance(status, str) and status not in ("??", "!!"):  # a tracked file's status
            return "removed" if "D" in status else "changed"
        return "new" if path in after else "removed"
    left = [k for k in set(after) | set(before) if before.get(k) != after.get(k)]
    return [f"{what(k)}: {k}" for k in sorted(left)]


def user_environment(root: pathlib.Path, pita: pathlib.Path, base: pathlib.Path):
    """An empty folder of the user's own and the environment the guides ask for."""
    work = base / "work"
    work.mkdir()
    bin_dir = base / "bin"
    bin_dir.mkdir()
    (bin_dir / "pita").symlink_to(pita)
    env = {**os.environ, "HOME": str(work), "PITA_SOURCE": str(root),
           "PATH": f"{bin_dir}:{os.environ.get('PATH', '/usr/bin:/bin')}"}
    return work, env


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
        for line, code, mark, reason in blocks(page):
            where = f"{page.relative_to(root)}:{line}"
            if mark and not reason:
                failures.append(f"{where}: a marking comment must say why (<!-- {mark}: REASON -->)")
                continue
            if mark == "no-run":
                skipped += 1
                continue
            runnable.append((where, code, mark == "in-clone"))
        if not runnable:
            continue
        with tempfile.TemporaryDirectory(prefix="pita-doc-") as base:
            work, env = user_environment(root, pita, pathlib.Path(base).resolve())
            if work == root or root in work.parents:
                print(f"the temporary folder {work} is inside the source tree {root}: set TMPDIR",
                      file=sys.stderr)
                return 2
            before = snapshot(root)
            for where, code, in_clone in runnable:
                ran += 1
                result = subprocess.run(["bash", "-e", "-o", "pipefail", "-c", code],
                                        cwd=root if in_clone else work, env=env,
                                        stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=600)
                if result.returncode != 0:
                    failures.append(f"{where}: the example exits {result.returncode}:\n{code}\n"
                                    f"--- its output:\n{result.stdout[-2000:]}{result.stderr[-2000:]}")
            left = differences(before, snapshot(root))
            if left:
                failures.append(f"{page.relative_to(root)}: its examples wrote into the source tree "
                                f"({len(left)}):\n  " + "\n  ".join(left[:20]))
    for failure in failures:
        print(failure, file=sys.stderr)
    print(f"{ran} examples ran, {skipped} marked no-run, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
