#!/usr/bin/env python3
"""ctest docs.links: every relative link and anchor of README.md, CHANGELOG.md
and docs/**/*.md resolves. A link is a Markdown link [text](target) or an
HTML href/src outside code; a target is a file or folder of the repository,
optionally with #anchor, which must be a heading of that Markdown file (as
GitHub makes anchors: lower case, punctuation dropped, spaces to hyphens, -1,
-2 ... for repeats) or an explicit <a id="..."> / <a name="...">; into
another file, only a line: #L12.

It also checks the references to a section that code, messages, the schema
and scenes make in words, `docs/reference/check.md "Claims"` (a comment may
break the quoted words over lines): the page exists and has a heading that
starts with those words.

  tests/docs/check_links.py ROOT
"""
import collections
import pathlib
import re
import subprocess
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


SECTION_REFERENCE = re.compile(r'(README(?:\.md)?|docs/[\w/.-]+\.md)(?: |\()\\?"([^"\\]{1,80})\\?"')
SOURCE_FOLDERS = ("src", "tests", "scripts", "schema", "scenes", "cmake", "fuzz", "bench")


def headings(path: pathlib.Path) -> list:
    return [re.sub(r"[`*]", "", m.group(2)).lower() for _, line in prose_lines(path.read_text())
            for m in [HEADING.match(line)] if m]


def section_references(root: pathlib.Path):
    """(where, page, words, problem or None) for each reference to a section in the sources."""
    try:
        listed = subprocess.run(["git", "ls-files", *SOURCE_FOLDERS, "CMakeLists.txt"], cwd=root,
                                capture_output=True, text=True, check=True).stdout.split()
    except (OSError, subprocess.CalledProcessError):
        listed = []
    if not listed:  # not a git tree (a source package, the self-test's data)
        listed = [str(p.relative_to(root)) for top in SOURCE_FOLDERS for p in (root / top).rglob("*") if p.is_file()]
    for name in listed:
        if name.startswith("tests/docs/"):  # the checks' own self-test names pages that do not exist
            continue
        path = root / name
        if path.suffix not in (".cpp", ".hpp", ".h", ".py", ".sh", ".json", ".txt", ".cmake", ".expect") \
                and path.name != "CMakeLists.txt":
            continue
        text = path.read_text(errors="replace")
        for m in SECTION_REFERENCE.finditer(text):
            where = f"{name}:{text.count(chr(10), 0, m.start()) + 1}"
            words = re.sub(r"\s*\n\s*(?://|#)?\s*", " ", m.group(2)).strip().lower()
            page = root / (m.group(1) if m.group(1).endswith(".md") else "README.md")
            problem = None
            if not page.exists():
                problem = "no such page"
            elif not any(h.startswith(words) for h in headings(page)):
                problem = f"{m.group(1)} has no heading that starts with it"
            yield where, m.group(1), words, problem


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
    references = list(section_references(root))
    wrong = [f'{where}: {page} "{words}": {problem}' for where, page, words, problem in references if problem]
    for problem in problems + wrong:
        print(problem, file=sys.stderr)
    if problems or wrong:
        print(f"{len(problems)} of {checked} links and {len(wrong)} of {len(references)} section references "
              "do not resolve", file=sys.stderr)
        return 1
    print(f"{checked} links in {len(files)} files and {len(references)} section references resolve")
    return 0


if __name__ == "__main__":
    sys.exit(main())
