"""Benchmark: the web app's response times through the real HTTP API — the bearing page and the workbench.

uvicorn serves :func:`bearingkit.app.create_app` on a free loopback port in a thread; a stdlib HTTP
client (one kept-alive connection, as a browser's) posts the page's state for
``examples/dgbb_6209.toml`` with a different radial load each time, so every request is a new analysis
(load → statics → rating → friction → ``to_dict`` → JSON), not the server's kept copy. Reported from one
run: the median and the 90th percentile of the wall time per request (target: median < 200 ms), and one
50-value radial-load sweep (one batched analysis).

Then the workbench (issue 39), each request once after a warm-up of its route, with new values so
nothing is the server's kept copy: a catalogue search (deep groove, d = 45 mm), a bearing selection
(5 kN / 1 kN, 3000 r/min, 20,000 h), a comparison of two bearings, the countershaft and the two-stage
gearbox examples (``examples/shaft_countershaft.toml``, ``examples/gearbox_two_stage.toml``: every
bearing's analysis, JSON), the duty cycle of ``examples/dgbb_6209_duty_cycle.toml`` (4 bins), and a
50-case study on the 6209 from the start request to its results (a child process: the imports, the
solves, the plots), with the time the start request itself took (the study's checks).

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


def _post(conn: http.client.HTTPConnection, path: str, body: dict | None) -> tuple[float, dict]:
    """(wall time [s], answer) of one request: a POST of ``body`` as JSON, a GET when it is None."""
    t0 = time.perf_counter()
    if body is None:
        conn.request("GET", path)
    else:
        conn.request(
            "POST", path, body=json.dumps(body).encode(), headers={"Content-Type": "application/json"}
        )
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
        bench = _workbench(conn)
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
        *bench,
    ]


def _workbench(conn: http.client.HTTPConnection) -> list[dict]:
    """One timed request per workbench route (module docstring), after one untimed warm-up of each."""
    point = {"speed": "3000 rpm", "temperature": "70 degC", "lubricant": "ISO_VG68", "contamination": "0.5"}
    shaft = {"system": "shaft", "source": {"kind": "example", "name": "shaft_countershaft.toml"}}
    gearbox = {"system": "drivetrain", "source": {"kind": "example", "name": "gearbox_two_stage.toml"}}
    duty = {"kind": "example", "name": "dgbb_6209_duty_cycle.toml"}
    bins = [
        {
            "name": "a",
            "values": {"F_x": "3 kN", "speed": "3000 rpm", "temperature": "70 degC"},
            "fraction": "0.6",
        },
        {
            "name": "b",
            "values": {"F_x": "6 kN", "speed": "2000 rpm", "temperature": "80 degC"},
            "fraction": "0.4",
        },
    ]
    requests = {
        "catalogue search (deep groove, d = 45 mm)": (
            "/api/catalogue/search",
            lambda i: {"kind": "deep_groove", "bounds": {"d": "45 mm", "D_max": f"{100 + i} mm"}},
        ),
        "bearing selection (5 kN, 1 kN, 3000 r/min, 20000 h)": (
            "/api/catalogue/select",
            lambda i: {
                "radial": f"{5 + 0.1 * i:.1f} kN",
                "axial": "1 kN",
                "speed": "3000 rpm",
                "life": "20000 h",
                "kind": "deep_groove",
                "count": 3,
            },
        ),
        "comparison of two bearings (6209, 6309)": (
            "/api/catalogue/compare",
            lambda i: {"designations": ["6209", "6309"], "point": {**point, "loads": {"F_x": f"{5 + i} kN"}}},
        ),
        "shaft example (countershaft, 3 cases, 2 bearings)": (
            "/api/system/analyze",
            lambda i: {**shaft, "contamination": f"{0.5 + 0.1 * i:.1f}"},
        ),
        "drivetrain example (two-stage gearbox, 6 bearings)": (
            "/api/system/analyze",
            lambda i: {**gearbox, "contamination": f"{0.5 + 0.1 * i:.1f}"},
        ),
        "duty cycle (6209, 2 bins)": (
            "/api/duty",
            lambda i: {"base": {"source": duty, "contamination": f"{0.5 + 0.1 * i:.1f}"}, "bins": bins},
        ),
    }
    out = []
    for name, (path, body) in requests.items():
        _post(conn, path, body(0))  # warm-up: the route's imports
        dt, _ = _post(conn, path, body(1))
        out.append({"name": f"app: {name}", "value": dt * 1e3, "unit": "ms", "target": ""})
    study = {
        "subject": "bearing",
        "bearing": {"source": {"kind": "example", "name": "dgbb_6209.toml"}, **point},
        "design": "factorial",
        "factors": [
            {"path": "geometry.clearance_radial", "start": "0 um", "stop": "40 um", "n": 5},
            {"path": "load_cases.page.F_x", "start": "1 kN", "stop": "10 kN", "n": 10},
        ],
        "outputs": ["L10r_h", "max_load_N", "friction_torque_Nm"],
    }
    t0 = time.perf_counter()
    start_dt, job = _post(conn, "/api/study", study)
    while job["state"] in ("running", "queued"):
        time.sleep(0.1)
        _, job = _post(conn, f"/api/study/{job['id']}", None)
    if job["state"] != "done":
        raise RuntimeError(f"study {job['state']}: {job['message']}")
    _post(conn, f"/api/study/{job['id']}/results", None)
    total = time.perf_counter() - t0
    out.append(
        {
            "name": "app: 50-case study, start to results",
            "value": total,
            "unit": "s",
            "target": "",
            "note": f"start request {start_dt * 1e3:.0f} ms (the study's checks); {job['message']}",
        }
    )
    return out


if __name__ == "__main__":
    for record in run(quick=False):
        print(record)
