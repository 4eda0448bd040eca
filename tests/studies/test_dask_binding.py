"""A LocalCluster the Dask executor starts serves no dashboard and listens on loopback only (item 8).

``dashboard_address=None`` did not turn Dask's HTTP server off: the scheduler still listened on
127.0.0.1:8787 (health, info, JSON and proxy routes) and every worker on a random port.
"""

import urllib.error
import urllib.request

import psutil
import pytest

from bearingkit.studies.run.executors import DaskExecutor

#: Paths Dask's scheduler and workers serve by default (health, prometheus, info pages, JSON).
PROBES = ("/health", "/metrics", "/info/main/workers.html", "/json/identity.json", "/status")


def _listeners() -> list[tuple[int, str, int]]:
    """(pid, ip, port) of every listening TCP socket of this process and its children."""
    me = psutil.Process()
    out = []
    for proc in [me, *me.children(recursive=True)]:
        for conn in proc.net_connections(kind="tcp"):
            if conn.status == psutil.CONN_LISTEN:
                out.append((proc.pid, conn.laddr.ip, conn.laddr.port))
    return out


def _http_status(port: int, path: str) -> int | None:
    try:
        with urllib.request.urlopen(f"http://127.0.0.1:{port}{path}", timeout=5) as r:
            return r.status
    except urllib.error.HTTPError as exc:
        return exc.code


def _comm_ports(client) -> set[int]:
    info = client.scheduler_info()
    addrs = [info["address"], *info["workers"], *(w.get("nanny") for w in info["workers"].values())]
    return {int(a.rsplit(":", 1)[1]) for a in addrs if a}


@pytest.mark.slow  # starts a LocalCluster of one worker process: ~5-10 s on the shared machine
def test_own_local_cluster_has_no_dashboard_and_binds_loopback():
    before = {port for _, _, port in _listeners()}
    ex = DaskExecutor(workers=1)
    try:
        new = [(pid, ip, port) for pid, ip, port in _listeners() if port not in before]
        assert new, "the cluster listens somewhere"
        assert all(ip == "127.0.0.1" for _, ip, _ in new), new
        assert 8787 not in {port for _, _, port in new}
        http_ports = {port for _, _, port in new} - _comm_ports(ex.client)
        served = {(port, path): _http_status(port, path) for port in http_ports for path in PROBES}
        assert all(code == 404 for code in served.values()), served
    finally:
        ex.close()


@pytest.mark.slow
def test_dashboard_only_when_asked():
    ex = DaskExecutor(workers=1, dashboard="127.0.0.1:0")
    try:
        http_ports = {port for _, _, port in _listeners()} - _comm_ports(ex.client)
        assert any(_http_status(port, "/health") == 200 for port in http_ports)
    finally:
        ex.close()
