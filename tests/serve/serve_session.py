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


def eventually(check, timeout=60.0, step=0.02):
    """Polls check() until it returns something true (returned), or fails after `timeout` s."""
    end = time.monotonic() + timeout
    while True:
        value = check()
        if value:
            return value
        if time.monotonic() > end:
            raise AssertionError(f"still not true after {timeout} s: {check.__doc__ or check}")
        time.sleep(step)


class Served:
    """`pita serve SCENES... --port 0` in `folder`, with the address it printed."""

    def __init__(self, folder, scenes, *extra):
        self.folder = pathlib.Path(folder)
        self.log = open(self.folder / ".serve-log", "w+")
        self.process = subprocess.Popen([PITA, "serve", *scenes, "--port", "0", *extra], cwd=folder,
                                        stdout=subprocess.DEVNULL, stderr=self.log)
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

    def open(self, url):
        self.call("Page.enable")
        self.call("Page.navigate", url=url)

    def close(self):
        self.socket.close()
        self.process.terminate()
        self.process.wait(30)
        shutil.rmtree(self.profile, ignore_errors=True)
