"""The report of `pita check --report` (src/golden/report.cpp) in headless Chromium, opened from the
disk as a person opens it: for scenes named like URL schemes ("javascript:...json", a "data:" name),
every link and image of the page is a file beside it (Chromium resolves each href and src: none is a
javascript: or data: URL, whose click would run or show what the name says), and every image loads.
Run by ctest golden.report_browser (tests/CMakeLists.txt)."""
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile

SOURCE = pathlib.Path(os.environ.get("PITA_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(SOURCE / "tests" / "serve"))
from serve_session import PITA, Browser, eventually  # noqa: E402

NAMES = ["javascript:document.title='ran'", "data:text,x"]


def main():
    with tempfile.TemporaryDirectory() as folder:
        folder = pathlib.Path(folder)
        scene = json.loads((SOURCE / "scenes" / "fig03-steady-morph.json").read_text())
        for name in NAMES:
            (folder / f"{name}.json").write_text(json.dumps(scene))
        # Goldens of the scene moved a little, so that each scene differs and its images are written.
        (folder / "golden").mkdir()
        subprocess.run([PITA, "update-goldens", *[f"{n}.json" for n in NAMES], "--golden", "golden"],
                       cwd=folder, check=True, capture_output=True)
        scene["keyframes"][1]["p"][0] += 0.5
        for name in NAMES:
            (folder / f"{name}.json").write_text(json.dumps(scene))
        run = subprocess.run([PITA, "check", *[f"{n}.json" for n in NAMES], "--golden", "golden", "--report", "report"],
                             cwd=folder, capture_output=True, text=True)
        assert run.returncode == 1, run.stderr[-2000:]
        page = folder / "report" / "index.html"
        browser = Browser()
        try:
            browser.open(page.as_uri())
            eventually(lambda: browser.evaluate("document.readyState") == "complete", 30)
            urls = browser.evaluate("[...document.querySelectorAll('a[href], img[src]')]"
                                    ".map(e => e.href || e.src).filter(u => !u.includes('#'))")
            assert urls, "the report links to its images"
            for url in urls:
                assert url.startswith(page.parent.as_uri() + "/"), f"a link that is not a file beside the page: {url}"
            images = browser.evaluate("[...document.querySelectorAll('img')].map(i => i.naturalWidth)")
            assert images and all(w > 0 for w in images), f"every image loads: {images}"
        finally:
            browser.close()
    print(f"ok: {len(urls)} links and images of the report are files")


if __name__ == "__main__":
    main()
