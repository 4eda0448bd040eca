"""Benchmark: the web app's response time for one analysis of the 6209 through the real HTTP API.

uvicorn serves :func:`bearingkit.app.create_app` on a free loopback port in a thread; a stdlib HTTP
client (one kept-alive connection, as a browser's) posts the page's state for
``examples/dgbb_6209.toml`` with a different radial load each time, so every request is a new analysis
(load → statics → rating → friction → ``to_dict`` → JSON), not the server's kept copy. Reported from one
run: the median and the 90th percentile of the wall time per request (target: median < 200 ms), and one
50-value radial-load sweep (one batched analysis).

``python -m benchmarks.bench_app`` prints the records; ``make bench`` includes them.
"""

from __future__ import annotations

import http.client
import json
import socket
import statistics
import threading
import time

#: Target of one analysis through the HTTP API [ms] (issue 21: "within a second" on screen, < 200 ms).
TARGET_MS = 200.0


def _post(conn: http.client.HTTPConnection, path: str, body: dict) -> tuple[float, dict]:
    data = json.dumps(body).encode()
    t0 = time.perf_counter()
    conn.request("POST", path, body=data, headers={"Content-Type": "application/json"})
    response = conn.getresponse()
    payload = response.read()
    dt = time.perf_counter() - t0
    if response.status != 200:
        raise RuntimeError(f"{path}: HTTP {response.status}: {payload[:200]!r}")
    return dt, json.loads(payload)


def run(quick: bool) -> list[dict]:
    import uvicorn

    from bearingkit.app import create_app

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    server = uvicorn.Server(uvicorn.Config(create_app(), host="127.0.0.1", port=port, log_level="warning"))
    thread = threading.Thread(target=server.run, daemon=True)
    thread.start()
    while not server.started:
        time.sleep(0.02)
    try:
        conn = http.client.HTTPConnection("127.0.0.1", port, timeout=120)
        source = {"kind": "example", "name": "dgbb_6209.toml"}
        cold, _ = _post(conn, "/api/analyze", {"source": source, "loads": {"F_x": "1 kN"}})
        n = 10 if quick else 40
        times = []
        for i in range(n):  # a new load each time: a new analysis, not the kept one
            body = {
                "source": source,
                "loads": {"F_x": f"{2 + 0.1 * i:.1f} kN"},
                "speed": "3000 rpm",
                "temperature": "70 degC",
                "lubricant": "ISO_VG68",
                "contamination": "0.5",
            }
            dt, out = _post(conn, "/api/analyze", body)
            assert out["analysis"]["cases"][0]["converged"]
            times.append(dt * 1e3)
        sweep_body = {
            "base": {"source": source, "speed": "3000 rpm", "lubricant": "ISO_VG68"},
            "factor": "F_x",
            "start": "1 kN",
            "stop": "20 kN",
            "n": 50,
        }
        sweep_dt, sweep = _post(conn, "/api/sweep", sweep_body)
        conn.close()
    finally:
        server.should_exit = True
        thread.join(10)
    median = statistics.median(times)
    p90 = statistics.quantiles(times, n=10)[-1]
    return [
        {
            "name": "app: one 6209 analysis via HTTP (median)",
            "value": median,
            "unit": "ms",
            "target": f"< {TARGET_MS:g}",
            "note": f"{n} requests, statics + rating + friction + JSON; first (cold) {cold * 1e3:.0f} ms",
        },
        {"name": "app: one 6209 analysis via HTTP (p90)", "value": p90, "unit": "ms", "target": ""},
        {
            "name": "app: 50-value radial-load sweep via HTTP",
            "value": sweep_dt * 1e3,
            "unit": "ms",
            "target": "",
            "note": f"{sweep['analyses']} analysis of 50 load cases",
        },
    ]


if __name__ == "__main__":
    for record in run(quick=False):
        print(record)
