"""The web app under attack, over a real socket (issue 41, Deliver 3): ``bearingkit serve`` as a user
starts it, on 127.0.0.1, hit with raw HTTP the way a hostile page or client would send it.

What held in the audit and must keep holding: foreign Host headers refused (DNS rebinding), cross-site
("simple") requests refused before anything runs (CSRF), 24 path-traversal forms 404, a 100 MB body
refused at once, deeply nested JSON refused in one line, slow clients not starving others, and a
bounded load test: 200 requests, no 5xx, the server's memory bounded. The workbench's routes (studies
started from the browser) pass the same checks.
"""

from __future__ import annotations

import json
import os
import socket
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import psutil
import pytest

pytest.importorskip("uvicorn")

EXAMPLE = {"kind": "example", "name": "dgbb_6209.toml"}
#: A study the workbench would start (a small one: it must never start here anyway).
STUDY = {
    "subject": "bearing",
    "bearing": {"source": EXAMPLE, "loads": {"F_x": "5 kN"}, "speed": "3000 rpm"},
    "design": "sweep",
    "factors": [{"path": "load_cases.page.F_x", "start": "1 kN", "stop": "2 kN", "n": 2}],
    "outputs": ["L10r_rev"],
}


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    """``bearingkit serve --port P`` in its own process; its temporary folder under a test folder."""
    tmp = tmp_path_factory.mktemp("attack")
    port = _free_port()
    # One solver core throughout: ``auto`` loads the compiled core (~130 MB, once) when the process has
    # spent its numpy budget, and 16 concurrent requests reach that budget (wall time under the GIL) at a
    # moment that depends on the machine's load: the memory bound below would then measure that one-off
    # load (seen in CI: 134 → 296 MB), not growth per request. The backends agree to 1e-12 (tests of the
    # solver); what is tested here is the HTTP layer.
    env = {**os.environ, "TMPDIR": str(tmp), "BEARINGKIT_BACKEND": "numpy"}
    cmd = [sys.executable, "-m", "bearingkit", "serve", "--port", str(port)]
    proc = subprocess.Popen(cmd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 90
    while True:
        try:
            if request(port, "GET", "/api/meta")[0] == 200:
                break
        except OSError:
            pass
        assert proc.poll() is None, f"bearingkit serve ended: {proc.stderr.read()}"
        assert time.monotonic() < deadline, "bearingkit serve did not answer within 90 s"
        time.sleep(0.2)
    yield port, proc, tmp
    proc.terminate()
    try:
        proc.wait(timeout=20)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()


def request(port, method, target, body=b"", headers=None, host="127.0.0.1", timeout=60.0):
    """One raw HTTP/1.1 request (the target is sent as written: no client-side normalisation);
    returns (status, headers, body)."""
    if isinstance(body, (dict, list)):
        body = json.dumps(body).encode()
        headers = {"Content-Type": "application/json", **(headers or {})}
    lines = [f"{method} {target} HTTP/1.1"]
    if host is not None:
        lines.append(f"Host: {host}")
    lines += [f"{k}: {v}" for k, v in (headers or {}).items()]
    lines += [f"Content-Length: {len(body)}", "Connection: close", "", ""]
    with socket.create_connection(("127.0.0.1", port), timeout=timeout) as s:
        s.sendall("\r\n".join(lines).encode("latin-1") + body)
        return _response(s)


def _response(s: socket.socket):
    data = b""
    while True:
        part = s.recv(65536)
        if not part:
            break
        data += part
    head, _, rest = data.partition(b"\r\n\r\n")
    status_line, *header_lines = head.decode("latin-1").split("\r\n")
    fields = {}
    for line in header_lines:
        k, _, v = line.partition(":")
        fields[k.strip().lower()] = v.strip()
    if fields.get("transfer-encoding") == "chunked":
        rest = _unchunk(rest)
    return int(status_line.split()[1]), fields, rest


def _unchunk(data: bytes) -> bytes:
    out = b""
    while data:
        size, _, data = data.partition(b"\r\n")
        n = int(size, 16)
        if n == 0:
            break
        out, data = out + data[:n], data[n + 2 :]
    return out


def one_line_error(body: bytes) -> str:
    data = json.loads(body)
    assert set(data) <= {"error", "field"} and "\n" not in data["error"] and "Traceback" not in data["error"]
    return data["error"]


def _nothing_started(tmp: Path) -> None:
    """No study folder in the server's temporary folder: nothing was written or run."""
    assert not list(tmp.glob("bearingkit-serve-*/studies/*")), "a refused request started a study"


# ------------------------------------------------------------------------------------------ Host
@pytest.mark.parametrize(
    "host",
    ["evil.example", "127.0.0.1.nip.io", "localhost.evil.example", "attacker.localhost", "127.0.0.2",
     "0.0.0.0", "127.0.0.1@evil.example", "[::ffff:127.0.0.1]", ""],
)  # fmt: skip
def test_a_foreign_host_is_refused_on_every_route(server, host):
    port, _, tmp = server
    for method, target, body in (
        ("GET", "/api/meta", b""),
        ("POST", "/api/analyze", {"source": EXAMPLE}),
        ("POST", "/api/study", STUDY),
        ("GET", "/", b""),
    ):
        status, _, _ = request(port, method, target, body, host=host)
        assert status == 400, (host, target, status)
    _nothing_started(tmp)


def test_the_loopback_names_are_answered(server):
    port = server[0]
    for host in ("127.0.0.1", "localhost", f"127.0.0.1:{port}", f"localhost:{port}"):
        assert request(port, "GET", "/api/meta", host=host)[0] == 200, host


# ------------------------------------------------------------------------------------------ CSRF
@pytest.mark.parametrize(
    "content_type",
    ["text/plain", "application/x-www-form-urlencoded", "multipart/form-data; boundary=x", None],
)
@pytest.mark.parametrize("target", ["/api/analyze", "/api/study", "/api/open", "/api/catalogue/compare"])
def test_a_cross_site_simple_request_is_refused_before_anything_runs(server, content_type, target):
    """A form or a no-cors fetch of another site can send these without a preflight; the API reads JSON
    only, so the body (valid JSON text) is refused and nothing runs."""
    port, _, tmp = server
    body = json.dumps(STUDY if target == "/api/study" else {"source": EXAMPLE, "designations": ["6209"]})
    headers = {"Origin": "http://evil.example", "Referer": "http://evil.example/page"}
    if content_type is not None:
        headers["Content-Type"] = content_type
    status, _, answer = request(port, "POST", target, body.encode(), headers=headers)
    assert status == 422, (status, answer)
    assert one_line_error(answer)
    _nothing_started(tmp)


def test_a_cross_site_json_request_gets_no_cors_permission(server):
    """A JSON POST from another origin needs the browser's preflight; the server grants no origin."""
    port = server[0]
    headers = {
        "Origin": "http://evil.example",
        "Access-Control-Request-Method": "POST",
        "Access-Control-Request-Headers": "content-type",
    }
    for target in ("/api/analyze", "/api/study"):
        status, fields, _ = request(port, "OPTIONS", target, headers=headers)
        assert status in (404, 405) and not any(k.startswith("access-control-allow") for k in fields), fields
    _, fields, _ = request(port, "GET", "/api/meta", headers={"Origin": "http://evil.example"})
    assert "access-control-allow-origin" not in fields


# ------------------------------------------------------------------------------------------ traversal
TRAVERSAL = [
    "/static/../../../../etc/passwd",
    "/static/..%2f..%2f..%2f..%2fetc%2fpasswd",
    "/static/%2e%2e/%2e%2e/%2e%2e/etc/passwd",
    "/static/%2e%2e%2f%2e%2e%2fpyproject.toml",
    "/static/%252e%252e/%252e%252e/etc/passwd",
    "/static/..%5c..%5c..%5cetc%5cpasswd",
    "/static/%c0%ae%c0%ae/%c0%ae%c0%ae/etc/passwd",
    "/static/....//....//etc/passwd",
    "/static//etc/passwd",
    "/static/%2fetc%2fpasswd",
    "/static/app.js%00.png",
    "/static/../api.py",
    "/static/..%2fapi.py",
    "/api/download/..%2F..%2Fetc%2Fpasswd",
    "/api/download/%2e%2e%2f%2e%2e%2fetc%2fpasswd",
    "/api/download/..%252F..%252Fetc%252Fpasswd",
    "/api/download/0123456789abcdef.toml%00.html",
    "/api/download/..%5C..%5Cwindows%5Cwin.ini",
    "/api/figure/..%2F..%2Fetc%2Fpasswd/pressure.svg",
    "/api/figure/system/..%2F..%2F/..%2Fetc%2Fpasswd",
    "/api/study/..%2F..%2Fetc%2Fpasswd",
    "/api/study/0123456789abcdef/figure/..%2Fstudy.toml",
    "/api/study/0123456789abcdef/figure/..%2F..%2F..%2Fetc%2Fpasswd",
    "/api/study/..%2F..%2Fetc%2Fpasswd.zip",
]


def test_24_traversal_forms_are_404(server):
    port = server[0]
    assert len(TRAVERSAL) == 24
    for target in TRAVERSAL:
        status, _, body = request(port, "GET", target)
        assert status == 404, (target, status, body[:200])
        assert b"root:" not in body and b"[project]" not in body and b"import " not in body, target


# ------------------------------------------------------------------------------------------ size, nesting
def test_a_100_mb_body_is_refused_at_once(server):
    """Declared 100 MB: 413 before the body is read (the client has sent 64 kB when the answer comes)."""
    port = server[0]
    head = (
        "POST /api/open HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
        f"Content-Length: {100 * 2**20}\r\nConnection: close\r\n\r\n"
    )
    t0 = time.perf_counter()
    with socket.create_connection(("127.0.0.1", port), timeout=30) as s:
        s.sendall(head.encode() + b'{"source": {"kind": "upload", "name": "a.toml", "text": "' + b"x" * 65536)
        status, _, body = _response(s)
    elapsed = time.perf_counter() - t0
    assert status == 413 and one_line_error(body).startswith("request too large")
    assert elapsed < 2.0, f"{elapsed:.2f} s to refuse a 100 MB body"


def test_a_streamed_100_mb_body_is_cut_off_near_the_limit(server):
    """No Content-Length (chunked): counted while it streams; the server stops reading near its limit."""
    from bearingkit.app.api import MAX_REQUEST_BYTES

    port = server[0]
    head = (
        "POST /api/open HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
        "Transfer-Encoding: chunked\r\nConnection: close\r\n\r\n"
    )
    piece = b"x" * 65536
    chunk = f"{len(piece):x}\r\n".encode() + piece + b"\r\n"
    sent, t0 = 0, time.perf_counter()
    with socket.create_connection(("127.0.0.1", port), timeout=30) as s:
        s.sendall(head.encode())
        s.settimeout(0.5)
        try:
            while sent < 100 * 2**20:
                s.sendall(chunk)
                sent += len(piece)
        except (BrokenPipeError, ConnectionResetError, TimeoutError):
            pass  # the server stopped reading: what it refused is no longer being buffered
        s.settimeout(30)
        try:
            status, _, body = _response(s)
        except ConnectionResetError:
            status, body = 413, b'{"error": "request too large (connection reset)"}'
    assert status == 413 and one_line_error(body).startswith("request too large")
    assert sent < MAX_REQUEST_BYTES + 16 * 2**20, f"{sent} bytes accepted"
    assert time.perf_counter() - t0 < 10.0


@pytest.mark.parametrize("deep", ["[" * 100_000 + "]" * 100_000, '{"a":' * 60_000 + "1" + "}" * 60_000])
def test_deeply_nested_json_is_refused_in_one_line(server, deep):
    port, proc, tmp = server
    for target in ("/api/analyze", "/api/study"):
        status, _, body = request(port, "POST", target, deep.encode(), {"Content-Type": "application/json"})
        assert 400 <= status < 500, (target, status, body[:200])
        assert one_line_error(body)
    assert proc.poll() is None
    _nothing_started(tmp)


# ------------------------------------------------------------------------------------------ slow clients
def test_slow_clients_do_not_starve_the_others(server):
    """40 clients that send their headers (or body) a byte at a time hold connections; a normal request
    and an analysis are answered meanwhile."""
    port = server[0]
    slow = []
    try:
        for i in range(40):
            s = socket.create_connection(("127.0.0.1", port), timeout=10)
            if i % 2:  # headers never finished
                s.sendall(b"GET /api/meta HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Slow: a")
            else:  # a body promised and never sent
                s.sendall(
                    b"POST /api/analyze HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
                    b"Content-Length: 400000\r\n\r\n{"
                )
            slow.append(s)
        t0 = time.perf_counter()
        assert request(port, "GET", "/api/meta", timeout=10)[0] == 200
        assert time.perf_counter() - t0 < 2.0
        body = {"source": EXAMPLE, "loads": {"F_x": "4.5 kN"}, "speed": "2000 rpm"}
        t0 = time.perf_counter()
        assert request(port, "POST", "/api/analyze", body, timeout=30)[0] == 200
        assert time.perf_counter() - t0 < 20.0
        for s in slow:  # still trickling: one more byte each, and the server still answers
            s.sendall(b"b")
        assert request(port, "GET", "/api/meta", timeout=10)[0] == 200
    finally:
        for s in slow:
            s.close()


# ------------------------------------------------------------------------------------------ load
def test_200_concurrent_requests_no_5xx_and_bounded_memory(server):
    port, proc, _ = server
    server_process = psutil.Process(proc.pid)
    work = []
    for i in range(200):
        kind = i % 5
        if kind == 0:
            work.append(("GET", "/", b""))
        elif kind == 1:
            work.append(("GET", "/static/app.js", b""))
        elif kind == 2:
            work.append(("GET", "/api/meta", b""))
        elif kind == 3:  # 8 distinct analyses (the rest answered from the server's store)
            work.append(("POST", "/api/analyze", {"source": EXAMPLE, "loads": {"F_x": f"{1 + i % 8} kN"}}))
        else:
            work.append(("POST", "/api/open", {"source": {"kind": "designation", "name": "6209"}}))
    request(port, *work[3])  # one analysis before the baseline (the engine loaded)
    rss0 = server_process.memory_info().rss
    t0 = time.perf_counter()
    with ThreadPoolExecutor(16) as pool:
        statuses = list(pool.map(lambda w: request(port, *w, timeout=120)[0], work))
    elapsed = time.perf_counter() - t0
    rss1 = server_process.memory_info().rss
    assert all(s < 500 for s in statuses), sorted(set(statuses))
    assert statuses.count(200) == 200, sorted(set(statuses))
    assert rss1 - rss0 < 150 * 2**20, f"RSS {rss0 / 2**20:.0f} → {rss1 / 2**20:.0f} MB"
    assert elapsed < 90.0, f"{elapsed:.1f} s for 200 requests"
    assert proc.poll() is None
