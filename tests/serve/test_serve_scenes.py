"""Play in the page of `pita serve`, measured on every scene of scenes/ at once, as a person
plays them: each scene's figure focused, Space pressed, the frames shown over half a second counted,
Space again. Every scene must play from the animated SVG the server makes once per save (no
request to the server while it plays) at a third of its timeline's frames per second or more.
That bound is loose on purpose: ctest runs this beside builds and other browsers on two cores,
where a quiet machine's 30 frames a second became 14; what it catches is play that waits on the
server or on a frame's drawing (0.5 to 1.2 frames a second before the animated SVG and the
layers drawn once). Prints the rate of each scene and the slowest; docs/reference/serve.md quotes
a quiet run's.
Run by ctest serve.browser.scenes (tests/CMakeLists.txt)."""
import os
import pathlib
import shutil
import sys
import tempfile
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from serve_session import Browser, Served, eventually, figures_asked_since, play  # noqa: E402

SOURCE = pathlib.Path(os.environ.get("PITA_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
PLAYED = 0.5  # seconds of play per scene


def ready(browser, i, name):
    """Scene i's figure is shown, nothing is on its way, and its animated SVG has come (or it has
    no timeline); fails at once when the server refused to make the animated SVG."""
    refused = browser.evaluate(f"typeof views !== 'undefined' && views.get({i}) && views.get({i}).animationRefused")
    if refused:
        raise AssertionError(f"{name}: no animated SVG: {refused}")
    return browser.evaluate(f"""(() => {{ const v = typeof views !== 'undefined' && views.get({i});
        return !!v && v.version >= 0 && v.shown !== null && !v.fetching &&
               (v.timeline === null || v.animation !== null); }})()""")


def main():
    names = sorted(p.stem for p in (SOURCE / "scenes").glob("*.json"))
    root = pathlib.Path(tempfile.mkdtemp(prefix="pita-serve-scenes-"))
    shutil.copytree(SOURCE / "scenes" / "images", root / "images")
    for name in names:
        shutil.copy(SOURCE / "scenes" / f"{name}.json", root / f"{name}.json")
    browser = Browser()
    served = Served(root, [f"{name}.json" for name in names])
    rates, failures = [], []
    try:
        started = time.monotonic()
        browser.open(served.url)
        for i, name in enumerate(names):
            eventually(lambda: ready(browser, i, name), 300, what=f"{name}: its figure and animated SVG")
        print(f"{len(names)} scenes and their animated SVGs in the page: {time.monotonic() - started:.1f} s")
        for i, name in enumerate(names):
            if browser.evaluate(f"views.get({i}).timeline === null"):
                print(f"{name}: a figure without a timeline (nothing moves in it)")
                continue
            shown, fps, since = play(browser, i, PLAYED)
            asked = figures_asked_since(browser, since)
            rates.append((shown / fps, shown, fps, name))
            print(f"play in the page, {name}: {shown:.1f} frames shown a second (the timeline's fps: {fps:g})")
            if asked:
                failures.append(f"{name}: play asked the server for frames: {asked[:2]}")
            if shown < fps / 3:
                failures.append(f"{name}: {shown:.1f} frames a second, of {fps:g}")
    finally:
        served.stop()
        browser.close()
        shutil.rmtree(root, ignore_errors=True)
    if rates:
        slowest = min(rates)
        print(f"the slowest: {slowest[3]}, {slowest[1]:.1f} frames a second of {slowest[2]:g}; "
              f"{sum(r[0] >= 0.95 for r in rates)} of {len(rates)} scenes at 95 % of their fps or more")
    if failures:
        raise AssertionError("\n".join(failures))
    print(f"ok: {len(rates)} scenes play in the page from their animated SVG")


if __name__ == "__main__":
    main()
