"""Every ```python example of the README and of docs/guide/python.md runs as a reader would
paste it: from a folder of their own (a scratch folder, outside the clone), holding the files
the page's shell examples wrote before it (the tour's `cat > three.json <<'EOF'`), and writing
nothing into the clone (docs.examples runs the sh examples)."""
import re

import pytest

from conftest import SOURCE

PAGES = [SOURCE / "README.md", SOURCE / "docs" / "guide" / "python.md"]
BLOCK = re.compile(r"^```python\n(.*?)^```$", re.S | re.M)
SH_BLOCK = re.compile(r"^```sh\n(.*?)^```$", re.S | re.M)
HERE_DOCUMENT = re.compile(r"^cat > (\S+) <<'(\w+)'\n(.*?\n)\2$", re.S | re.M)
EXAMPLES = [(page, match.group(1), match.start()) for page in PAGES for match in BLOCK.finditer(page.read_text())]


def written_before(page, offset):
    """{name: text} of the files the page's sh examples before `offset` write with a here-document."""
    text = page.read_text()[:offset]
    return {m.group(1): m.group(3) for block in SH_BLOCK.finditer(text) for m in HERE_DOCUMENT.finditer(block.group(1))}


def test_there_are_examples():
    assert {page for page, _, _ in EXAMPLES} == set(PAGES)


def files_of_the_clone():
    """The clone's top level and the folders pita.example and the examples reach."""
    return ({path.name for path in SOURCE.iterdir()}
            | {path.relative_to(SOURCE) for folder in ("scenes", "examples") for path in (SOURCE / folder).rglob("*")})


@pytest.mark.parametrize("page, code, offset", EXAMPLES,
                         ids=[f"{page.name}-{i}" for i, (page, _, _) in enumerate(EXAMPLES)])
def test_example_runs_from_a_folder_of_ones_own(page, code, offset, tmp_path, monkeypatch):
    for name, text in written_before(page, offset).items():
        (tmp_path / name).write_text(text)
    monkeypatch.chdir(tmp_path)
    before = files_of_the_clone()
    exec(compile(code, str(page), "exec"), {"__name__": "__example__"})
    assert files_of_the_clone() == before
