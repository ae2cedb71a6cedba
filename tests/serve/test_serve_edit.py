"""pita serve --edit in Chromium, with real mouse and keyboard events as a person edits: a drag
shows the changed figure while the button is held and the handle stays under the pointer (the
view held, "fit" refits it); the file diffed after release; Ctrl+Z, Ctrl+Shift+Z and Ctrl+Y undo
and redo byte for byte; arrow keys nudge the selected handle; the timeline's markers edit "t",
and one dragged past its neighbour is refused with the reason. Prints the drag-to-figure latency
docs/reference/serve.md quotes. Run by ctest serve.browser.edit (tests/CMakeLists.txt)."""
import json
import os
import pathlib
import shutil
import statistics
import sys
import tempfile
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from serve_session import Browser, Served, eventually  # noqa: E402

SOURCE = pathlib.Path(os.environ.get("PITA_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
FIG03 = (SOURCE / "scenes" / "fig03-steady-morph.json").read_text()
FIGURE = "document.querySelector('#scene-0 .figure svg')"


def check(condition, message):
    if not condition:
        raise AssertionError(message)


def centre(browser, selector):
    """The centre of the element `selector` in CSS pixels of the viewport, or None."""
    return browser.evaluate(f"""(() => {{ const e = document.querySelector({json.dumps(selector)});
        if (!e) return null; const r = e.getBoundingClientRect(); return [r.x + r.width / 2, r.y + r.height / 2]; }})()""")


def mouse(browser, kind, x, y, held=False):
    extra = {"button": "left", "clickCount": 1} if kind != "mouseMoved" else ({"button": "left", "buttons": 1} if held else {})
    browser.call("Input.dispatchMouseEvent", type=kind, x=x, y=y, **extra)


def scroll_to(browser, selector):
    """Scrolls the page so that `selector` is in the middle of the window (as a person scrolls to it)."""
    browser.evaluate(f"document.querySelector({json.dumps(selector)}).scrollIntoView({{block: 'center'}})")


def in_figure(browser, selector):
    """The centre of `selector` from the top left corner of scene 0's figure, in CSS pixels."""
    at, corner = centre(browser, selector), centre(browser, "#scene-0 .figure")
    size = browser.evaluate("(() => { const r = document.querySelector('#scene-0 .figure').getBoundingClientRect();"
                            " return [r.width, r.height]; })()")
    return at and [at[0] - corner[0] + size[0] / 2, at[1] - corner[1] + size[1] / 2]


def click(browser, selector):
    scroll_to(browser, selector)
    x, y = centre(browser, selector)
    mouse(browser, "mouseMoved", x, y)
    mouse(browser, "mousePressed", x, y)
    mouse(browser, "mouseReleased", x, y)


# Keys as the keyboard sends them: (key, code, Windows virtual key code).
KEYS = {"z": ("z", "KeyZ", 90), "Z": ("Z", "KeyZ", 90), "y": ("y", "KeyY", 89), "ArrowRight": ("ArrowRight", "ArrowRight", 39),
        "Escape": ("Escape", "Escape", 27)}
CTRL, SHIFT = 2, 8


def press(browser, name, modifiers=0):
    key, code, vk = KEYS[name]
    for kind in ("rawKeyDown", "keyUp"):
        browser.call("Input.dispatchKeyEvent", type=kind, key=key, code=code, windowsVirtualKeyCode=vk,
                     nativeVirtualKeyCode=vk, modifiers=modifiers)


def changes(browser):
    """How many figures scene 0 has shown (the page counts each one it puts in place)."""
    return browser.evaluate("views.get(0).changes")


def serve_fig03(folder, browser):
    (folder / "s.json").write_text(FIG03)
    served = Served(folder, ["s.json"], "--edit")
    browser.open(served.url)
    eventually(lambda: centre(browser, TAIL1) is not None, 60, what="the handles drawn")
    return served


def page_ready(browser, served, version_before=None):
    """The page shows the server's latest version of scene 0, with its handles."""
    def shown():
        status, body = served.get("/api/scenes")
        version = json.loads(body)[0]["version"]
        return (browser.evaluate("document.querySelector('#scene-0').dataset.version") == str(version)
                and (version_before is None or version != version_before)
                and browser.evaluate("document.querySelectorAll('#scene-0 circle.handle').length") > 0
                and browser.evaluate("views.get(0).fetching") is None and version)
    return eventually(shown, 60, what="the page at the server's version")


def version(served):
    return json.loads(served.get("/api/scenes")[1])[0]["version"]


TAIL1 = "#scene-0 circle.handle.tail[data-pointer='/keyframes/1']"


def test_a_drag_is_seen_live_and_undone_from_the_keyboard(folder, browser, latencies, in_page):
    served = serve_fig03(folder, browser)
    try:
        before_figure = browser.evaluate(f"{FIGURE}.outerHTML")
        x, y = centre(browser, TAIL1)
        mouse(browser, "mouseMoved", x, y)
        mouse(browser, "mousePressed", x, y)
        # Outward (right and down): the content grows, so a refitted figure would move the handle.
        steps = 8
        dx, dy = 64.0, 48.0
        for k in range(1, steps + 1):
            shown = changes(browser)
            started = time.monotonic()
            mouse(browser, "mouseMoved", x + dx * k / steps, y + dy * k / steps, held=True)
            # Each move waits for the figure it asks for: its latency, pointer move to figure shown.
            eventually(lambda: changes(browser) > shown, 30, step=0.002, what="a preview shown while dragging")
            latencies.append(time.monotonic() - started)
            check(browser.evaluate("document.querySelector('#scene-0 .refused.shown') === null"),
                  "no refusal while dragging: " + str(browser.evaluate("views.get(0).refused.textContent")))
        in_page.extend(browser.evaluate("window.pitaPreviewLatencies || []"))
        held_figure = browser.evaluate(f"{FIGURE}.outerHTML")
        check(held_figure != before_figure, "the figure changed while the button is held")
        check(FIG03 == (folder / "s.json").read_text(), "nothing written before release")
        under = centre(browser, TAIL1)
        check(abs(under[0] - (x + dx)) < 2 and abs(under[1] - (y + dy)) < 2, f"the handle under the pointer: {under}")
        old = version(served)
        mouse(browser, "mouseReleased", x + dx, y + dy)
        edited = eventually(lambda: (folder / "s.json").read_text() != FIG03 and (folder / "s.json").read_text(), 60)
        page_ready(browser, served, old)
        # The figure drawn from the file, in the view held: the handle where it was dropped.
        after = centre(browser, TAIL1)
        check(abs(after[0] - (x + dx)) < 2 and abs(after[1] - (y + dy)) < 2,
              f"the handle stays where it was dropped: {after} against {(x + dx, y + dy)}")
        # One value changed, every other byte kept.
        value = json.loads(edited)["keyframes"][1]["p"]
        check(value[0] > 4 and value[1] < 1, f"the tail moved right and down: {value}")
        start = FIG03.index('"p": [4, 1]') + len('"p": ')
        check(edited[:start] == FIG03[:start] and edited[edited.index("]", start) + 1:] == FIG03[start + len("[4, 1]"):],
              f"only p changed: {edited[start - 10:start + 40]}")
        check(all(len(str(c).split(".")[-1]) <= 4 for c in value), f"short numbers: {value}")

        # The keyboard: Ctrl+Z undoes, Ctrl+Shift+Z and Ctrl+Y redo, each byte for byte.
        check(browser.evaluate("document.activeElement === document.querySelector('#scene-0 .figure')"),
              "the figure has the focus after the drag")
        for keys, text in (((("z", CTRL),), FIG03), ((("Z", CTRL | SHIFT),), edited), ((("z", CTRL),), FIG03),
                           ((("y", CTRL),), edited)):
            for name, modifiers in keys:
                press(browser, name, modifiers)
            eventually(lambda: (folder / "s.json").read_text() == text, 30,
                       what=lambda: f"the file after {keys}: {(folder / 's.json').read_text()[200:500]}; the page: " +
                       browser.evaluate("JSON.stringify({undo: views.get(0).undo, redo: views.get(0).redo, "
                                        "refused: views.get(0).refused.textContent})") + served.stderr()[-600:])
        page_ready(browser, served)
        # "fit": out of the view held, the figure fitted to its content again: the handle moves.
        held = in_figure(browser, TAIL1)
        click(browser, "#scene-0 button.fit")
        eventually(lambda: browser.evaluate("views.get(0).held") is None, 30,
                   what=lambda: browser.evaluate("""JSON.stringify([document.querySelector('#scene-0 button.fit')
                       .getBoundingClientRect(), innerHeight, scrollY])"""))
        eventually(lambda: (lambda c: c and abs(c[0] - held[0]) + abs(c[1] - held[1]) > 2)(in_figure(browser, TAIL1)), 30,
                   what=lambda: f"the handle refitted: {in_figure(browser, TAIL1)} against {held}")
        press(browser, "z", CTRL)
        eventually(lambda: (folder / "s.json").read_text() == FIG03, 30)
        # The log line of an edit follows its write: awaited.
        eventually(lambda: served.stderr().count("edited /keyframes/1/p") == 6, 30,
                   what=lambda: f"one log line per edit, none for previews: {served.stderr()}")
    finally:
        served.stop()


def test_arrow_keys_nudge_the_selected_handle(folder, browser):
    served = serve_fig03(folder, browser)
    try:
        # The canvas pixels of a world unit: the two tails are p = (0, 0) and (4, 1).
        tail0 = browser.evaluate("views.get(0).handles.find(h => h.pointer === '/keyframes/0' && h.part === 'tail').at")
        tail1 = browser.evaluate("views.get(0).handles.find(h => h.pointer === '/keyframes/1' && h.part === 'tail').at")
        scale = (tail1[0] - tail0[0]) / 4.0
        click(browser, TAIL1)
        check(browser.evaluate(f"document.querySelector({json.dumps(TAIL1)}).classList.contains('selected')"),
              "a click selects the handle")
        check(FIG03 == (folder / "s.json").read_text(), "a click writes nothing")
        old = version(served)
        press(browser, "ArrowRight")
        edited = eventually(lambda: (folder / "s.json").read_text() != FIG03 and (folder / "s.json").read_text(), 30)
        x, y = json.loads(edited)["keyframes"][1]["p"]
        check(abs((x - 4) * scale - 1) < 0.15 and y == 1, f"one canvas pixel to the right: p = {[x, y]} at {scale} px/unit")
        page_ready(browser, served, old)
        old = version(served)
        press(browser, "ArrowRight", SHIFT)
        edited = eventually(lambda: (lambda t: t != edited and t)((folder / "s.json").read_text()), 30)
        x, y = json.loads(edited)["keyframes"][1]["p"]
        check(abs((x - 4) * scale - 11) < 0.15, f"then ten more with Shift: p = {[x, y]}")
        page_ready(browser, served, old)
        # Escape deselects: the arrows step the slider's frames again, and the file stays.
        press(browser, "Escape")
        check(browser.evaluate("document.querySelectorAll('#scene-0 circle.handle.selected').length") == 0, "deselected")
        press(browser, "ArrowRight")
        eventually(lambda: browser.evaluate("views.get(0).k") == 1, 30, what="a frame stepped")
        time.sleep(0.3)
        check((folder / "s.json").read_text() == edited, "no nudge without a selection")
    finally:
        served.stop()


def test_a_refused_drag_says_why_while_held(folder, browser):
    """A drag the scene would refuse (a tip dropped on its tail: a magnitude of 0) says why while the
    button is held, over a figure that does not move; on release the file stays as it was."""
    served = serve_fig03(folder, browser)
    try:
        tip = "#scene-0 circle.handle.tip[data-pointer='/keyframes/0']"
        tail = "#scene-0 circle.handle.tail[data-pointer='/keyframes/0']"
        eventually(lambda: centre(browser, tip) is not None, 30)
        before = browser.evaluate(f"{FIGURE}.outerHTML")
        top = browser.evaluate("document.querySelector('#scene-0 .figure').getBoundingClientRect().top")
        (x, y), (tx, ty) = centre(browser, tip), centre(browser, tail)
        mouse(browser, "mouseMoved", x, y)
        mouse(browser, "mousePressed", x, y)
        for k in range(1, 6):
            mouse(browser, "mouseMoved", x + (tx - x) * k / 5, y + (ty - y) * k / 5, held=True)
        refused = eventually(lambda: browser.evaluate(
            "document.querySelector('#scene-0 .refused.shown') && document.querySelector('#scene-0 .refused').textContent"),
            30, what="the refusal shown while the button is held")
        check("/keyframes/0/m" in refused and "magnitude" in refused, f"the reason: {refused}")
        check(browser.evaluate("document.querySelector('#scene-0 .figure').getBoundingClientRect().top") == top,
              "the banner does not move the figure")
        # The last figure shown is a good one: the previews before the tail was reached, or the first.
        check(browser.evaluate(f"{FIGURE}.outerHTML") != "" and (folder / "s.json").read_text() == FIG03, "nothing written")
        mouse(browser, "mouseReleased", tx, ty)
        eventually(lambda: "edit refused: /keyframes/0/m" in served.stderr(), 30, what=lambda: served.stderr())
        check((folder / "s.json").read_text() == FIG03, "a refused drag leaves the file")
        check(before != "", "a figure was shown")
    finally:
        served.stop()


def marker(pointer):
    return f"#scene-0 .timeline .marker[data-pointer='{pointer}']"


def test_the_timeline_edits_times(folder, browser):
    served = serve_fig03(folder, browser)
    try:
        eventually(lambda: browser.evaluate("document.querySelectorAll('#scene-0 .timeline .marker').length") == 2, 30)
        label = browser.evaluate(f"document.querySelector({json.dumps(marker('/keyframes/1'))}).textContent")
        check(label == "1: t=1", f"the marker's label: {label}")
        # Keyframe 1 (t = 1) dragged a quarter of the strip to the left.
        scroll_to(browser, "#scene-0 .timeline")
        track = browser.evaluate("""(() => { const r = document.querySelector('#scene-0 .timeline-track')
            .getBoundingClientRect(); return [r.x, r.width]; })()""")
        x, y = centre(browser, marker("/keyframes/1"))
        mouse(browser, "mouseMoved", x, y)
        mouse(browser, "mousePressed", x, y)
        for k in range(1, 6):
            mouse(browser, "mouseMoved", x - track[1] / 4 * k / 5, y, held=True)
        mouse(browser, "mouseReleased", x - track[1] / 4, y)
        edited = eventually(lambda: (folder / "s.json").read_text() != FIG03 and (folder / "s.json").read_text(), 30)
        t = json.loads(edited)["keyframes"][1]["t"]
        check(0.6 < t < 0.8 and len(str(t)) <= 5, f"t moved to about 0.73, written short: {t}")
        start = FIG03.index('{"t": 1,') + len('{"t": ')
        check(edited[:start] == FIG03[:start] and edited[start + len(str(t)):] == FIG03[start + 1:],
              f"only t changed: {edited[start - 10:start + 30]}")
        page_ready(browser, served)
        # The timeline drawn again from the file (the title is written only then).
        eventually(lambda: browser.evaluate(
            f"document.querySelector({json.dumps(marker('/keyframes/1'))}).title").startswith(f"/keyframes/1: t = {t} "), 30)
        check(browser.evaluate(f"document.querySelector({json.dumps(marker('/keyframes/1'))}).textContent") == f"1: t={t}",
              "the marker labelled with its new time")
        # Keyframe 0 dragged past keyframe 1: refused, with the reason, and the file kept.
        x0, y0 = centre(browser, marker("/keyframes/0"))
        x1, _ = centre(browser, marker("/keyframes/1"))
        mouse(browser, "mouseMoved", x0, y0)
        mouse(browser, "mousePressed", x0, y0)
        for k in range(1, 6):
            mouse(browser, "mouseMoved", x0 + (x1 + 20 - x0) * k / 5, y0, held=True)
        mouse(browser, "mouseReleased", x1 + 20, y0)
        refused = eventually(lambda: browser.evaluate(
            "document.querySelector('#scene-0 .refused.shown') && document.querySelector('#scene-0 .refused').textContent"), 30,
            what=lambda: served.stderr()[-500:] + browser.evaluate("JSON.stringify([views.get(0).keys, views.get(0).undo])"))
        check("/keyframes/1/t" in refused and "increasing" in refused, f"the reason: {refused}")
        check((folder / "s.json").read_text() == edited, "a refused time leaves the file")
        back = centre(browser, marker("/keyframes/0"))
        check(abs(back[0] - x0) < 1, f"the marker back where the file has it: {back[0]} against {x0}")
        # Ctrl+Z undoes a time too (the focus on no figure: the scene edited last).
        press(browser, "z", CTRL)
        eventually(lambda: (folder / "s.json").read_text() == FIG03, 30)
    finally:
        served.stop()


def measure_drag_latency(folder, browser, name, results, moves=6):
    """Drag to figure for scenes/NAME.json: the first tail dragged in `moves` steps, each waited for."""
    (folder / "s.json").write_text((SOURCE / "scenes" / f"{name}.json").read_text())
    served = Served(folder, ["s.json"], "--edit")
    try:
        browser.open(served.url)
        tail = "#scene-0 circle.handle.tail"
        eventually(lambda: centre(browser, tail) is not None, 60, what="the handles drawn")
        x, y = centre(browser, tail)
        mouse(browser, "mouseMoved", x, y)
        mouse(browser, "mousePressed", x, y)
        for k in range(1, moves + 1):
            shown = changes(browser)
            mouse(browser, "mouseMoved", x + 3 * k, y + 2 * k, held=True)
            eventually(lambda: changes(browser) > shown, 30, step=0.002, what="a preview shown while dragging")
        results.append((name, browser.evaluate("window.pitaPreviewLatencies")))
        mouse(browser, "mouseReleased", x + 3 * moves, y + 2 * moves)
        eventually(lambda: (folder / "s.json").read_text() != (SOURCE / "scenes" / f"{name}.json").read_text(), 30)
    finally:
        served.stop()


def main():
    latencies, in_page = [], []
    root = pathlib.Path(tempfile.mkdtemp(prefix="pita-serve-edit-test-"))
    browser = Browser()
    try:
        for test in (test_a_drag_is_seen_live_and_undone_from_the_keyboard, test_arrow_keys_nudge_the_selected_handle,
                     test_a_refused_drag_says_why_while_held, test_the_timeline_edits_times):
            folder = root / test.__name__
            folder.mkdir()
            started = time.monotonic()
            if test is test_a_drag_is_seen_live_and_undone_from_the_keyboard:
                test(folder, browser, latencies, in_page)
            else:
                test(folder, browser)
            print(f"ok {test.__name__} ({time.monotonic() - started:.1f} s)")
        others = []
        for name in ("fig01-eight-pitas",):
            folder = root / f"latency-{name}"
            folder.mkdir()
            measure_drag_latency(folder, browser, name, others)
    finally:
        browser.close()
        shutil.rmtree(root, ignore_errors=True)
    # Two clocks: the page's own (the pointer event to the next frame drawn with the new figure), and this
    # test's (the mouse event sent over the DevTools protocol to the new figure seen by polling the page).
    print(f"drag to figure in the page, fig03-steady-morph: median {statistics.median(in_page):.0f} ms in the page "
          f"(pointer move to the frame drawn; min {min(in_page):.0f}, max {max(in_page):.0f}, {len(in_page)} previews); "
          f"median {statistics.median(latencies) * 1000:.0f} ms from the test's mouse event to the figure seen "
          f"(min {min(latencies) * 1000:.0f}, max {max(latencies) * 1000:.0f}, {len(latencies)} moves)")
    for name, measured in others:
        print(f"drag to figure in the page, {name}: median {statistics.median(measured):.0f} ms in the page "
              f"(min {min(measured):.0f}, max {max(measured):.0f}, {len(measured)} previews)")


if __name__ == "__main__":
    main()
