"""index.html of a sweep (src/sweep/index_page.cpp) at 2 x 10^4 rows (ctest's size; 10^5 with
PITA_TEST_SIZE=large, the size docs/reference/sweep.md quotes; 2000 with PITA_TEST_SIZE=small), in headless Chromium opened from
the disk (file://), as a person uses it: the first page shows 100 rows and the table never holds
more than a page; sorting by a metric, descending, shows the rows in the order an independent sort
of manifest.csv gives (Python's, here), failed rows (no metric) last; the last page, a page typed in,
500 rows a page, and an address with #sort=...&page=... give their rows; a sort asked for while
another is loading wins over it. Prints how long the
page took to load and to sort. Run by ctest sweep.index_browser (tests/CMakeLists.txt)."""
import csv
import json
import os
import pathlib
import subprocess
import sys
import tempfile
import time

SOURCE = pathlib.Path(os.environ.get("PITA_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(SOURCE / "tests" / "serve"))
from serve_session import PITA, Browser, eventually  # noqa: E402

SCENE = SOURCE / "tests" / "sweep" / "data" / "three-arrows.json"
# 200 x 100 = 2 x 10^4 variants, 200 pages of 100 rows in 20 rows files of 1000 (small: 20 x 100,
# 2 rows files; large: 1000 x 100 = 10^5); a fifth have m <= 0 and fail. The page loads the same
# files in the same way at every size; the sweep of 10^5 variants alone took 2 to 4 minutes of
# CI's two cores.
STEPS = {"small": 20, "large": 1000}.get(os.environ.get("PITA_TEST_SIZE", ""), 200)
ROWS = STEPS * 100
VARY = ["--vary", f"/keyframes/1/t=0.05:0.95:{STEPS}", "--vary", "/keyframes/1/m=-0.5:2:100"]


def expected_order(rows, column, descending):
    """Row indices sorted as the page must: numbers by value, empty last in both orders, ties by index."""
    def key(row):
        text = row[column]
        if text == "":
            return (1, 0.0, int(row["index"]))
        value = float(text)
        return (0, -value if descending else value, int(row["index"]))
    return [row["index"] for row in sorted(rows, key=key)]


def shown(browser):
    return browser.evaluate("Array.from(document.querySelectorAll('#rows tr')).map(tr => tr.dataset.index)")


def wait_shown(browser, state):
    """Until the page has shown `state` (its address after the #), and is not loading."""
    return eventually(lambda: browser.evaluate(
        f"!!document.body && document.body.dataset.shown === {json.dumps(state)} && !document.body.dataset.busy"), 120,
        what=lambda: browser.evaluate("JSON.stringify([document.body && document.body.dataset.shown, "
                                      "document.getElementById('status').textContent])"))


def main():
    with tempfile.TemporaryDirectory() as folder:
        folder = pathlib.Path(folder)
        started = time.monotonic()
        run = subprocess.run([PITA, "sweep", str(SCENE), *VARY, "--format", "metrics", "-o", "big", "-q"],
                             cwd=folder, capture_output=True, text=True)
        assert run.returncode == 1, run.stderr[-2000:]  # exit 1: some variants failed, as intended
        print(f"the sweep of {ROWS} variants: {time.monotonic() - started:.1f} s")
        with open(folder / "big" / "manifest.csv", newline="") as f:
            rows = list(csv.DictReader(f))
        assert len(rows) == ROWS, len(rows)
        assert sum(r["status"] != "ok" for r in rows) == ROWS // 5
        page = (folder / "big" / "index.html").as_uri()
        browser = Browser()
        try:
            started = time.monotonic()
            browser.open(page)
            wait_shown(browser, "sort=index&order=asc&page=1&rows=100")
            print(f"first page: {time.monotonic() - started:.2f} s")
            assert shown(browser) == [str(i) for i in range(100)], shown(browser)[:5]
            assert browser.evaluate("document.getElementById('pages').textContent").startswith(f"of {ROWS // 100} ")
            # A failed row says why, a good one has its numbers as manifest.csv prints them.
            texts = browser.evaluate("Array.from(document.querySelectorAll('#rows tr')[25].cells).map(c => c.textContent)")
            assert texts[0] == "#25" and texts[1] == rows[25]["/keyframes/1/t"], texts
            assert rows[25]["discrepancy_max"] in texts, (texts, rows[25])
            assert "magnitude must be > 0" in browser.evaluate(
                "document.querySelectorAll('#rows tr.failed')[0].textContent")

            # Sort by a metric, largest first, with the controls; asked for right after another
            # sort (by path_length_q), before that one is done: the later one wins.
            started = time.monotonic()
            browser.evaluate("(() => { const s = document.getElementById('sort'); "
                             "const pick = name => Array.from(s.options).find(o => o.textContent === name).value; "
                             "s.value = pick('path_length_q'); s.dispatchEvent(new Event('change')); "
                             "s.value = pick('discrepancy_max'); "
                             "document.getElementById('order').value = 'desc'; "
                             "s.dispatchEvent(new Event('change')); })()")
            wait_shown(browser, "sort=discrepancy_max&order=desc&page=1&rows=100")
            print(f"sorting {ROWS} rows by discrepancy_max: {time.monotonic() - started:.2f} s")
            want = expected_order(rows, "discrepancy_max", True)
            assert shown(browser) == want[:100], (shown(browser)[:5], want[:5])
            assert browser.evaluate("document.querySelectorAll('tr').length") <= 101  # a page and the heading

            # The last page: failed rows, without the metric, come last.
            browser.evaluate("document.getElementById('last').click()")
            wait_shown(browser, f"sort=discrepancy_max&order=desc&page={ROWS // 100}&rows=100")
            assert shown(browser) == want[-100:], (shown(browser)[:5], want[-100:][:5])
            assert browser.evaluate("document.querySelectorAll('#rows tr.failed').length") == 100

            # A page typed in, 500 rows a page, ascending by clicking the heading twice... once.
            typed = min(77, ROWS // 100 - 3)
            browser.evaluate("(() => { const p = document.getElementById('page'); p.value = %d; "
                             "p.dispatchEvent(new Event('change')); })()" % typed)
            wait_shown(browser, f"sort=discrepancy_max&order=desc&page={typed}&rows=100")
            assert shown(browser) == want[(typed - 1) * 100:typed * 100]
            # A page box emptied by hand: the first page, not an empty table.
            browser.evaluate("(() => { const p = document.getElementById('page'); p.value = ''; "
                             "p.dispatchEvent(new Event('change')); })()")
            wait_shown(browser, "sort=discrepancy_max&order=desc&page=1&rows=100")
            assert shown(browser) == want[:100]
            browser.evaluate("(() => { const s = document.getElementById('size'); s.value = '500'; "
                             "s.dispatchEvent(new Event('change')); })()")
            wait_shown(browser, "sort=discrepancy_max&order=desc&page=1&rows=500")
            assert shown(browser) == want[:500]
            browser.evaluate("Array.from(document.querySelectorAll('th')).find(h => h.textContent === "
                             "'/keyframes/1/m').click()")
            wait_shown(browser, "sort=%2Fkeyframes%2F1%2Fm&order=asc&page=1&rows=500")
            assert shown(browser) == expected_order(rows, "/keyframes/1/m", False)[:500]

            # An address names the sort and the page: opened anew, the page shows them.
            browser.open(page + "#sort=path_length_p&order=asc&page=3&rows=50")
            wait_shown(browser, "sort=path_length_p&order=asc&page=3&rows=50")
            assert shown(browser) == expected_order(rows, "path_length_p", False)[100:150]
            heap = browser.evaluate("performance.memory ? performance.memory.usedJSHeapSize : 0")
            print(f"the page's JavaScript heap after sorting: {heap / 2**20:.0f} MB")
        finally:
            browser.close()
    print(f"ok: index.html pages and sorts {ROWS} rows in Chromium")


if __name__ == "__main__":
    main()
