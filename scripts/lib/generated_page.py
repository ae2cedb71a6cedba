"""The one way the docs generators (scripts/make-*.py) write a generated page
or check it: with --check, exit 1 and say which command rewrites the page when
it is out of date; without, write it and say so."""
import sys
from pathlib import Path


def write_or_check(root: Path, page: Path, text: str, why: str, command: str, same=None) -> int:
    """`same(old, new)` decides "up to date" (default: equal text)."""
    name = page.relative_to(root)
    if "--check" in sys.argv[1:]:
        current = page.read_text() if page.exists() else None
        if current is None or not (same or str.__eq__)(current, text):
            print(f"{command.split()[0].rsplit('/', 1)[-1]}: {name} is out of date ({why}): run {command}",
                  file=sys.stderr)
            return 1
        return 0
    page.write_text(text)
    print(f"wrote {name}")
    return 0
