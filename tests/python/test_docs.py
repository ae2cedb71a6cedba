"""Every ```python example of the README and of docs/guide/python.md runs, from the
source folder, as a reader would paste it (docs.examples runs the sh examples)."""
import re

import pytest

from conftest import SOURCE

PAGES = [SOURCE / "README.md", SOURCE / "docs" / "guide" / "python.md"]
BLOCK = re.compile(r"^```python\n(.*?)^```$", re.S | re.M)
EXAMPLES = [(page, match.group(1)) for page in PAGES for match in BLOCK.finditer(page.read_text())]


def test_there_are_examples():
    assert {page for page, _ in EXAMPLES} == set(PAGES)


@pytest.mark.parametrize("page, code", EXAMPLES,
                         ids=[f"{page.name}-{i}" for i, (page, _) in enumerate(EXAMPLES)])
def test_example_runs(page, code, monkeypatch):
    monkeypatch.chdir(SOURCE)
    exec(compile(code, str(page), "exec"), {"__name__": "__example__"})
