"""pita serve's 3D camera in the page (src/serve/page/camera.js, src/serve/camera_edit.cpp), as a
person uses it in Chromium with the mouse: a drag on a 3D panel turns the figure, which is what
pita render draws of the scene with that camera written in; one request at a time, the latest
position asked for when the answer comes; the wheel zooms and Shift+drag pans; "Save view" writes
the camera into the file keeping every other byte (adding the members the file lacks, writing
"auto": false where the scene had "auto": true), and undo gives the file back byte for byte; a
scene of the plane does not turn. Prints the time from a pointer move to the turned figure shown
(sam-3d-fig13-polysam), which docs/reference/serve.md quotes. Run by ctest serve.browser.camera
(tests/CMakeLists.txt)."""
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from serve_session import PITA, Browser, Served, eventually  # noqa: E402

SOURCE = pathlib.Path(os.environ.get("PITA_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
FIGURE = "document.querySelector('#scene-0 .figure svg')"


def check(condition, message):
    if not condition:
        raise AssertionError(message)


def figure_text(browser):
    """Scene 0's figure as the page shows it ("" before it came)."""
    return browser.evaluate(f"{FIGURE} ? {FIGURE}.outerHTML : ''")


def settled(browser):
    """The page holds a turned view and shows it: no figure on its way, the one shown of the latest camera."""
    return browser.evaluate("""(() => { const v = views.get(0); return !!v.turned && !v.fetching &&
        v.shownTurn === turnKey(v.turned); })()""")


def turned(browser):
    return browser.evaluate("views.get(0).turned && [views.get(0).turned.azimuth, views.get(0).turned.elevation]")


def panel_centre(browser, panel=0):
    """Where panel `panel` of scene 0's figure is on the screen (CSS pixels)."""
    return browser.evaluate(f"""(() => {{ const svg = {FIGURE}; const [x, y, w, h] = views.get(0).panels[{panel}];
        const p = svg.createSVGPoint(); p.x = x + w / 2; p.y = y + h / 2;
        const q = p.matrixTransform(svg.getScreenCTM()); return [q.x, q.y]; }})()""")


def mouse(browser, kind, x, y, modifiers=0, buttons=1):
    extra = {"button": "left", "clickCount": 1} if kind != "mouseMoved" else {"button": "left", "buttons": buttons}
    browser.call("Input.dispatchMouseEvent", type=kind, x=x, y=y, modifiers=modifiers, **extra)


def drag(browser, x, y, dx, dy, steps=5, modifiers=0):
    """A drag with the left button from (x, y) by (dx, dy), in `steps` moves."""
    browser.call("Input.dispatchMouseEvent", type="mouseMoved", x=x, y=y)
    mouse(browser, "mousePressed", x, y, modifiers)
    for step in range(1, steps + 1):
        mouse(browser, "mouseMoved", x + dx * step / steps, y + dy * step / steps, modifiers)
    mouse(browser, "mouseReleased", x + dx, y + dy, modifiers)


def click(browser, selector):
    """A click of the mouse at the middle of the element."""
    x, y = browser.evaluate(f"""(() => {{ const e = document.querySelector({json.dumps(selector)});
        e.scrollIntoView({{block: "center"}}); const r = e.getBoundingClientRect();
        return [r.x + r.width / 2, r.y + r.height / 2]; }})()""")
    browser.call("Input.dispatchMouseEvent", type="mouseMoved", x=x, y=y)
    mouse(browser, "mousePressed", x, y)
    mouse(browser, "mouseReleased", x, y)


def rendered(folder, text, *extra):
    """The bytes `pita render [EXTRA...]` writes of the scene `text`."""
    (folder / ".r.json").write_text(text)
    subprocess.run([PITA, "render", ".r.json", *extra, "-o", ".r.svg"], cwd=folder, check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    svg = (folder / ".r.svg").read_text()
    (folder / ".r.json").unlink()
    (folder / ".r.svg").unlink()
    return svg


def with_camera(text, azimuth, elevation):
    """The scene text with its camera's azimuth and elevation given (as a person would write them)."""
    scene = json.loads(text)
    scene["camera"] = dict(scene.get("camera", {}), azimuth=azimuth, elevation=elevation)
    scene["camera"].pop("auto", None)
    return json.dumps(scene, indent=2)


def open_scene(browser, served):
    browser.open(served.url)
    eventually(lambda: browser.evaluate("typeof views !== 'undefined' && views.get(0) && !!views.get(0).camera"
                                        f" && !!{FIGURE}"), 60, what="the 3D figure and its camera")
    # The animated SVG is made in the background after the first figure: waited for, so that the
    # server is not busy with it while turning is measured.
    eventually(lambda: browser.evaluate("views.get(0).animation !== null"), 120, what="the animated SVG")
    browser.evaluate("document.querySelector('#scene-0 .figure').scrollIntoView()")


def test_turning_and_saving(folder, browser):
    """Fig. 12 (a camera with azimuth -65, elevation 32): a drag turns it, the figure is pita
    render's of the file with that camera; wheel zooms, Shift+drag pans; Save view writes the two
    numbers and nothing else; undo gives the file back."""
    text = (SOURCE / "scenes" / "sam-3d-fig12-bezier.json").read_text()
    (folder / "s.json").write_text(text)
    served = Served(folder, ["s.json"], "--edit")
    try:
        open_scene(browser, served)
        before = figure_text(browser)
        shown = browser.evaluate("document.querySelector('#scene-0 .camera').textContent")
        check(shown == "camera: azimuth -65\u00b0, elevation 32\u00b0", f"the camera shown: {shown}")
        check(browser.evaluate("getComputedStyle(document.querySelector('#scene-0 button.save-view')).display")
              == "none", "no Save view before turning")
        x, y = panel_centre(browser)
        drag(browser, x, y, 80, 30)
        eventually(lambda: settled(browser), 60, what=lambda: f"the turned figure: {turned(browser)}")
        # 0.5 degree a pixel: right turns the azimuth down, down raises the camera.
        check(turned(browser) == [-105, 47], f"turned to {turned(browser)}")
        after = figure_text(browser)
        check(after and after != before, "the figure turned")
        shown = browser.evaluate("document.querySelector('#scene-0 .camera').textContent")
        check(shown.startswith("camera: azimuth -105\u00b0, elevation 47\u00b0 (turned"), f"the camera shown: {shown}")
        svg = browser.evaluate("views.get(0).svg")
        check(svg == rendered(folder, with_camera(text, -105, 47)),
              "the turned figure is pita render's of the scene with that camera")
        check((folder / "s.json").read_text() == text, "turning is not an edit")
        # The slider's frames, while the view is held turned, are drawn with the turned camera:
        # render --at's of the scene with that camera written in; "figure" returns to the turned figure.
        browser.evaluate("document.querySelector('#scene-0 .figure').focus()")
        for _ in range(3):
            browser.call("Input.dispatchKeyEvent", type="keyDown", key="ArrowRight", code="ArrowRight",
                         windowsVirtualKeyCode=39)
            browser.call("Input.dispatchKeyEvent", type="keyUp", key="ArrowRight", code="ArrowRight",
                         windowsVirtualKeyCode=39)
        at = eventually(lambda: browser.evaluate("""(() => { const v = views.get(0); return v.t !== null &&
            v.shown === 'frame' && v.shownFrame === 3 && !v.fetching && v.t; })()"""), 60, what="the turned frame")
        check(browser.evaluate("views.get(0).svg") == rendered(folder, with_camera(text, -105, 47), "--at", repr(at)),
              "the turned frame is render --at's of the scene with that camera")
        click(browser, "#scene-0 button.still")
        eventually(lambda: browser.evaluate("views.get(0).t === null && views.get(0).shown === 'still'")
                   and settled(browser), 60, what="the turned figure back")
        check(browser.evaluate("views.get(0).svg") == svg, "the turned figure again")
        browser.evaluate("document.querySelector('#scene-0 .figure').scrollIntoView()")
        x, y = panel_centre(browser)

        # The wheel zooms the figure (the view box); a drag still turns it, and keeps the zoom.
        box = lambda: browser.evaluate(f"{FIGURE}.getAttribute('viewBox')")
        whole = box()
        browser.call("Input.dispatchMouseEvent", type="mouseWheel", x=x, y=y, deltaX=0, deltaY=-100)
        zoomed = eventually(lambda: box() != whole and box(), 10, what="zoomed by the wheel")
        check(float(zoomed.split()[2]) < float(whole.split()[2]), f"zoomed in: {zoomed}")
        drag(browser, x, y, -20, 0)
        eventually(lambda: settled(browser) and turned(browser) == [-95, 47], 60,
                   what=lambda: f"turned again while zoomed: {turned(browser)}")
        check(box() == zoomed, f"a drag on a 3D panel turns, never pans: {zoomed} -> {box()}")
        # Shift+drag pans, and does not turn.
        drag(browser, x, y, 40, 0, modifiers=8)
        check(float(box().split()[0]) < float(zoomed.split()[0]), f"Shift+drag panned: {zoomed} -> {box()}")
        check(turned(browser) == [-95, 47], "Shift+drag did not turn")
        click(browser, "#scene-0 button.fit")

        # Save view: the two numbers written, every other byte as it was.
        click(browser, "#scene-0 button.save-view")
        saved = eventually(lambda: (lambda t: t != text and t)((folder / "s.json").read_text()), 60,
                           what=lambda: "the file saved: " + served.stderr()[-400:])
        expected = text.replace('"azimuth": -65,', '"azimuth": -95,', 1).replace('"elevation": 32,', '"elevation": 47,', 1)
        check(expected != text and saved == expected, f"only the camera's numbers changed:\n{saved[:800]}")
        # The saved file draws what the page showed; the page then shows the file's camera, not a turn.
        eventually(lambda: browser.evaluate("views.get(0).turned === null && !views.get(0).fetching"), 60,
                   what="the turned view dropped once the file has it")
        check(rendered(folder, saved) == browser.evaluate("views.get(0).svg"),
              "the saved file renders as the turned page showed")
        shown = browser.evaluate("document.querySelector('#scene-0 .camera').textContent")
        check(shown == "camera: azimuth -95\u00b0, elevation 47\u00b0", f"the camera shown: {shown}")
        check("edited /camera/" in served.stderr(), served.stderr())
        # Undo: the file back, byte for byte.
        eventually(lambda: browser.evaluate("document.querySelector('#scene-0 button.undo').style.display === ''"), 30)
        click(browser, "#scene-0 button.undo")
        eventually(lambda: (folder / "s.json").read_text() == text, 60, what="the file back after undo")
    finally:
        served.stop()


def test_save_view_adds_what_the_file_lacks(folder, browser):
    """A scene without "camera": Save view adds it, at the end of the scene, every other byte kept;
    undo takes it out again."""
    text = (SOURCE / "scenes" / "sam-3d-fig12-bezier.json").read_text()
    start = text.index('  "camera": {')
    end = text.index("},\n", start) + 3
    bare = text[:start] + text[end:]
    check(json.loads(bare).get("camera") is None, "a scene without a camera")
    (folder / "s.json").write_text(bare)
    served = Served(folder, ["s.json"], "--edit")
    try:
        open_scene(browser, served)
        # A frame of the slider shown (the right arrow): turning goes back to the figure itself.
        browser.evaluate("document.querySelector('#scene-0 .figure').focus()")
        browser.call("Input.dispatchKeyEvent", type="keyDown", key="ArrowRight", code="ArrowRight",
                     windowsVirtualKeyCode=39)
        browser.call("Input.dispatchKeyEvent", type="keyUp", key="ArrowRight", code="ArrowRight",
                     windowsVirtualKeyCode=39)
        check(browser.evaluate("views.get(0).t !== null"), "a frame of the slider shown")
        x, y = panel_centre(browser)
        drag(browser, x, y, -30, -10)
        eventually(lambda: settled(browser), 60, what=lambda: f"the turned figure: {turned(browser)}")
        azimuth, elevation = turned(browser)
        check([azimuth, elevation] == [50, 20], f"from the default camera (35, 25): {[azimuth, elevation]}")
        check(browser.evaluate("views.get(0).t === null && views.get(0).shown === 'still'"), "the figure itself, turned")
        click(browser, "#scene-0 button.save-view")
        saved = eventually(lambda: (lambda t: t != bare and t)((folder / "s.json").read_text()), 60,
                           what=lambda: "the file saved: " + served.stderr()[-400:])
        added = ',\n  "camera": {"azimuth": 50, "elevation": 20}'
        check(saved.count(added) == 1 and saved.replace(added, "", 1) == bare,
              f"the camera added, every other byte kept: {saved[-300:]}")
        eventually(lambda: browser.evaluate("views.get(0).turned === null && !views.get(0).fetching"), 60)
        check(rendered(folder, saved) == browser.evaluate("views.get(0).svg"), "the saved file renders as shown")
        click(browser, "#scene-0 button.undo")
        eventually(lambda: (folder / "s.json").read_text() == bare, 60, what="the file back after undo")
    finally:
        served.stop()


def test_auto_camera_and_turn_latency(folder, browser, latencies):
    """SAM 3D Fig. 13 ("auto": true): the turn starts from the camera each panel is drawn with and
    is drawn as turned; one request at a time, the last position shown; the time from a move to
    its figure; Save view writes "auto": false with the numbers."""
    text = (SOURCE / "scenes" / "sam-3d-fig13-polysam.json").read_text()
    (folder / "s.json").write_text(text)
    served = Served(folder, ["s.json"], "--edit")
    try:
        open_scene(browser, served)
        shown = browser.evaluate("document.querySelector('#scene-0 .camera').textContent")
        check("(auto; the file: -70\u00b0, 28\u00b0)" in shown, f"the camera shown: {shown}")
        drawn = browser.evaluate("views.get(0).camera.panels[0]")
        # A quick drag of 30 moves: never two figures on their way, and the last position shown.
        browser.evaluate("""(() => { window.pitaTurns = {on: 0, most: 0, asked: 0}; const fetched = window.fetch;
            window.fetch = async (url, options) => { const turn = String(url).includes('camera=');
              if (turn) { pitaTurns.asked++; pitaTurns.on++; pitaTurns.most = Math.max(pitaTurns.most, pitaTurns.on); }
              try { return await fetched(url, options); } finally { if (turn) pitaTurns.on--; } }; })()""")
        x, y = panel_centre(browser)
        drag(browser, x, y, 60, -20, steps=30)
        eventually(lambda: settled(browser), 60, what=lambda: f"the last position shown: {turned(browser)}")
        expected = [round(drawn["azimuth"] - 30, 1), round(drawn["elevation"] - 10, 1)]
        check(turned(browser) == expected, f"turned from the panel's drawn camera {drawn}: {turned(browser)}")
        counts = browser.evaluate("pitaTurns")
        check(counts["most"] == 1, f"one request at a time: {counts}")
        check(counts["asked"] < 30, f"moves while one was on its way waited for it: {counts}")
        check(browser.evaluate("views.get(0).svg") == rendered(folder, with_camera(text, *expected)),
              "drawn as turned (auto off), as pita render draws the file with that camera")

        # Time from a pointer move to its turned figure shown, move by move.
        times = []
        x, y = panel_centre(browser)
        browser.call("Input.dispatchMouseEvent", type="mouseMoved", x=x, y=y)
        mouse(browser, "mousePressed", x, y)
        for trial in range(1, 8):
            time.sleep(0.1)
            mouse(browser, "mouseMoved", x + 8 * trial, y)
            eventually(lambda: settled(browser), 60, what="the turned figure")
            times.append(browser.evaluate("views.get(0).turnShownAt - views.get(0).turnMovedAt"))
        mouse(browser, "mouseReleased", x + 56, y)
        latencies.append(("sam-3d-fig13-polysam", sorted(times)[len(times) // 2], min(times), max(times)))

        azimuth, elevation = turned(browser)
        click(browser, "#scene-0 button.save-view")
        saved = eventually(lambda: (lambda t: t != text and t)((folder / "s.json").read_text()), 60,
                           what=lambda: "the file saved: " + served.stderr()[-400:])
        camera = json.loads(saved)["camera"]
        check(camera["auto"] is False and [camera["azimuth"], camera["elevation"]] == [azimuth, elevation], camera)
        check(json.loads(saved) == dict(json.loads(text), camera=dict(json.loads(text)["camera"], auto=False,
                                                                     azimuth=azimuth, elevation=elevation)),
              "nothing else changed")
        eventually(lambda: browser.evaluate("views.get(0).turned === null && !views.get(0).fetching"), 60)
        check(rendered(folder, saved) == browser.evaluate("views.get(0).svg"), "the saved file renders as shown")
        click(browser, "#scene-0 button.undo")
        eventually(lambda: (folder / "s.json").read_text() == text, 60, what="the file back after undo")
    finally:
        served.stop()


def test_shift_wheel_moves_a_perspective_camera(folder, browser):
    """With "projection": "perspective", Shift+wheel over a panel moves the camera farther (down)
    or nearer; the plain wheel still zooms. Save view writes the distance."""
    text = (SOURCE / "scenes" / "sam-3d-fig12-bezier.json").read_text()
    text = text.replace('"shadow": true', '"shadow": true, "projection": "perspective", "distance": 12', 1)
    (folder / "s.json").write_text(text)
    served = Served(folder, ["s.json"], "--edit")
    try:
        open_scene(browser, served)
        box = lambda: browser.evaluate(f"{FIGURE}.getAttribute('viewBox')")
        whole = box()
        x, y = panel_centre(browser)
        browser.call("Input.dispatchMouseEvent", type="mouseMoved", x=x, y=y)
        browser.call("Input.dispatchMouseEvent", type="mouseWheel", x=x, y=y, deltaX=0, deltaY=100, modifiers=8)
        eventually(lambda: settled(browser), 60, what="the farther camera's figure")
        distance = browser.evaluate("views.get(0).turned.distance")
        check(distance == 13.2 and turned(browser) == [-65, 32], f"a tenth farther: {distance}, {turned(browser)}")
        check(box() == whole, "Shift+wheel does not zoom the view box")
        scene = json.loads(text)
        scene["camera"]["distance"] = 13.2
        check(browser.evaluate("views.get(0).svg") == rendered(folder, json.dumps(scene)),
              "the figure is pita render's with that distance")
        check("distance 13.2" in browser.evaluate("document.querySelector('#scene-0 .camera').textContent"),
              "the distance shown")
        click(browser, "#scene-0 button.save-view")
        saved = eventually(lambda: (lambda t: t != text and t)((folder / "s.json").read_text()), 60,
                           what=lambda: "the file saved: " + served.stderr()[-400:])
        check(saved == text.replace('"distance": 12', '"distance": 13.2', 1), f"only the distance changed: {saved[:600]}")
        eventually(lambda: browser.evaluate("views.get(0).turned === null && !views.get(0).fetching"), 60)
        browser.evaluate("document.querySelector('#scene-0 .figure').scrollIntoView()")
        x, y = panel_centre(browser)
        browser.call("Input.dispatchMouseEvent", type="mouseWheel", x=x, y=y, deltaX=0, deltaY=-100)
        eventually(lambda: box() != whole, 10, what="the plain wheel zooms")
        # Nearer and nearer, until the camera stands among the solids: the page says why it is not drawn.
        for _ in range(30):
            browser.call("Input.dispatchMouseEvent", type="mouseWheel", x=x, y=y, deltaX=0, deltaY=-100, modifiers=8)
        said = lambda: browser.evaluate("document.querySelector('#scene-0 .camera').textContent")
        eventually(lambda: "not drawn" in said() and "behind the perspective camera" in said(), 60,
                   what=lambda: f"the reason shown: {said()}")
    finally:
        served.stop()


def test_a_scene_of_the_plane_does_not_turn(folder, browser):
    text = (SOURCE / "scenes" / "fig03-steady-morph.json").read_text()
    (folder / "s.json").write_text(text)
    served = Served(folder, ["s.json"])
    try:
        browser.open(served.url)
        eventually(lambda: browser.evaluate(f"typeof views !== 'undefined' && views.get(0) && !!{FIGURE}"), 60)
        before = browser.evaluate("views.get(0).svg")
        browser.evaluate("window.pitaAsked = 0; const f0 = window.fetch; window.fetch = (u, o) => "
                         "{ if (String(u).includes('/api/figure/')) window.pitaAsked++; return f0(u, o); }")
        x, y = panel_centre(browser)
        drag(browser, x, y, 80, 30)
        time.sleep(0.5)
        asked = browser.evaluate("window.pitaAsked")
        check(asked == 0 and browser.evaluate("views.get(0).svg") == before, f"nothing turned ({asked} figures asked for)")
        check(browser.evaluate("views.get(0).camera === null && views.get(0).turned == null"), "no camera")
        check(browser.evaluate("!document.querySelector('#scene-0 .camera-tools') || "
                               "getComputedStyle(document.querySelector('#scene-0 .camera-tools')).display === 'none'"),
              "no camera tools")
        status, body = served.get("/api/figure/0?camera=10,20")
        check(status == 400 and b"only a 3D pose scene" in body, (status, body))
        check((folder / "s.json").read_text() == text, "the file as it was")
    finally:
        served.stop()


def corner_on_screen(browser, pointer, part):
    """Where the handle of `part` of `pointer` is on the screen (CSS pixels), or None."""
    return browser.evaluate(f"""(() => {{ const c = [...document.querySelectorAll('#scene-0 circle.handle')].find(h =>
        h.dataset.pointer === {json.dumps(pointer)} && h.dataset.part === {json.dumps(part)});
        if (!c) return null; const r = c.getBoundingClientRect(); return [r.x + r.width / 2, r.y + r.height / 2]; }})()""")


def top_corner(browser):
    """A corner handle nothing covers (the pointer finds it at its centre), the last drawn first."""
    for h in reversed(browser.evaluate("views.get(0).shownHandles")):
        at = corner_on_screen(browser, h["pointer"], h["part"])
        hit = at and browser.evaluate(f"(() => {{ const e = document.elementFromPoint({at[0]}, {at[1]}); "
                                      "return e && e.dataset ? [e.dataset.pointer, e.dataset.part] : null; })()")
        if hit == [h["pointer"], h["part"]]:
            return h["pointer"], h["part"], at
    raise AssertionError("no corner handle on top")


def test_a_corner_of_space_is_dragged_in_the_views_plane(folder, browser, name="sam-3d-fig12-bezier"):
    """Fig. 12 with --edit: a handle at each corner of each pose's reference tetrahedron; a drag
    that starts on one moves it (the camera does not turn), the figure follows while the button is
    held, the release writes that pose's matrix entries only, the handle stays under the pointer,
    and Ctrl+Z gives the file back byte for byte. While the view is turned, no handles."""
    text = (SOURCE / "scenes" / f"{name}.json").read_text()
    (folder / "s.json").write_text(text)
    served = Served(folder, ["s.json"], "--edit")
    try:
        open_scene(browser, served)
        poses = len(json.loads(text)["poses"])
        count = lambda: browser.evaluate("document.querySelectorAll('#scene-0 circle.handle').length")
        eventually(lambda: count() == 4 * poses, 30, what=lambda: f"four handles a pose: {count()}")
        pointer, part, (x, y) = top_corner(browser)
        k = int(pointer.split("/")[-1])
        shown = browser.evaluate("views.get(0).changes")
        old_version = json.loads(served.get("/api/scenes")[1])[0]["version"]
        dx, dy = 36.0, -28.0
        browser.call("Input.dispatchMouseEvent", type="mouseMoved", x=x, y=y)
        mouse(browser, "mousePressed", x, y)
        for step in range(1, 7):
            mouse(browser, "mouseMoved", x + dx * step / 6, y + dy * step / 6)
            time.sleep(0.05)
        # The figure follows while the button is held (POST /api/preview), and the camera stays.
        eventually(lambda: browser.evaluate("views.get(0).changes") > shown, 30, what="a live figure while dragging")
        check(browser.evaluate("views.get(0).turned") is None, "a drag from a handle does not turn the camera")
        check((folder / "s.json").read_text() == text, "nothing written before release")
        mouse(browser, "mouseReleased", x + dx, y + dy)
        edited = eventually(lambda: (lambda t: t != text and t)((folder / "s.json").read_text()), 60,
                            what=lambda: "the file edited: " + served.stderr()[-400:])
        # Only numbers of pose k's matrix changed: the bytes that differ lie within that pose.
        was, now = json.loads(text), json.loads(edited)
        moved = was["poses"][k]["matrix"]
        was["poses"][k]["matrix"] = now["poses"][k]["matrix"]
        check(was == now and moved != now["poses"][k]["matrix"], f"only pose {k}'s matrix changed")
        same_start = next(i for i, (a, b) in enumerate(zip(text, edited)) if a != b)
        same_end = next(i for i, (a, b) in enumerate(zip(reversed(text), reversed(edited))) if a != b)
        starts = [i for i in range(text.index('"poses"'), len(text)) if text.startswith('"t":', i)]
        end = text.index("}", starts[k])  # a pose is an object with no object inside
        check(starts[k] < same_start and len(text) - same_end <= end,
              f"the changed bytes lie in pose {k}: {text[same_start:len(text) - same_end]!r}")
        for r in range(3):
            for c in range(4):
                if now["poses"][k]["matrix"][r][c] == moved[r][c]:
                    check(str(moved[r][c]) in edited[starts[k]:], "an untouched entry keeps its text")
        check(browser.evaluate("views.get(0).turned") is None, "still the file's camera")
        # The figure drawn from the file in the view held: the corner where it was dropped.
        def at_new_version():
            version = json.loads(served.get("/api/scenes")[1])[0]["version"]
            return (version != old_version and browser.evaluate("views.get(0).fetching") is None and
                    browser.evaluate("document.querySelector('#scene-0').dataset.version") == str(version))
        eventually(at_new_version, 60, what="the page at the edited file's version")
        eventually(lambda: (lambda at: at and abs(at[0] - x - dx) < 2 and abs(at[1] - y - dy) < 2)(
                       corner_on_screen(browser, pointer, part)), 30,
                   what=lambda: f"the handle under the pointer: {corner_on_screen(browser, pointer, part)} "
                                f"against {(x + dx, y + dy)}")
        # Ctrl+Z: the file back, byte for byte.
        for kind in ("rawKeyDown", "keyUp"):
            browser.call("Input.dispatchKeyEvent", type=kind, key="z", code="KeyZ", windowsVirtualKeyCode=90,
                         nativeVirtualKeyCode=90, modifiers=2)
        eventually(lambda: (folder / "s.json").read_text() == text, 30, what="the file back after Ctrl+Z")
        # Turned in the page, the figure shows no handles (they are the file's camera's); "reset view" brings them back.
        eventually(lambda: count() == 4 * poses and not browser.evaluate("views.get(0).fetching"), 30)
        # A press on the panel away from every handle turns it.
        px, py = browser.evaluate(f"""(() => {{ const svg = {FIGURE}; const [x, y, w, h] = views.get(0).panels[0];
            for (const [fx, fy] of [[0.1, 0.9], [0.9, 0.9], [0.1, 0.2], [0.9, 0.2], [0.5, 0.95]]) {{
              const p = svg.createSVGPoint(); p.x = x + fx * w; p.y = y + fy * h;
              const q = p.matrixTransform(svg.getScreenCTM());
              const e = document.elementFromPoint(q.x, q.y);
              if (e && !e.classList.contains('handle')) return [q.x, q.y]; }} return null; }})()""")
        drag(browser, px, py, 40, 0)
        eventually(lambda: settled(browser), 60, what=lambda: f"the turned figure: {turned(browser)}")
        check(count() == 0, f"no handles on the turned figure: {count()}")
        click(browser, "#scene-0 button.reset-view")
        eventually(lambda: count() == 4 * poses, 30, what=lambda: f"the handles back: {count()}")
    finally:
        served.stop()


def test_a_corner_under_an_auto_camera_stays_under_the_pointer(folder, browser):
    """SAM 3D Fig. 13 ("auto": true, poses over several lines): the camera the figure was drawn with
    is held while editing, so that the edit does not turn the view under the pointer."""
    test_a_corner_of_space_is_dragged_in_the_views_plane(folder, browser, "sam-3d-fig13-polysam")


def test_the_camera_parameter_is_checked(folder):
    shutil.copy(SOURCE / "scenes" / "sam-3d-fig12-bezier.json", folder / "s.json")
    served = Served(folder, ["s.json"])
    try:
        check(served.get("/api/figure/0?camera=10,20")[0] == 200, "a good camera")
        for query, reason in (("nan,20", b"finite"), ("10,95", b"elevation must be within"),
                              ("361,0", b"azimuth must be within"), ("10", b"two or three"),
                              ("10,20,0", b"distance must be > 0")):
            status, body = served.get(f"/api/figure/0?camera={query}")
            check(status == 400 and reason in body, f"{query}: {status} {body}")
        check(served.get("/api/figure/0?camera=10,20", token="")[0] == 403, "the token first")
        status, body = served.get("/api/edit/0", data=b'{"changes": [{"pointer": "/camera/azimuth", "value": "1"}]}')
        check(status == 403, "Save view needs --edit")
    finally:
        served.stop()


def main():
    latencies = []
    root = pathlib.Path(tempfile.mkdtemp(prefix="pita-serve-camera-"))
    browser = Browser()
    try:
        for test in (test_the_camera_parameter_is_checked, test_a_scene_of_the_plane_does_not_turn,
                     test_turning_and_saving, test_save_view_adds_what_the_file_lacks,
                     test_shift_wheel_moves_a_perspective_camera, test_auto_camera_and_turn_latency,
                     test_a_corner_of_space_is_dragged_in_the_views_plane,
                     test_a_corner_under_an_auto_camera_stays_under_the_pointer):
            folder = root / test.__name__
            folder.mkdir()
            started = time.monotonic()
            if test is test_the_camera_parameter_is_checked:
                test(folder)
            elif test is test_auto_camera_and_turn_latency:
                test(folder, browser, latencies)
            else:
                test(folder, browser)
            print(f"ok {test.__name__} ({time.monotonic() - started:.1f} s)")
    finally:
        browser.close()
        shutil.rmtree(root, ignore_errors=True)
    for name, median, least, most in latencies:
        print(f"pointer move to turned figure shown, {name}: median {median:.0f} ms "
              f"(of 7 moves: {least:.0f} to {most:.0f} ms)")


if __name__ == "__main__":
    main()
