#!/usr/bin/env python3
"""The figure gallery (docs/gallery.md): a thumbnail of each scene's golden PNG, linked,
with the scene's title and the claims it makes (docs/reference/check.md "Claims": each one is
checked by `pita check`, so by ctest's golden.<scene>, and the suite fails
when one stops holding), between the markers <!-- gallery:begin --> and
<!-- gallery:end --> of docs/gallery.md.

  scripts/make-gallery.py           rewrite the gallery in docs/gallery.md
  scripts/make-gallery.py --check   exit 1 if it is not up to date (ctest docs.gallery)
"""
import json
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "scripts" / "lib"))
from generated_page import write_or_check  # noqa: E402
BEGIN, END = "<!-- gallery:begin -->", "<!-- gallery:end -->"
COLUMNS = 3
SHOWN_CLAIMS = 3  # per cell; the others are counted


def gallery() -> str:
    cells = []
    for scene in sorted((ROOT / "scenes").glob("*.json")):
        name = scene.stem
        document = json.loads(scene.read_text())
        title = document.get("title", name).replace("|", "\\|")
        png = f"golden/{name}/{name}.png"
        link = f"../{png}"  # relative to docs/
        if not (ROOT / png).exists():
            raise SystemExit(f"make-gallery: {png} is missing: write the goldens first (pita update-goldens)")
        claims = [c["says"].replace("|", "\\|").replace("<", "&lt;") for c in document.get("claims", [])]
        lines = [f"✓ {says}" for says in claims[:SHOWN_CLAIMS]]
        if len(claims) > SHOWN_CLAIMS:
            lines.append(f"(and {len(claims) - SHOWN_CLAIMS} more claims)")
        cells.append("<br>".join([f'<a href="{link}"><img src="{link}" width="260" alt="{name}"></a>',
                                  f"`{name}`: {title}", *lines]))
    rows = ["| " + " | ".join([""] * COLUMNS) + " |", "|" + "---|" * COLUMNS]
    for i in range(0, len(cells), COLUMNS):
        chunk = cells[i:i + COLUMNS] + [""] * (COLUMNS - len(cells[i:i + COLUMNS]))
        rows.append("| " + " | ".join(chunk) + " |")
    return "\n".join([BEGIN, *rows, END])


def main() -> int:
    page = ROOT / "docs" / "gallery.md"
    text = page.read_text()
    if BEGIN not in text or END not in text:
        print(f"make-gallery: docs/gallery.md has no {BEGIN} ... {END} section", file=sys.stderr)
        return 1
    start, end = text.index(BEGIN), text.index(END) + len(END)
    return write_or_check(ROOT, page, text[:start] + gallery() + text[end:], "a scene or its title changed",
                          "scripts/make-gallery.py")


if __name__ == "__main__":
    sys.exit(main())
