"""pita serve (src/serve/server.cpp, src/serve/page/), as a person uses it in Chromium
and as a hostile page would try it: a save updates the figure in the page, a bad save shows its
error and keeps the figure, the slider draws the frame at its time; requests without the token,
with another path or too large a body are refused; a hundred saves leave the last figure and no
temporary. Run by ctest serve.browser (tests/CMakeLists.txt)."""
import json
import os
import pathlib
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import urllib.request

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from serve_session import PITA, Browser, Served, eventually, figures_asked_since, key, play  # noqa: E402

SOURCE = pathlib.Path(os.environ.get("PITA_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
FIG03 = json.loads((SOURCE / "scenes" / "fig03-steady-morph.json").read_text())
FIGURE = "document.querySelector('#scene-0 .figure svg')"


def save(folder, scene, name="s.json"):
    """Saves as an editor does: a new file renamed over the old one."""
    (folder / f".~{name}").write_text(json.dumps(scene, indent=2))
    os.replace(folder / f".~{name}", folder / name)


def figure_text(browser):
    """Scene 0's figure in the page, its ids as cairo wrote them (the page prefixes them with s0-)."""
    text = browser.evaluate(f"{FIGURE} ? {FIGURE}.outerHTML : ''")
    return text.replace('id="s0-', 'id="').replace('"#s0-', '"#').replace("url(#s0-", "url(#")


def page_state(browser):
    """What the page shows of scene 0, for a failure's message."""
    return browser.evaluate("""JSON.stringify({version: document.querySelector('#scene-0') &&
        document.querySelector('#scene-0').dataset.version, error: document.querySelector('#scene-0 .error') &&
        document.querySelector('#scene-0 .error').textContent, status: document.getElementById('status').textContent,
        figure: (document.querySelector('#scene-0 .figure') || {innerHTML: ''}).innerHTML.length})""")


def check(condition, message):
    if not condition:
        raise AssertionError(message)


def test_the_page_follows_the_saves(folder, browser, latencies):
    save(folder, FIG03)
    served = Served(folder, ["s.json"])
    try:
        browser.open(served.url)
        first = eventually(lambda: figure_text(browser), 60)
        check(browser.evaluate("document.querySelector('#scene-0 h2').textContent").startswith("s: Fig. 3"),
              "the scene's name and title")

        # The caption's claims, measured: Fig. 3's hold.
        claims = eventually(lambda: browser.evaluate(
            "[...document.querySelectorAll('#scene-0 .claims li')].map(li => li.className)"), 60)
        check(claims and all(c == "held" for c in claims), f"the claims hold: {claims}")

        # A save: the page shows the new figure without reloading.
        browser.evaluate("window.pitaMarker = 1")
        changed = dict(FIG03)
        changed["keyframes"] = [dict(k) for k in FIG03["keyframes"]]
        changed["keyframes"][1]["w"] = 2.0
        start = time.time()
        browser.evaluate("""window.pitaSeen = null; new MutationObserver(() => { if (window.pitaSeen === null)
            window.pitaSeen = Date.now(); }).observe(document.querySelector('#scene-0 .figure'), {childList: true})""")
        save(folder, changed)
        second = eventually(lambda: (figure_text(browser) or first) != first and figure_text(browser), 60,
                            what=lambda: "the new figure: " + page_state(browser))
        check(browser.evaluate("window.pitaMarker") == 1, "the page was reloaded")
        # w = 2.0 breaks the claim that the winding runs from 0.3 to 3.6: the page says so.
        failed = eventually(lambda: browser.evaluate(
            "[...document.querySelectorAll('#scene-0 .claims li.failed')].map(li => li.textContent)"), 60)
        check(any("winding" in text for text in failed), f"the failed claim: {failed}")
        seen = eventually(lambda: browser.evaluate("window.pitaSeen"), 10)
        check(seen / 1000 - start < 60, "the figure came")
        status, body = served.get("/api/figure/0")
        check(status == 200 and body.decode().split("<svg", 1)[1][:300] in second, "the page's figure is the server's")

        # A bad save: the error, with its line:column, over the last good figure.
        (folder / "s.json").write_text('{"method": "SMA",\n  "keyframes": [')
        error = eventually(lambda: browser.evaluate(
            "document.querySelector('#scene-0 .error.shown') && document.querySelector('#scene-0 .error').textContent"), 60,
            what=lambda: "the malformed save's error: " + page_state(browser))
        check("s.json:2:" in error, f"the error names the line: {error}")
        check(figure_text(browser) == second, "the last good figure stays")
        save(folder, dict(FIG03, keyframes=[dict(k, m=-1) if i == 1 else k for i, k in enumerate(FIG03["keyframes"])]))
        eventually(lambda: "/keyframes/1/m: magnitude must be > 0" in (browser.evaluate(
            "document.querySelector('#scene-0 .error').textContent") or ""), 60,
            what=lambda: "the bad value's error: " + page_state(browser))
        save(folder, FIG03)
        eventually(lambda: not browser.evaluate("document.querySelector('#scene-0 .error.shown')"), 60,
                   what=lambda: "the error gone: " + page_state(browser))
        eventually(lambda: figure_text(browser) == first, 60, what=lambda: "the first figure back: " + page_state(browser))
        # The terminal said each save, one line each: the good ones, and the errors.
        said = served.stderr()
        check(said.count("pita: s.json: saved, figure updated") >= 2, said)
        check("1 of 3 claims fail" in said or "claims fail" in said, said)
        check("s.json:2:" in said and "/keyframes/1/m: magnitude must be > 0" in said, said)
        check("the page keeps the last good figure" in said, said)

        # The slider: frame k of pita animate, at its time t_k, as pita render --at draws it.
        check(browser.evaluate("getComputedStyle(document.querySelector('#scene-0 .controls')).display") != "none",
              "a scene with a motion has a slider")
        check(browser.evaluate("document.querySelector('#scene-0 .controls label').textContent") == "t from 0 to 1",
              "the slider says what it runs through")
        # Frames fetched one by one (before the animated SVG came, or without one): render --at's frame.
        browser.evaluate("""(() => { views.get(0).animation = null; const s = document.querySelector('#scene-0 input[type=range]');
            s.value = String(Math.round(+s.max / 2)); s.dispatchEvent(new Event('input')); })()""")
        at = eventually(lambda: browser.evaluate("views.get(0).shown === 'frame' && views.get(0).t"), 60,
                        what=lambda: "the fetched frame: " + page_state(browser))
        frame = figure_text(browser)
        subprocess.run([PITA, "render", "s.json", "--at", repr(at), "-o", ".at.svg"], cwd=folder, check=True,
                       stdout=subprocess.DEVNULL)
        svg = (folder / ".at.svg").read_text()
        (folder / ".at.svg").unlink()
        check(svg.split("<svg", 1)[1][:300] in frame and frame != first, "the slider's frame is render --at's")
        check(browser.evaluate("document.querySelector('#scene-0 .controls .time').textContent").startswith(
              f"t = {at:.3f}  (frame "), "the slider's time is shown")
    finally:
        check(served.stop() == 128 + 15, "SIGTERM stops it with 128 + 15")


def test_dragging_writes_the_scene_file(folder, browser):
    """--edit: a dragged tail changes "p" in the file and nothing else; undo restores the file
    byte for byte; a drag that would make the scene bad is refused with the reason."""
    text = (SOURCE / "scenes" / "fig03-steady-morph.json").read_text()
    (folder / "s.json").write_text(text)
    served = Served(folder, ["s.json"], "--edit")
    try:
        browser.open(served.url)
        tail = "#scene-0 circle.handle.tail[data-pointer='/keyframes/0']"
        eventually(lambda: browser.evaluate(f"document.querySelector({json.dumps(tail)}) !== null"), 60)
        # Zoomed in about the tail (the wheel over it), the handle stays under the pointer and drags.
        x, y = browser.evaluate(f"""(() => {{ const r = document.querySelector({json.dumps(tail)}).getBoundingClientRect();
            return [r.x + r.width / 2, r.y + r.height / 2]; }})()""")
        browser.call("Input.dispatchMouseEvent", type="mouseWheel", x=x, y=y, deltaX=0, deltaY=-100)
        check(browser.evaluate("document.querySelector('#scene-0 .figure svg').classList.contains('zoomed')"), "zoomed")
        moved = browser.evaluate(f"""(() => {{ const r = document.querySelector({json.dumps(tail)}).getBoundingClientRect();
            return Math.hypot(r.x + r.width / 2 - {x}, r.y + r.height / 2 - {y}); }})()""")
        check(moved < 1, f"the tail stays under the pointer when zoomed about it ({moved} px)")
        browser.drag(tail, 40, 0)
        edited = eventually(lambda: (folder / "s.json").read_text() != text and (folder / "s.json").read_text(), 60)
        before, after = json.loads(text), json.loads(edited)
        check(after["keyframes"][0]["p"][0] > before["keyframes"][0]["p"][0], "the tail moved right")
        check(after["keyframes"][0]["p"][1] == before["keyframes"][0]["p"][1] or
              abs(after["keyframes"][0]["p"][1] - before["keyframes"][0]["p"][1]) < 0.05, "and not up or down")
        # Every byte but the value of p is as it was.
        start = text.index('"p": [0, 0]') + len('"p": ')
        end = start + len("[0, 0]")
        check(edited[:start] == text[:start] and edited[edited.index("]", start) + 1:] == text[end:],
              f"only p changed: {edited[start - 10:start + 40]}")
        # The figure follows, then undo puts the file back.
        eventually(lambda: browser.evaluate("document.querySelector('#scene-0 button.undo').style.display === ''"), 60)
        browser.evaluate("document.querySelector('#scene-0 button.undo').click()")
        eventually(lambda: (folder / "s.json").read_text() == text, 60)
        # An edit that would make the scene bad (a magnitude of -1) is refused, with the reason shown.
        browser.evaluate("""edit(0, {changes: [{pointer: '/keyframes/0/m', value: '-1'}]}, true)""")
        refused = eventually(lambda: browser.evaluate(
            "document.querySelector('#scene-0 .refused.shown') && document.querySelector('#scene-0 .refused').textContent"), 60,
            what=lambda: "the refusal shown: " + page_state(browser) + " " + served.stderr()[-600:])
        check("/keyframes/0/m" in refused and "magnitude must be > 0" in refused, f"the reason: {refused}")
        # The refusal is shown over the figure, which stays where it was; a good state clears it.
        top = browser.evaluate("document.querySelector('#scene-0 .figure').getBoundingClientRect().top")
        browser.evaluate("views.get(0).refused.classList.remove('shown')")
        check(browser.evaluate("document.querySelector('#scene-0 .figure').getBoundingClientRect().top") == top,
              "the banner does not move the figure")
        browser.evaluate("views.get(0).refused.classList.add('shown')")
        (folder / "s.json").write_text(text.replace('"samples": ', '"samples":  ', 1))
        eventually(lambda: not browser.evaluate("document.querySelector('#scene-0 .refused.shown')"), 60,
                   what="the banner cleared by the next good save")
        (folder / "s.json").write_text(text)
        # The slider's frames have no handles; the "figure" button brings the figure and its handles back.
        eventually(lambda: browser.evaluate("document.querySelectorAll('#scene-0 circle.handle').length") > 0, 60)
        browser.evaluate("""(() => { const s = document.querySelector('#scene-0 input[type=range]');
            s.value = String((+s.min + +s.max) / 2); s.dispatchEvent(new Event('input')); })()""")
        eventually(lambda: browser.evaluate("document.querySelectorAll('#scene-0 circle.handle').length") == 0
                   and browser.evaluate("document.querySelector('#scene-0 button.still').style.display") == "", 60)
        browser.evaluate("document.querySelector('#scene-0 button.still').click()")
        eventually(lambda: browser.evaluate("document.querySelectorAll('#scene-0 circle.handle').length") > 0, 60,
                   what="the handles back after the slider")
        status, body = served.get("/api/edit/0", data=b'{"changes": [{"pointer": "/keyframes/9", "value": "1"}]}')
        check(status == 400, f"a pointer to nothing: {status} {body}")
        # A drag naming a panel the figure does not have (1e20 read as an index was panel 0).
        for panel in (b"1e20", b"-1", b"7"):
            status, body = served.get("/api/edit/0", data=b'{"drag": {"panel": ' + panel +
                                      b', "pointer": "/keyframes/0", "part": "tail", "to": [1, 1]}}')
            check(status == 400 and b"must be the index of a panel of the figure" in body, f"panel {panel}: {status} {body}")
        check((folder / "s.json").read_text() == text, "a refused edit leaves the file")
        said = served.stderr()
        check("pita: s.json: edited /keyframes/0/p" in said, said)
        check("pita: s.json: edit refused:" in said and "magnitude must be > 0" in said, said)
        check("edit refused: \"panel\" must be the index of a panel" in said, said)
        # A save that is not UTF-8 (Latin-1): the error is answered, as JSON, never an empty 500.
        (folder / "s.json").write_bytes(text.replace('"title": "', '"title": "caf\xe9 ', 1).encode("latin-1"))
        status, body = eventually(lambda: (lambda r: r if r[0] == 200 and b"UTF-8" in r[1] else None)(
            served.get("/api/scenes")), 30, what=lambda: served.get("/api/scenes"))
        json.loads(body)
        (folder / "s.json").write_text(text)
    finally:
        served.stop()
    check(sorted(p.name for p in folder.iterdir() if p.name.startswith(".")) == [], "no temporary left")


def test_two_figures_keep_their_own_glyphs(folder, browser):
    """cairo gives every SVG the same ids (glyph0-1, ...): in one page each figure must still
    draw with its own glyphs and clips."""
    save(folder, FIG03, "a.json")
    save(folder, json.loads((SOURCE / "scenes" / "fig01-eight-pitas.json").read_text()), "b.json")
    served = Served(folder, ["a.json", "b.json"])
    try:
        browser.open(served.url)
        eventually(lambda: browser.evaluate("document.querySelectorAll('.figure svg').length") == 2, 60,
                   what=lambda: "two figures: " + page_state(browser))
        ids = browser.evaluate("[...document.querySelectorAll('.figure [id]')].map(e => e.id)")
        check(len(ids) > 10 and len(ids) == len(set(ids)), f"{len(ids) - len(set(ids))} ids shared")
        strays = browser.evaluate("""[...document.querySelectorAll('.figure svg')].flatMap(svg =>
            [...svg.querySelectorAll('use')].map(u => u.getAttribute('xlink:href') || u.getAttribute('href'))
              .filter(h => !svg.querySelector(h)))""")
        check(strays == [], f"references to another figure's glyphs: {strays[:5]}")
        # The pointer over Fig. 1's third panel: the measures of P3 alone.
        browser.evaluate("document.querySelector('#scene-1 .figure').scrollIntoView()")
        x, y = browser.evaluate("""(() => { const svg = document.querySelector('#scene-1 .figure svg');
            const v = views.get(1); const [cx, cy, w, h] = v.panels[2];
            const p = svg.createSVGPoint(); p.x = cx + w / 2; p.y = cy + h / 2;
            const q = p.matrixTransform(svg.getScreenCTM()); return [q.x, q.y]; })()""")
        browser.call("Input.dispatchMouseEvent", type="mouseMoved", x=x, y=y)
        shown = eventually(lambda: browser.evaluate("document.querySelector('#scene-1 .measures').textContent"), 60)
        check(shown.startswith("P3") and "\n" not in shown, f"the measures of the panel under the pointer: {shown}")
        # A save while the pointer stays: the measures follow the new figure, without leaving and coming back.
        fig01 = json.loads((SOURCE / "scenes" / "fig01-eight-pitas.json").read_text())
        fig01["keyframes"][1]["p"] = [fig01["keyframes"][1]["p"][0] + 1.5, fig01["keyframes"][1]["p"][1]]
        save(folder, fig01, "b.json")
        after = eventually(lambda: (lambda t: t != shown and t.startswith("P3") and t)(
            browser.evaluate("document.querySelector('#scene-1 .measures').textContent")), 60,
            what=lambda: browser.evaluate("document.querySelector('#scene-1 .measures').textContent"))
        check("\n" not in after, f"still the panel under the pointer: {after}")
    finally:
        served.stop()


def test_the_page_links_only_within_itself(folder, browser):
    """Every href and src of the page, figures included, is a fragment, an inline image or a
    path of this server: never another scheme, whatever the scene is named."""
    save(folder, FIG03, name="javascript:alert(1).json")
    served = Served(folder, ["javascript:alert(1).json"])
    try:
        browser.open(served.url)
        eventually(lambda: figure_text(browser), 60)
        links = browser.evaluate("""[...document.querySelectorAll('*')].flatMap(e => [...e.attributes]
            .filter(a => /(^|:)(href|src|action)$/i.test(a.name)).map(a => a.value))""")
        check(links, "the page has links (the figure's glyphs)")
        scheme = re.compile(r"^\s*[a-zA-Z][a-zA-Z0-9+.-]*:")
        bad = [link for link in links
               if scheme.match(link) and not link.startswith("data:image/") and not link.startswith(served.base)]
        check(not bad, f"links out of the page: {bad[:5]}")
        check(browser.evaluate("document.querySelector('#scene-0 h2').textContent").startswith("javascript:alert(1)"),
              "the scene's name is shown as text")
    finally:
        served.stop()


def visible_frames(browser, index):
    """The frame groups of the animated SVG the page shows, visible now (their indices)."""
    return browser.evaluate(f"""[...document.querySelectorAll('#scene-{index} .figure svg > g[visibility]')]
        .map((g, j) => getComputedStyle(g).visibility === 'visible' ? j : -1).filter(j => j >= 0)""")


def animation_frame_paths(svg_text, k):
    """The d of every path of frame k of an animated SVG (`pita animate -o x.svg`)."""
    groups = re.findall(r'<g visibility="(?:visible|hidden)"><animate .*?\n', svg_text)
    return re.findall(r' d="([^"]*)"', groups[k])


def test_scrubbing_and_play(folder, browser, rates):
    """The slider, the arrow keys and play seek the scene's animated SVG, asking nothing of the
    server: the frame shown is pita animate's frame k, at the time of render --at's; play shows
    frames at the timeline's fps (measured over 2 s)."""
    names = ("fig01-eight-pitas", "sam-fig02-linear-and-sam")
    shutil.copytree(SOURCE / "scenes" / "images", folder / "images")
    for name in names:
        shutil.copy(SOURCE / "scenes" / f"{name}.json", folder / f"{name}.json")
    served = Served(folder, [f"{name}.json" for name in names])
    try:
        browser.open(served.url)
        for i, name in enumerate(names):
            # The animated SVG, and the figure fetched first (the animation may come before it).
            eventually(lambda: browser.evaluate(f"typeof views !== 'undefined' && views.get({i}) && "
                                                f"views.get({i}).animation !== null && views.get({i}).shown !== null && "
                                                f"!views.get({i}).fetching"), 60,
                       what=f"{name}'s animated SVG and figure")
            # Space plays: the frames shown change at the display's rate, up to the timeline's fps.
            shown, fps, since = play(browser, i, 2)
            check(not browser.evaluate(f"views.get({i}).playing"), "space pauses")
            rates.append((name, shown, fps))
            # A third of the rate: ctest runs this beside builds and other browsers (serve.browser.scenes).
            check(shown > fps / 3, f"{name}: {shown} frames a second, of {fps}")
            # An arrow steps one frame; the frame shown is pita animate's frame k.
            k = browser.evaluate(f"views.get({i}).k")
            key(browser, "ArrowRight", "ArrowRight", 39)
            check(browser.evaluate(f"views.get({i}).k") == k + 1, "the right arrow steps a frame")
            key(browser, "ArrowLeft", "ArrowLeft", 37)
            key(browser, "ArrowLeft", "ArrowLeft", 37)
            k -= 1
            check(browser.evaluate(f"views.get({i}).k") == k, "the left arrow steps back")
            eventually(lambda: visible_frames(browser, i) == [k], 10,
                       what=lambda: f"frame {k} shown: {visible_frames(browser, i)}")
            asked = figures_asked_since(browser, since)
            check(not asked, f"play and the arrows asked nothing of the server: {asked}")
            subprocess.run([PITA, "animate", f"{name}.json", "-o", ".a.svg"], cwd=folder, check=True,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            shown = browser.evaluate(f"""[...document.querySelectorAll('#scene-{i} .figure svg > g[visibility]')[{k}]
                .querySelectorAll('path')].map(p => p.getAttribute('d'))""")
            check(shown and shown == animation_frame_paths((folder / ".a.svg").read_text(), k),
                  f"{name}: the page's frame {k} is pita animate's")
            (folder / ".a.svg").unlink()
            # Its time is render --at's t_k.
            t = browser.evaluate(f"views.get({i}).t")
            expected = browser.evaluate(f"frameTime(views.get({i}).timeline, {k})")
            check(t == expected, f"t = {t} is frame {k}'s time {expected}")
        # Without the animated SVG (too large or slow to make) frames are fetched: a scrub cancels
        # each request the next one supersedes, and the last frame asked for is the one shown.
        browser.evaluate("""(() => { window.pitaSignals = []; const fetched = window.fetch;
            window.fetch = (url, options) => { if (String(url).includes('/api/figure/'))
              window.pitaSignals.push(options.signal); return fetched(url, options); };
            views.get(1).animation = null; const s = document.querySelector('#scene-1 input[type=range]');
            for (const k of [10, 20, 30]) { s.value = String(k); s.dispatchEvent(new Event('input')); } })()""")
        eventually(lambda: browser.evaluate("views.get(1).shown === 'frame' && views.get(1).shownFrame === 30"), 60,
                   what=lambda: browser.evaluate("[views.get(1).shown, views.get(1).shownFrame]"))
        aborted = browser.evaluate("window.pitaSignals.map(s => s.aborted)")
        check(aborted == [True, True, False], f"superseded requests cancelled: {aborted}")
    finally:
        served.stop()


def test_orientation(folder, browser):
    """The caption, labelled controls, an index telling same-named files apart, the hovered
    panel outlined with pita measure's row, zoom and pan, and a page that fits 800 x 600."""
    fig01 = json.loads((SOURCE / "scenes" / "fig01-eight-pitas.json").read_text())
    for sub in ("a", "b"):
        (folder / sub).mkdir()
    save(folder / "a", FIG03)
    save(folder / "b", fig01)
    served = Served(folder, ["a/s.json", "b/s.json"])
    try:
        browser.call("Emulation.setDeviceMetricsOverride", width=800, height=600, deviceScaleFactor=1, mobile=False)
        browser.open(served.url)
        eventually(lambda: browser.evaluate("document.querySelectorAll('.figure svg').length") == 2, 60)
        index = browser.evaluate("[...document.querySelectorAll('#index li')].map(li => li.textContent)")
        check(len(index) == 2 and "a/s.json" in index[0] and "b/s.json" in index[1], f"the index: {index}")
        check(browser.evaluate("document.querySelector('#index a').getAttribute('href')") == "#scene-0", "its links")
        check(browser.evaluate("document.querySelector('#scene-0 .caption').textContent") == FIG03["description"],
              "the caption")
        check(browser.evaluate("document.querySelector('#scene-0 button.play').title").startswith("play"), "play")
        # At 800 x 600: no horizontal scroll, each figure within the window.
        check(browser.evaluate("document.documentElement.scrollWidth <= innerWidth"), "no horizontal scroll")
        check(browser.evaluate("[...document.querySelectorAll('.figure svg')].every(s => "
                               "s.getBoundingClientRect().right <= innerWidth && s.getBoundingClientRect().height <= innerHeight)"),
              "the figures fit")
        # The pointer over Fig. 1's second panel: outlined, and pita measure's row for it.
        browser.evaluate("document.querySelector('#scene-1 .figure').scrollIntoView()")
        at = """(() => { const svg = document.querySelector('#scene-1 .figure svg');
            const [cx, cy, w, h] = views.get(1).panels[PANEL]; const p = svg.createSVGPoint();
            p.x = cx + w / 2; p.y = cy + h / 2; const q = p.matrixTransform(svg.getScreenCTM()); return [q.x, q.y]; })()"""
        x, y = browser.evaluate(at.replace("PANEL", "1"))
        browser.call("Input.dispatchMouseEvent", type="mouseMoved", x=x, y=y)
        row = eventually(lambda: browser.evaluate("document.querySelector('#scene-1 .measures').textContent"), 60)
        check(row.startswith("P2 LS-Po") and "\n" not in row and "/panels" not in row, f"one panel's row: {row}")
        for cell in ("E max prev / avg / pita", "length p, q", "turning p, q", "winding [", "most sensitive", "pop "):
            check(cell in row, f"{cell} in {row}")
        outline = browser.evaluate("(() => { const r = document.querySelector('#scene-1 svg rect.outline');"
                                   " return r && [+r.getAttribute('x'), +r.getAttribute('width')]; })()")
        cell = browser.evaluate("views.get(1).panels[1]")
        check(outline and abs(outline[0] - cell[0] - 1) < 1e-6 and abs(outline[1] - cell[2] + 2) < 1e-6,
              f"the panel outlined: {outline} {cell}")
        x, y = browser.evaluate(at.replace("PANEL", "2"))
        browser.call("Input.dispatchMouseEvent", type="mouseMoved", x=x, y=y)
        row = eventually(lambda: (lambda t: t.startswith("P3") and t)(
            browser.evaluate("document.querySelector('#scene-1 .measures').textContent")), 10)
        check(row.startswith("P3 Pa-LP:") and "P3 (Pa-LP)" not in row, f"no label twice: {row}")
        # A panel the report names by its pointer alone is "panel N".
        untitled = browser.evaluate("""measureRow({pointer: '/panels/1', title: '', method: 'SAM', kind: 'poses',
            ara: 0.5, velocity_jump: 0}, 1)""")
        check(untitled == "panel 2 (SAM): ARA 0.5; velocity jump 0", untitled)
        # The wheel zooms in about the pointer, a drag of the background pans, "fit" shows it all.
        box = lambda: browser.evaluate("document.querySelector('#scene-1 .figure svg').getAttribute('viewBox')")
        whole = box()
        browser.call("Input.dispatchMouseEvent", type="mouseWheel", x=x, y=y, deltaX=0, deltaY=-100)
        browser.call("Input.dispatchMouseEvent", type="mouseWheel", x=x, y=y, deltaX=0, deltaY=-100)
        zoomed = eventually(lambda: box() != whole and box(), 10)
        check(float(zoomed.split()[2]) < float(whole.split()[2]), f"zoomed in: {zoomed}")
        browser.call("Input.dispatchMouseEvent", type="mousePressed", x=x, y=y, button="left", clickCount=1)
        browser.call("Input.dispatchMouseEvent", type="mouseMoved", x=x + 50, y=y, button="left", buttons=1)
        browser.call("Input.dispatchMouseEvent", type="mouseReleased", x=x + 50, y=y, button="left", clickCount=1)
        panned = box()
        check(float(panned.split()[0]) < float(zoomed.split()[0]) and panned.split()[2] == zoomed.split()[2],
              f"panned left: {zoomed} -> {panned}")
        browser.evaluate("document.querySelector('#scene-1 button.fit').click()")
        check(box() == whole, "fit")
    finally:
        browser.call("Emulation.clearDeviceMetricsOverride")
        served.stop()


def test_exports_are_render_and_animate_bytes(folder):
    """The downloads of the frame (SVG, PNG) and of the animation are the bytes pita render --at
    and pita animate write, as attachments, with the token only."""
    save(folder, FIG03)
    served = Served(folder, ["s.json"])
    try:
        for args, what in ((["render", "--at", "0.25", "-o", ".x.png"], "png&at=0.25"),
                           (["render", "--at", "0.25", "-o", ".x.svg"], "svg&at=0.25"),
                           (["render", "-o", ".x.png"], "png"), (["animate", "-o", ".x.svg"], "animation")):
            subprocess.run([PITA, args[0], "s.json", *args[1:]], cwd=folder, check=True,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            out = folder / args[-1]
            status, body = served.get(f"/api/export/0?what={what}")
            check(status == 200 and body == out.read_bytes(), f"{what}: {status}, {len(body)} bytes, "
                  f"not the {out.stat().st_size} of pita {' '.join(args)}")
            out.unlink()
        url = f"{served.base}/api/export/0?what=png&at=0.5&token={served.token}"
        with urllib.request.urlopen(url, timeout=30) as response:
            disposition = response.headers["Content-Disposition"]
        check(disposition == 'attachment; filename="s-at-0.5.png"', disposition)
        check(served.get("/api/export/0?what=png", token="")[0] == 403, "an export without the token")
        check(served.get("/api/animation/0", token="")[0] == 403, "the animation without the token")
        for path in ("/api/export/0?what=../s.json", "/api/export/0", "/api/export/0?what=png&at=x",
                     "/api/export/0?what=animation&at=0.5"):
            check(served.get(path)[0] == 400, path)
        check(served.get("/api/export/1?what=png")[0] == 404, "no scene 1")
    finally:
        served.stop()


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_a_restart_keeps_the_open_tab(folder, browser):
    """--keep-token: a restart in the same folder keeps the token, and the open tab reconnects by
    itself and follows the saves again; --open starts the desktop's browser on the address."""
    save(folder, FIG03)
    env = dict(os.environ, XDG_STATE_HOME=str(folder / ".state"))
    # A stand-in for xdg-open that notes the address it is given.
    bin_dir = folder / ".bin"
    bin_dir.mkdir()
    (bin_dir / "xdg-open").write_text(f'#!/bin/sh\nprintf "%s" "$1" > "{folder}/.opened"\n')
    (bin_dir / "xdg-open").chmod(0o755)
    env["PATH"] = f"{bin_dir}:{env['PATH']}"
    port = free_port()
    served = Served(folder, ["s.json"], "--keep-token", "--open", port=port, env=env)
    token = served.token
    opened = eventually(lambda: (folder / ".opened").exists() and (folder / ".opened").read_text(), 30)
    check(opened == served.url, f"--open opened {opened}")
    browser.open(served.url)
    first = eventually(lambda: figure_text(browser), 60)
    served.stop()
    eventually(lambda: "connection lost" in browser.evaluate("document.getElementById('status').textContent"), 30)
    served = Served(folder, ["s.json"], "--keep-token", port=port, env=env)
    try:
        check(served.token == token, "the kept token")
        eventually(lambda: "connection lost" not in browser.evaluate("document.getElementById('status').textContent"),
                   30, what="the tab reconnected")
        changed = dict(FIG03, keyframes=[dict(k) for k in FIG03["keyframes"]])
        changed["keyframes"][1]["w"] = 2.0
        save(folder, changed)
        eventually(lambda: (figure_text(browser) or first) != first, 60, what="the reconnected tab follows a save")
        modes = (oct((folder / ".state" / "pita" / "serve-tokens").stat().st_mode & 0o777),
                 [oct(f.stat().st_mode & 0o777) for f in (folder / ".state" / "pita" / "serve-tokens").iterdir()])
        check(modes == ("0o700", ["0o600"]), f"the kept token is the user's only: {modes}")
    finally:
        served.stop()
    # A token given on the command line must be one.
    bad = subprocess.run([PITA, "serve", "s.json", "--token", "short"], cwd=folder, capture_output=True, text=True)
    check(bad.returncode == 2 and "16 to 128 characters" in bad.stderr, (bad.returncode, bad.stderr))


def measure_latency(folder, browser, name, latencies, trials=5):
    """Save to updated figure in the page, for scenes/NAME.json (the median of `trials` saves)."""
    scene = json.loads((SOURCE / "scenes" / f"{name}.json").read_text())
    save(folder, scene)
    served = Served(folder, ["s.json"])
    try:
        browser.open(served.url)
        eventually(lambda: figure_text(browser), 60)
        times = []
        for trial in range(trials):
            time.sleep(0.2)
            browser.evaluate("""window.pitaSeen = null; new MutationObserver(() => { if (window.pitaSeen === null)
                window.pitaSeen = Date.now(); }).observe(document.querySelector('#scene-0 .figure'), {childList: true})""")
            start = time.time()
            save(folder, dict(scene, title=f"{scene.get('title', name)} ({trial})"))
            seen = eventually(lambda: browser.evaluate("window.pitaSeen"), 60)
            times.append(seen / 1000 - start)
        latencies.append((name, sorted(times)[len(times) // 2]))
    finally:
        served.stop()


def test_hostile_requests_are_refused(folder):
    save(folder, FIG03)
    served = Served(folder, ["s.json"])
    try:
        check(served.get("/", token="")[0] == 403, "no token")
        check(served.get("/", token="0" * 32)[0] == 403, "a wrong token")
        check(served.get("/api/scenes", token=served.token[:-1])[0] == 403, "a token cut short")
        check(served.get("/")[0] == 200, "the page with the token")
        for path in ["/../s.json", "/s.json", "/api/figure/../../s.json", "/api/figure/1", "/api/figure/-1",
                     "/etc/passwd", "/api/figure/0x0", "/%2e%2e/s.json"]:
            status, _ = served.get(path)
            check(status in (400, 404), f"{path}: {status}")
        check(served.get("/api/scenes", data=b"x" * (1 << 20))[0] in (413, "reset"), "a body of a megabyte")
        check(served.get("/api/figure/0?at=nan")[0] == 400, "a time that is not a number")
        check(served.get("/api/edit/0", data=b'{"changes": []}')[0] == 403, "no editing without --edit")
    finally:
        served.stop()
    # Another host than loopback is warned about.
    served = Served(folder, ["s.json"], "--host", "0.0.0.0")
    try:
        check("warning: listening on 0.0.0.0" in served.stderr(), served.stderr())
    finally:
        served.stop()


def test_a_hundred_saves_leave_the_last_figure_and_no_temporary(folder):
    save(folder, FIG03)
    served = Served(folder, ["s.json"])
    try:
        for i in range(100):
            save(folder, dict(FIG03, keyframes=[FIG03["keyframes"][0], dict(FIG03["keyframes"][1], w=1.0 + i / 100)]))
        last = folder / "last.json"
        last.write_text((folder / "s.json").read_text())
        subprocess.run([PITA, "render", "last.json", "-o", "last.svg"], cwd=folder, check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        expected = (folder / "last.svg").read_bytes()
        eventually(lambda: served.get("/api/figure/0")[1] == expected, 60)
    finally:
        served.stop()
    check(sorted(p.name for p in folder.iterdir() if p.name.startswith(".")) == [], "no temporary left")
    (folder / "last.svg").unlink()


def main():
    latencies = []
    rates = []
    root = pathlib.Path(tempfile.mkdtemp(prefix="pita-serve-test-"))
    browser = Browser()
    try:
        for test in (test_the_page_follows_the_saves, test_dragging_writes_the_scene_file,
                     test_two_figures_keep_their_own_glyphs, test_the_page_links_only_within_itself,
                     test_a_restart_keeps_the_open_tab, test_hostile_requests_are_refused,
                     test_a_hundred_saves_leave_the_last_figure_and_no_temporary, test_scrubbing_and_play,
                     test_orientation, test_exports_are_render_and_animate_bytes):
            folder = root / test.__name__
            folder.mkdir()
            started = time.monotonic()
            if test is test_the_page_follows_the_saves:
                test(folder, browser, latencies)
            elif test is test_scrubbing_and_play:
                test(folder, browser, rates)
            elif test in (test_dragging_writes_the_scene_file, test_two_figures_keep_their_own_glyphs,
                          test_the_page_links_only_within_itself, test_a_restart_keeps_the_open_tab,
                          test_orientation):
                test(folder, browser)
            else:
                test(folder)
            print(f"ok {test.__name__} ({time.monotonic() - started:.1f} s)")
        # Fig. 1, and the scene with the largest figure (fig26-banners: 766 kB of SVG).
        for name in ("fig01-eight-pitas", "fig26-banners"):
            folder = root / f"latency-{name}"
            folder.mkdir()
            measure_latency(folder, browser, name, latencies)
    finally:
        browser.close()
        shutil.rmtree(root, ignore_errors=True)
    for name, seconds in latencies:
        print(f"save to updated figure in the page, {name}: {seconds * 1000:.0f} ms")
    for name, shown, fps in rates:
        print(f"play in the page, {name}: {shown:.1f} frames shown a second (the timeline's fps: {fps:g})")


if __name__ == "__main__":
    main()
