#!/usr/bin/env python3
"""ctest docs.self_test: the documentation checks fail when they should. A
doc example broken on purpose fails docs.examples, naming its line; a no-run
or in-clone comment without a reason is an error; the examples run in an
empty folder of the user's own outside the source tree, with pita on PATH and
PITA_SOURCE set, and in-clone ones in the source tree; examples that write
into the source tree fail, naming the files, in a git work tree and in a tree
without git; broken links and anchors fail
docs.links, each named, as do references to a section that does not exist,
and the good ones pass.

  tests/docs/self_test.py PITA
"""
import pathlib
import shutil
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
DATA = HERE / "data"
ROOT = HERE.parent.parent


def run(*args):
    return subprocess.run([sys.executable, *map(str, args)], capture_output=True, text=True)


def main() -> int:
    pita = sys.argv[1]
    failures = []
    checks = 0

    def expect(condition, what, result):
        nonlocal checks
        checks += 1
        if not condition:
            failures.append(f"{what}\n--- stdout:\n{result.stdout}--- stderr:\n{result.stderr}")

    broken = run(HERE / "run_examples.py", ROOT, pita, DATA / "broken-example.md")
    expect(broken.returncode == 1, "a broken example must fail docs.examples (exit 1)", broken)
    expect("broken-example.md:11: the example exits 2" in broken.stderr,
           "the failure must name the page and line of the broken block", broken)
    expect("no-such-scene.json" in broken.stderr, "the failure must show pita's message", broken)
    expect("also-missing" not in broken.stderr, "a no-run block must not run", broken)
    expect("2 examples ran, 1 marked no-run, 1 failed" in broken.stdout, "the counts", broken)

    unexplained = run(HERE / "run_examples.py", ROOT, pita, DATA / "unexplained-no-run.md")
    expect(unexplained.returncode == 1 and "must say why" in unexplained.stderr,
           "a no-run comment without a reason must fail", unexplained)

    own = run(HERE / "run_examples.py", ROOT, pita, DATA / "own-folder.md")
    expect(own.returncode == 0 and "3 examples ran, 0 marked no-run, 0 failed" in own.stdout,
           "the examples run in an empty folder of the user's own, in-clone ones in the source tree", own)

    git = shutil.which("git")
    for with_git in (False, True) if git else (False,):
        with tempfile.TemporaryDirectory(prefix="pita-doc-tree-") as tree:
            tree = pathlib.Path(tree)
            (tree / "scenes").mkdir()
            (tree / "scenes" / "a.json").write_text('{"title": "a scene of the tree"}\n')
            (tree / ".gitignore").write_text("/out/\n")
            shutil.copy(DATA / "writes-into-clone.md", tree / "page.md")
            if with_git:
                quiet = {"check": True, "capture_output": True}
                subprocess.run([git, "init", "-q", str(tree)], **quiet)
                subprocess.run([git, "-C", str(tree), "add", "scenes/a.json"], **quiet)
                subprocess.run([git, "-C", str(tree), "-c", "user.name=t", "-c", "user.email=t@t", "commit", "-q",
                                "-m", "a scene"], **quiet)
            kind = "a git work tree" if with_git else "a tree without git"
            wrote = run(HERE / "run_examples.py", tree, pita, tree / "page.md")
            expect(wrote.returncode == 1 and "page.md: its examples wrote into the source tree" in wrote.stderr,
                   f"examples that write into the source tree must fail ({kind})", wrote)
            expect("new: stray.txt" in wrote.stderr and ("new: out/" if with_git else "new: out/figure.svg")
                   in wrote.stderr and "changed: scenes/a.json" in wrote.stderr,
                   f"the files written and changed are named ({kind})", wrote)
            expect("page.md:14: a marking comment must say why" in wrote.stderr,
                   "an in-clone comment without a reason must fail", wrote)

    links = run(HERE / "check_links.py", DATA / "broken")
    expect(links.returncode == 1, "broken links must fail docs.links (exit 1)", links)
    expect("README.md:4: docs/missing.md: no such file" in links.stderr, "a missing file is named", links)
    expect("README.md:4: docs/page.md#no-such-heading: docs/page.md has no heading #no-such-heading"
           in links.stderr, "a missing heading is named", links)
    expect("outside the repository" in links.stderr, "a link out of the tree is refused", links)
    expect("docs/code.txt is shorter" in links.stderr, "a line past the end of a file is named", links)
    expect('src/refs.cpp:2: docs/page.md "no such section": docs/page.md has no heading that starts with it'
           in links.stderr, "a reference to a section a page does not have is named", links)
    expect('src/refs.cpp:3: docs/gone.md "a heading": no such page' in links.stderr,
           "a reference to a missing page is named", links)
    expect("4 of 8 links and 2 of 3 section references do not resolve" in links.stderr,
           "only the bad links and references fail", links)

    for failure in failures:
        print(failure, file=sys.stderr)
    print(f"{checks - len(failures)} of {checks} checks hold")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
