#!/usr/bin/env python3
"""The generated parts of docs/, written from pita itself so that they cannot
disagree with it:

- in each page of docs/reference/, the block between
  <!-- help:begin pita SUBCOMMAND --> and <!-- help:end --> is the output of
  `pita SUBCOMMAND --help` (the man page is written from the same CLI11
  definitions, tests/packaging/check_man_page.py);
- docs/images/fig23-image-motion.svg, the README's animation, is
  `pita animate scenes/fig23-image-motion.json --frames 60 --duration 4`.

  scripts/make-docs.py PITA           rewrite them
  scripts/make-docs.py PITA --check   exit 1 if one is not up to date (ctest docs.reference)

PITA is the binary (build/pita).
"""
import pathlib
import re
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
BLOCK = re.compile(r"(<!-- help:begin pita ?([a-z0-9 -]*?) -->\n)(.*?)(<!-- help:end -->)", re.S)
ANIMATION = ("scenes/fig23-image-motion.json", "docs/images/fig23-image-motion.svg",
             ["--frames", "60", "--duration", "4"])


def help_text(pita: str, subcommand: str) -> str:
    result = subprocess.run([pita, *subcommand.split(), "--help"], capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"make-docs: a help block names `pita {subcommand}`, which pita does not know: "
                 f"{result.stderr.strip()}")
    return "```text\n" + result.stdout.rstrip() + "\n```\n"


def subcommands(pita: str, parent: str = "") -> list:
    """Every subcommand pita's --help lists ("eval", ..., "audit sam3d-existence")."""
    text = subprocess.run([pita, *parent.split(), "--help"], capture_output=True, text=True, check=True).stdout
    listed = re.search(r"^Subcommands:\n((?:  \S.*\n)+)", text, re.M)
    found = []
    for line in listed.group(1).splitlines() if listed else []:
        name = f"{parent} {line.split()[0]}".strip()
        found += [name, *subcommands(pita, name)]
    return found


def pages_with_help(pita: str):
    """(page, text now, text wanted) for each reference page with a help block."""
    for page in sorted((ROOT / "docs" / "reference").glob("*.md")):
        text = page.read_text()
        wanted = BLOCK.sub(lambda m: m.group(1) + help_text(pita, m.group(2)) + m.group(4), text)
        yield page, text, wanted


def animation(pita: str) -> bytes:
    scene, _, options = ANIMATION
    with tempfile.TemporaryDirectory() as work:
        out = pathlib.Path(work) / "animation.svg"
        subprocess.run([pita, "animate", str(ROOT / scene), "-o", str(out), "-q", *options],
                       check=True, capture_output=True, cwd=ROOT)
        return out.read_bytes()


NUMBER = re.compile(rb"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?")


def same_figure(a: bytes, b: bytes) -> bool:
    """The same SVG up to rounding: a build with another compiler (the
    sanitizers' clang) may differ in the last digits of a coordinate."""
    if NUMBER.sub(b"#", a) != NUMBER.sub(b"#", b):
        return False
    x, y = NUMBER.findall(a), NUMBER.findall(b)
    return all(abs(float(u) - float(v)) <= 1e-3 * max(1.0, abs(float(u))) for u, v in zip(x, y))


def main() -> int:
    args = [a for a in sys.argv[1:] if a != "--check"]
    check = "--check" in sys.argv[1:]
    if len(args) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    pita = str(pathlib.Path(args[0]).resolve())
    stale = []
    documented = {m.group(2) for page in (ROOT / "docs" / "reference").glob("*.md")
                  for m in BLOCK.finditer(page.read_text())}
    missing = [name for name in ["", *subcommands(pita)] if name not in documented]
    for name in missing:
        print(f"make-docs: no page of docs/reference holds `pita {name} --help` "
              f"(add <!-- help:begin pita {name} --> <!-- help:end --> to its page)".replace("pita  ", "pita "),
              file=sys.stderr)
    for page, text, wanted in pages_with_help(pita):
        if text != wanted:
            stale.append(page)
            if not check:
                page.write_text(wanted)
    target = ROOT / ANIMATION[1]
    svg = animation(pita)
    if not target.exists() or not same_figure(target.read_bytes(), svg):
        stale.append(target)
        if not check:
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(svg)
    if missing:
        return 1
    if check and stale:
        for path in stale:
            print(f"make-docs: {path.relative_to(ROOT)} is out of date (pita's --help or the figure changed): "
                  "run scripts/make-docs.py build/pita and review the difference", file=sys.stderr)
        return 1
    for path in stale if not check else []:
        print(f"wrote {path.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
