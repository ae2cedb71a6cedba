#!/usr/bin/env python3
"""ctest docs.links: every relative link and anchor of README.md, CHANGELOG.md
and docs/**/*.md resolves. A link is a Markdown link [text](target) or an
HTML href/src outside code; a target is a file or folder of the repository,
optionally with #anchor, which must be a heading of that Markdown file (as
GitHub makes anchors: lower case, punctuation dropped, spaces to hyphens, -1,
-2 ... for repeats) or an explicit <a id="..."> / <a name="...">; into
another file, only a line: #L12.

  tests/docs/check_links.py ROOT
"""
import collections
import pathlib
import re
import sys

LINK = re.compile(r"\]\(([^()\s]+)\)|(?:href|src)=\"([^\"]+)\"")
HEADING = re.compile(r"^(#{1,6}) +(.*?) *#*$")
EXPLICIT = re.compile(r"<a (?:id|name)=\"([^\"]+)\"")


def slug(text: str) -> str:
    text = re.sub(r"<[^>]+>", "", text)  # inline HTML
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)  # links keep their text
    text = text.strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def prose_lines(text: str):
    """(line number, line) outside fenced code blocks."""
    fence = None
    for number, line in enumerate(text.split("\n"), 1):
        stripped = line.lstrip()
        if fence is None and (stripped.startswith("```") or stripped.startswith("~~~")):
            fence = stripped[:3]
            continue
        if fence is not None:
            if stripped.startswith(fence):
                fence = None
            continue
        yield number, line


def anchors(path: pathlib.Path, cache={}) -> set:
    if path not in cache:
        seen = collections.Counter()
        found = set()
        for _, line in prose_lines(path.read_text()):
            found.update(EXPLICIT.findall(line))
            m = HEADING.match(line)
            if m:
                base = slug(m.group(2))
                found.add(base if seen[base] == 0 else f"{base}-{seen[base]}")
                seen[base] += 1
        cache[path] = found
    return cache[path]


def main() -> int:
    root = pathlib.Path(sys.argv[1]).resolve()
    files = [f for f in (root / "README.md", root / "CHANGELOG.md") if f.exists()]
    files += sorted((root / "docs").rglob("*.md"))
    problems = []
    checked = 0
    for page in files:
        for number, line in prose_lines(page.read_text()):
            for m in LINK.finditer(re.sub(r"`[^`]*`", "", line)):
                target = m.group(1) or m.group(2)
                if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # http:, mailto: ...
                    continue
                checked += 1
                where = f"{page.relative_to(root)}:{number}"
                path_part, _, anchor = target.partition("#")
                goal = (page.parent / path_part).resolve() if path_part else page
                if not goal.exists():
                    problems.append(f"{where}: {target}: no such file")
                    continue
                if root not in goal.parents and goal != root:
                    problems.append(f"{where}: {target}: outside the repository")
                    continue
                if anchor:
                    if goal.suffix != ".md":
                        line_anchor = re.fullmatch(r"L(\d+)", anchor)
                        if not line_anchor:
                            problems.append(f"{where}: {target}: an anchor into a file that is not Markdown")
                        elif int(line_anchor.group(1)) > len(goal.read_text(errors="replace").split("\n")):
                            problems.append(f"{where}: {target}: {goal.relative_to(root)} is shorter")
                    elif anchor not in anchors(goal):
                        problems.append(f"{where}: {target}: {goal.relative_to(root)} has no heading #{anchor}")
    for problem in problems:
        print(problem, file=sys.stderr)
    if problems:
        print(f"{len(problems)} of {checked} links do not resolve", file=sys.stderr)
        return 1
    print(f"{checked} links in {len(files)} files resolve")
    return 0


if __name__ == "__main__":
    sys.exit(main())
