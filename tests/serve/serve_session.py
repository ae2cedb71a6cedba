"""A `pita serve` and a headless Chromium driven over the DevTools protocol, for the tests
of tests/serve/test_serve.py (Debian chromium and python3-websocket, test packages only)."""
import json
import os
import pathlib
import re
import shutil
import subprocess
import tempfile
import time
import urllib.request

import websocket

PITA = os.environ.get("PITA_BINARY", "build/pita")


def eventually(check, timeout=60.0, step=0.02, what=None):
    """Polls check() until it returns something true (returned), or fails after `timeout` s,
    saying `what` was awaited (a string, or a function that describes the state then)."""
    end = time.monotonic() + timeout
    while True:
        value = check()
        if value:
            return value
        if time.monotonic() > end:
            said = what() if callable(what) else what
            raise AssertionError(f"still not true after {timeout} s: {said or check.__doc__ or check}")
        time.sleep(step)


class Served:
    """`pita serve SCENES... --port PORT` (0: any free one) in `folder`, with the address it printed."""

    def __init__(self, folder, scenes, *extra, port=0, env=None):
        self.folder = pathlib.Path(folder)
        self.log = open(self.folder / ".serve-log", "w+")
        self.process = subprocess.Popen([PITA, "serve", *scenes, "--port", str(port), *extra], cwd=folder,
                                        stdout=subprocess.DEVNULL, stderr=self.log, env=env)
        self.url = eventually(self._address, 60)
        self.base, self.token = self.url.split("/?token=")

    def _address(self):
        """pita serve printed its address"""
        if self.process.poll() is not None:
            raise AssertionError(f"pita serve exited {self.process.returncode}: {self.stderr()}")
        found = re.search(r"(http://\S+/\?token=[0-9a-f]+)", self.stderr())
        return found and found.group(1)

    def stderr(self):
        self.log.flush()
        return (self.folder / ".serve-log").read_text()

    def get(self, path, token=None, data=None):
        """(status, body) of a request to the server."""
        sep = "&" if "?" in path else "?"
        url = f"{self.base}{path}{sep}token={self.token if token is None else token}"
        try:
            with urllib.request.urlopen(urllib.request.Request(url, data=data), timeout=30) as response:
                return response.status, response.read()
        except urllib.error.HTTPError as error:
            return error.code, error.read()
        except urllib.error.URLError as error:
            # The server may answer a body it refuses (413) and close before the client has sent it all.
            if isinstance(error.reason, ConnectionResetError) or "reset" in str(error.reason).lower():
                return "reset", b""
            raise

    def stop(self):
        self.process.terminate()
        code = self.process.wait(30)
        self.log.close()
        (self.folder / ".serve-log").unlink()
        return code


class Browser:
    """Headless Chromium with one page, driven over the DevTools protocol."""

    def __init__(self):
        self.profile = tempfile.mkdtemp(prefix="pita-chromium-")
        chromium = shutil.which("chromium") or "/usr/bin/chromium"
        self.process = subprocess.Popen(
            [chromium, "--headless=new", "--no-sandbox", "--disable-gpu", "--no-first-run",
             "--remote-debugging-port=0", f"--user-data-dir={self.profile}", "about:blank"],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        active = pathlib.Path(self.profile) / "DevToolsActivePort"
        port = eventually(lambda: active.exists() and active.read_text().split("\n")[0], 60)
        targets = eventually(lambda: self._targets(port), 30)
        page = next(t for t in targets if t["type"] == "page")
        self.socket = websocket.create_connection(page["webSocketDebuggerUrl"], timeout=60)
        self.next_id = 0

    @staticmethod
    def _targets(port):
        try:
            with urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list", timeout=5) as response:
                return json.loads(response.read())
        except OSError:
            return None

    def call(self, method, **params):
        self.next_id += 1
        self.socket.send(json.dumps({"id": self.next_id, "method": method, "params": params}))
        while True:
            message = json.loads(self.socket.recv())
            if message.get("id") == self.next_id:
                if "error" in message:
                    raise AssertionError(f"{method}: {message['error']}")
                return message["result"]

    def evaluate(self, expression):
        """The value of a JavaScript expression in the page (awaited when a promise)."""
        result = self.call("Runtime.evaluate", expression=expression, returnByValue=True, awaitPromise=True)
        if "exceptionDetails" in result:
            raise AssertionError(f"{expression}: {result['exceptionDetails']}")
        return result["result"].get("value")

    def drag(self, selector, dx, dy, onto=None):
        """Drags the element `selector` by (dx, dy) CSS pixels (or onto the element `onto`) with the mouse."""
        box = self.evaluate(f"(() => {{ const r = document.querySelector({json.dumps(selector)}).getBoundingClientRect();"
                            " return [r.x + r.width / 2, r.y + r.height / 2]; })()")
        if onto is not None:
            target = self.evaluate(f"(() => {{ const r = document.querySelector({json.dumps(onto)}).getBoundingClientRect();"
                                   " return [r.x + r.width / 2, r.y + r.height / 2]; })()")
            dx, dy = target[0] - box[0], target[1] - box[1]
        x, y = box
        self.call("Input.dispatchMouseEvent", type="mouseMoved", x=x, y=y)
        self.call("Input.dispatchMouseEvent", type="mousePressed", x=x, y=y, button="left", clickCount=1)
        for step in range(1, 6):
            self.call("Input.dispatchMouseEvent", type="mouseMoved", x=x + dx * step / 5, y=y + dy * step / 5,
                      button="left", buttons=1)
        self.call("Input.dispatchMouseEvent", type="mouseReleased", x=x + dx, y=y + dy, button="left", clickCount=1)

    def open(self, url):
        self.call("Page.enable")
        self.call("Page.navigate", url=url)

    def close(self):
        self.socket.close()
        self.process.terminate()
        self.process.wait(30)
        shutil.rmtree(self.profile, ignore_errors=True)


def key(browser, name, code, keycode, text=None):
    """A key pressed and released, as the keyboard sends it."""
    extra = {"text": text} if text else {}
    browser.call("Input.dispatchKeyEvent", type="keyDown", key=name, code=code, windowsVirtualKeyCode=keycode, **extra)
    browser.call("Input.dispatchKeyEvent", type="keyUp", key=name, code=code, windowsVirtualKeyCode=keycode)


def figures_asked_since(browser, since):
    """The figures and frames the page asked the server for since `since` (its performance.now()).
    Requests are told apart by when they started: the list is in that order, and a request still
    on its way when counted would join it before later ones."""
    return browser.evaluate(f"performance.getEntriesByType('resource').filter(e => e.startTime >= {since})"
                            ".map(e => e.name).filter(n => n.includes('/api/figure/'))")


def play(browser, i, seconds):
    """Scene i's figure focused, Space pressed, `seconds` of play, Space again: (the frames shown a
    second, the timeline's fps, the page's time when play began, for figures_asked_since)."""
    browser.evaluate(f"document.querySelector('#scene-{i}').scrollIntoView(); "
                     f"document.querySelector('#scene-{i} .figure').focus()")
    since = browser.evaluate("performance.now()")
    key(browser, " ", "Space", 32, " ")
    eventually(lambda: browser.evaluate(f"views.get({i}).shown") == "animation", 10)
    before = browser.evaluate(f"views.get({i}).changes")
    time.sleep(seconds)
    after = browser.evaluate(f"views.get({i}).changes")
    key(browser, " ", "Space", 32, " ")
    return (after - before) / seconds, browser.evaluate(f"views.get({i}).timeline.fps"), since
