#!/usr/bin/env python3
"""ctest docs.scenes_lint: every scene the docs show lints clean.

A scene is a fenced ```json block, or a here-document of a ```sh block
(cat > NAME.json <<'EOF' ... EOF), that parses as a JSON object with
"keyframes", "points" or "poses". Each is written to a temporary folder
(beside the docs' examples/ images, so that relative paths resolve as in the
examples) and given to `pita lint`; any finding it does not accept fails the
test, which prints the page, the line and the lint's message. A reader who
copies a scene from the docs gets a figure without findings.

  tests/docs/lint_scenes.py ROOT PITA
"""
import json
import pathlib
import re
import subprocess
import sys
import tempfile

FENCED = re.compile(r"```json\n(.*?)```", re.S)
HEREDOC = re.compile(r"cat > \S+\.json <<'?(\w+)'?\n(.*?)\n\1\n", re.S)


def scenes(page: pathlib.Path):
    """(line, scene) of each scene shown on the page."""
    text = page.read_text()
    for pattern, group in ((FENCED, 1), (HEREDOC, 2)):
        for m in pattern.finditer(text):
            try:
                value = json.loads(m.group(group))
            except ValueError:
                continue  # a fragment ("claims": [...]) or an example of a bad scene
            if isinstance(value, dict) and any(k in value for k in ("keyframes", "points", "poses")):
                yield text[: m.start()].count("\n") + 1, value


def main() -> int:
    root, pita = pathlib.Path(sys.argv[1]), sys.argv[2]
    pages = sorted((root / "docs").rglob("*.md")) + [root / "README.md"]
    failures, count = 0, 0
    with tempfile.TemporaryDirectory() as work:
        for page in pages:
            for line, scene in scenes(page):
                count += 1
                path = pathlib.Path(work) / f"scene-{count}.json"
                path.write_text(json.dumps(scene))
                result = subprocess.run([pita, "lint", str(path)], capture_output=True, text=True, cwd=root)
                if result.returncode == 2:
                    continue  # not a whole scene on its own (needs a file of the page): docs.examples runs it
                if result.returncode != 0:
                    failures += 1
                    print(f"{page.relative_to(root)}:{line}: pita lint exits {result.returncode}:")
                    print((result.stdout + result.stderr).replace(str(path), "scene"))
    print(f"{count} scenes of the docs linted, {failures} with findings")
    return 1 if failures or count == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
