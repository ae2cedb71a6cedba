"""pita serve against a hostile local client, on real sockets (src/serve/http_front.cpp,
src/serve/http_request.cpp, docs/reference/serve.md "Security"): a flood of header lines, a
chunked body, a body beyond the limit and a long request line are refused before they are read
whole, and the server's memory stays flat; slow half-requests and dozens of event streams do
not lock the page's own requests out; a Host that is not the address served is refused (DNS
rebinding); a second server on a busy port is refused; SIGTERM stops the server within a second
while clients hold it busy. Run by ctest
serve.limits (tests/CMakeLists.txt)."""
import json
import os
import pathlib
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from serve_session import Served  # noqa: E402

SOURCE = pathlib.Path(os.environ.get("PITA_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


def check(condition, message):
    if not condition:
        raise AssertionError(message)


class Client:
    """Raw HTTP on a socket to the served address."""

    def __init__(self, served):
        self.served = served
        host_port = served.base.removeprefix("http://")
        self.host, port = host_port.rsplit(":", 1)
        self.port = int(port)
        self.host_header = host_port

    def connect(self):
        return socket.create_connection((self.host, self.port), timeout=30)

    def request(self, path, host=None, extra=b"", token=True):
        sep = "&" if "?" in path else "?"
        target = f"{path}{sep}token={self.served.token}" if token else path
        return (f"GET {target} HTTP/1.1\r\nHost: {host or self.host_header}\r\n".encode() + extra + b"\r\n")

    def exchange(self, data):
        """(status, body) of the answer to the bytes `data`."""
        with self.connect() as s:
            s.sendall(data)
            return read_answer(s)

    def timed_get(self, path):
        """(status, seconds) of a GET with the token."""
        start = time.monotonic()
        status, _ = self.exchange(self.request(path))
        return status, time.monotonic() - start


def read_answer(s):
    """(status, body) of an answer that ends with the connection."""
    data = b""
    while True:
        try:
            part = s.recv(65536)
        except ConnectionResetError:
            break
        if not part:
            break
        data += part
    head, _, body = data.partition(b"\r\n\r\n")
    return int(head.split(b" ", 2)[1]), body


def rss_kib(pid):
    for line in pathlib.Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1])
    raise AssertionError("no VmRSS")


def send_until_closed(s, chunk, limit):
    """Sends `chunk` until the server stops reading or `limit` bytes went; the bytes sent."""
    sent = 0
    s.settimeout(5)
    try:
        while sent < limit:
            s.sendall(chunk)
            sent += len(chunk)
    except (BrokenPipeError, ConnectionResetError, socket.timeout):
        pass
    return sent


def test_floods_are_refused_before_they_are_read(served, client):
    before = rss_kib(served.process.pid)
    # 150 MB of header lines: refused at 64 KiB (431), long before the flood ends.
    with client.connect() as s:
        s.sendall(client.request("/")[:-2])
        sent = send_until_closed(s, b"X-Flood: " + b"x" * 1000 + b"\r\n", 150 << 20)
        check(sent < 150 << 20, "the server read 150 MB of header lines")
    status, body = client.exchange(client.request("/", extra=b"X-A: b\r\n" * 101))
    check(status == 431 and b"more than 100 header lines" in body, (status, body))
    # A chunked body of 96 MB: refused from its head (413).
    with client.connect() as s:
        s.sendall(f"POST /api/edit/0?token={served.token} HTTP/1.1\r\nHost: {client.host_header}\r\n"
                  "Transfer-Encoding: chunked\r\n\r\n".encode())
        status, body = read_answer(s)
        check(status == 413 and b"Content-Length" in body, (status, body))
    # A body declared larger than 64 KiB: refused before it is sent.
    status, body = client.exchange(f"POST /api/edit/0 HTTP/1.1\r\nHost: {client.host_header}\r\n"
                                   "Content-Length: 100000000\r\n\r\n".encode())
    check(status == 413 and b"100000000" in body, (status, body))
    # A request line of 9 KiB.
    status, body = client.exchange(client.request("/" + "a" * 9000))
    check(status == 414, (status, body))
    grown = rss_kib(served.process.pid) - before
    check(grown < 30 * 1024, f"the server grew by {grown} KiB")
    print(f"  floods refused; the server grew by {grown} KiB")


def test_the_host_must_be_the_address_served(served, client):
    for host in ("evil.example", f"evil.example:{client.port}", "localhost.evil.example"):
        status, body = client.exchange(client.request("/", host=host))
        check(status == 403 and b"DNS rebinding" in body, (host, status, body))
    for host in (client.host_header, f"localhost:{client.port}"):
        check(client.exchange(client.request("/", host=host))[0] == 200, host)


def test_a_busy_port_is_refused(served, client):
    """A second pita serve on the port of the first is exit 3, naming the port (no sharing)."""
    second = subprocess.run([os.environ.get("PITA_BINARY", "build/pita"), "serve", "s.json", "--port",
                             str(client.port)], cwd=served.folder, capture_output=True, text=True, timeout=60)
    check(second.returncode == 3 and f":{client.port}" in second.stderr, (second.returncode, second.stderr))
    check(client.exchange(client.request("/"))[0] == 200, "the first server still answers")


def slow_half_request(client, answers, stop):
    """Sends a request's head a byte every 0.3 s; records the server's answer."""
    try:
        with client.connect() as s:
            s.sendall(b"GET / HTTP/1.1\r\n")
            s.settimeout(0.3)
            while not stop.is_set():
                try:
                    data = s.recv(65536)
                    rest = b""
                    s.settimeout(5)
                    while True:
                        part = s.recv(65536)
                        if not part:
                            break
                        rest += part
                    answers.append(data + rest)
                    return
                except socket.timeout:
                    s.sendall(b"X")
    except OSError as error:
        answers.append(str(error).encode())


def test_slow_clients_and_streams_do_not_lock_the_page_out(served, client):
    answers, stop = [], threading.Event()
    slow = [threading.Thread(target=slow_half_request, args=(client, answers, stop)) for _ in range(40)]
    for thread in slow:
        thread.start()
    streams = []
    for _ in range(40):
        s = client.connect()
        s.sendall(client.request("/api/events"))
        streams.append(s)
    time.sleep(1)
    # The page's own requests get through, at once.
    for path in ("/", "/api/scenes", "/api/figure/0"):
        status, seconds = client.timed_get(path)
        check(status == 200 and seconds < 2, f"{path}: {status} after {seconds:.1f} s")
    # 24 streams were ended (the oldest the server took up: on a loaded machine its workers may
    # take them in another order than they connected), and 16 stay open.
    received = {s: b"" for s in streams}
    ended = set()

    def read_streams(seconds):
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            for s in streams:
                if s in ended:
                    continue
                s.settimeout(0.01)
                try:
                    part = s.recv(65536)
                except socket.timeout:
                    continue
                received[s] += part
                if not part or received[s].endswith(b"0\r\n\r\n"):
                    ended.add(s)
                    check(received[s].endswith(b"0\r\n\r\n"), f"a stream closed without its end: {received[s][-40:]}")
            if len(ended) >= 24:
                return

    read_streams(20)
    check(len(ended) == 24, f"{len(ended)} streams were ended, not 24")
    read_streams(1.5)
    check(len(ended) == 24, f"{len(ended)} streams were ended: the newest 16 stay open")
    for s in streams:
        s.close()
    # Every half-request is answered 408: the oldest at once (when newer requests, the page's and
    # the streams' included, took their places), the others within 10 s.
    for thread in slow:
        thread.join(20)
    stop.set()
    check(len(answers) == 40, f"{len(answers)} of 40 half-requests answered")
    too_many = sum(b"408" in a and b"the oldest was closed" in a for a in answers)
    too_slow = sum(b"408" in a and b"within 10 s" in a for a in answers)
    check(too_many + too_slow == 40 and too_many >= 24 and too_slow >= 1, (too_many, too_slow, answers[:3]))


def test_sigterm_stops_it_within_a_second(folder):
    served = Served(folder, ["s.json"])
    client = Client(served)
    held = []
    for _ in range(8):
        s = client.connect()
        s.sendall(b"GET / HTTP/1.1\r\nHost: x")
        held.append(s)
    for _ in range(4):
        s = client.connect()
        s.sendall(client.request("/api/events"))
        held.append(s)
    time.sleep(0.5)
    start = time.monotonic()
    served.process.send_signal(signal.SIGTERM)
    code = served.process.wait(10)
    seconds = time.monotonic() - start
    for s in held:
        s.close()
    served.log.close()
    check(code == 128 + signal.SIGTERM and seconds < 1.5, f"exit {code} after {seconds:.2f} s")
    print(f"  SIGTERM with 12 clients holding the server: stopped in {seconds * 1000:.0f} ms")
    # While it renders: 300 copies of the largest figure take seconds to draw before it serves.
    banners = (SOURCE / "scenes" / "fig26-banners.json").read_text()
    names = []
    for i in range(300):
        (folder / f"b{i}.json").write_text(banners)
        names.append(f"b{i}.json")
    log = open(folder / ".busy-log", "w+")
    process = subprocess.Popen([os.environ.get("PITA_BINARY", "build/pita"), "serve", *names, "--port", "0"],
                               cwd=folder, stdout=subprocess.DEVNULL, stderr=log)
    time.sleep(0.3)
    start = time.monotonic()
    process.send_signal(signal.SIGTERM)
    code = process.wait(10)
    seconds = time.monotonic() - start
    log.close()
    said = (folder / ".busy-log").read_text()
    check(code == 128 + signal.SIGTERM and seconds < 1.5, f"exit {code} after {seconds:.2f} s: {said}")
    check("serving" not in said and "interrupted (SIGTERM)" in said, said)
    print(f"  SIGTERM while rendering 300 figures: stopped in {seconds * 1000:.0f} ms")


def main():
    root = pathlib.Path(tempfile.mkdtemp(prefix="pita-serve-limits-"))
    try:
        scene = json.loads((SOURCE / "scenes" / "fig03-steady-morph.json").read_text())
        (root / "s.json").write_text(json.dumps(scene))
        served = Served(root, ["s.json"])
        try:
            client = Client(served)
            for test in (test_floods_are_refused_before_they_are_read, test_the_host_must_be_the_address_served,
                         test_a_busy_port_is_refused, test_slow_clients_and_streams_do_not_lock_the_page_out):
                started = time.monotonic()
                test(served, client)
                print(f"ok {test.__name__} ({time.monotonic() - started:.1f} s)")
        finally:
            served.stop()
        started = time.monotonic()
        test_sigterm_stops_it_within_a_second(root)
        print(f"ok test_sigterm_stops_it_within_a_second ({time.monotonic() - started:.1f} s)")
    finally:
        shutil.rmtree(root, ignore_errors=True)


if __name__ == "__main__":
    main()
